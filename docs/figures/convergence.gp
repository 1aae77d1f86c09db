# The convergence chart; regenerate with: gnuplot docs/figures/convergence.gp
set datafile separator ','
set title 'cornell_box.json (built in) 128x128: RMS error against a 4096-spp path reference' noenhanced
set logscale xy
set grid
set key bottom left
set xlabel 'seconds (render + radiosity solve, 2 threads)'
set ylabel 'RMS error / mean luminance of the reference'
set terminal pngcairo size 700,500
set output 'docs/figures/convergence.png'
plot 'docs/figures/convergence.csv' skip 1 using (strcol(1) eq 'path' ? $3 : NaN):4 with linespoints pt 7 title 'path (1-1024 spp)', \
     '' skip 1 using (strcol(1) eq 'radiosity' ? $3 : NaN):4 with linespoints pt 5 title 'whitted + radiosity (patch size)', \
     '' skip 1 using (strcol(1) eq 'radiosity' ? $3 : NaN):4:2 with labels offset 0,1 notitle, \
     0.100559565 * sqrt(0.646933355 / x) dashtype 2 lc rgb 'gray' title 'slope -1/2'
set terminal svg size 700,500
set output 'docs/figures/convergence.svg'
replot
unset output
