# Charts of the height-field study; regenerate with: bench/heightfield_study.sh
set datafile separator ','
set grid
set logscale xy
set key top left
set xlabel 'samples (N x N)'
set format x '%.0s%c'
set terminal pngcairo size 800,500
f = 'docs/figures/heightfield.csv'
set output 'docs/figures/heightfield_build.png'
set ylabel 'build time (s, one thread)'
set title 'Height field: build time'
plot f skip 1 using (strcol(2) eq 'dda' ? $1*$1 : NaN):3 with linespoints pt 7 title 'dda (traversal)', \
     f skip 1 using (strcol(2) eq 'mesh' ? $1*$1 : NaN):3 with linespoints pt 5 title 'mesh (Embree triangles)'
set output 'docs/figures/heightfield_memory.png'
set ylabel 'MiB'
set title 'Height field: memory (peak RSS; representation = own + Embree bytes)'
plot f skip 1 using (strcol(2) eq 'dda' ? $1*$1 : NaN):($6/1048576) with linespoints pt 7 title 'dda peak RSS', \
     f skip 1 using (strcol(2) eq 'mesh' ? $1*$1 : NaN):($6/1048576) with linespoints pt 5 title 'mesh peak RSS', \
     f skip 1 using (strcol(2) eq 'dda' ? $1*$1 : NaN):(($4+$5)/1048576) with linespoints pt 6 dt 2 title 'dda representation', \
     f skip 1 using (strcol(2) eq 'mesh' ? $1*$1 : NaN):(($4+$5)/1048576) with linespoints pt 4 dt 2 title 'mesh representation'
set output 'docs/figures/heightfield_speed.png'
unset logscale y
set ylabel 'Mrays/s (512x512 coherent camera rays, one thread)'
set title 'Height field: tracing speed'
plot f skip 1 using (strcol(2) eq 'dda' ? $1*$1 : NaN):8 with linespoints pt 7 title 'dda (traversal)', \
     f skip 1 using (strcol(2) eq 'mesh' ? $1*$1 : NaN):8 with linespoints pt 5 title 'mesh (Embree triangles)'
