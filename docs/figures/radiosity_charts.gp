# The charts of docs/radiosity.md, from the CSVs beside this file: gnuplot radiosity_charts.gp
set datafile separator ","
set terminal pngcairo size 640,400 noenhanced
set output "radiosity_unshot.png"
set logscale y
set xlabel "shots"
set ylabel "unshot energy / emitted energy"
set title "Cornell box: progressive refinement (rays, 16 per pair)"
set grid
plot "radiosity_unshot_120.csv" every ::1 using 1:2 with lines lw 2 title "patch_size 120 (674 patches)", \
     "radiosity_unshot_60.csv" every ::1 using 1:2 with lines lw 2 title "patch_size 60 (2508 patches)"
set output "radiosity_time.png"
set logscale xy
set xlabel "patches"
set ylabel "solve time (s)"
set title "Cornell box: radiosity solve time to 1% unshot energy (2 threads)"
plot "radiosity_time.csv" every ::1 using 2:3 with linespoints lw 2 pt 7 title "measured", \
     "radiosity_time.csv" every ::1 using 2:(3.8*($2/674)**2) with lines dt 2 title "proportional to patches^2"
