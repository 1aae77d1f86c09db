# Charts of rayo's shape-method study; regenerate with: rayo bench accuracy --only shapes -o docs/figures
set key outside right
set grid
set logscale xy
set xlabel 'measured error (px; largest surface separation, 1e-3 = none)'
set terminal pngcairo size 1000,640
set output 'docs/figures/shape_methods_time.png'
set title 'Shape methods: time against error (lines: meshes at 4 .. 1/16 px budgets; flat: analytic)'
set ylabel 'ns per camera ray (8x8 streams, one thread)'
plot for [i=0:13] 'docs/figures/shape_methods.dat' index i using 1:2 with linespoints lc (i/2+1) title columnheader(1)
set terminal svg size 1000,640
set output 'docs/figures/shape_methods_time.svg'
set title 'Shape methods: time against error (lines: meshes at 4 .. 1/16 px budgets; flat: analytic)'
set ylabel 'ns per camera ray (8x8 streams, one thread)'
plot for [i=0:13] 'docs/figures/shape_methods.dat' index i using 1:2 with linespoints lc (i/2+1) title columnheader(1)
set terminal pngcairo size 1000,640
set output 'docs/figures/shape_methods_memory.png'
set title 'Shape methods: memory against error (lines: meshes at 4 .. 1/16 px budgets; flat: analytic)'
set ylabel 'Embree bytes'
plot for [i=0:13] 'docs/figures/shape_methods.dat' index i using 1:3 with linespoints lc (i/2+1) title columnheader(1)
set terminal svg size 1000,640
set output 'docs/figures/shape_methods_memory.svg'
set title 'Shape methods: memory against error (lines: meshes at 4 .. 1/16 px budgets; flat: analytic)'
set ylabel 'Embree bytes'
plot for [i=0:13] 'docs/figures/shape_methods.dat' index i using 1:3 with linespoints lc (i/2+1) title columnheader(1)
