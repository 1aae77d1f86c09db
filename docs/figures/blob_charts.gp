# Blobs analytic against marching-tetrahedra meshes (docs/csg-and-blobs.md); regenerate with:
#   build/blob_study 512 > docs/figures/blob_study.csv && gnuplot docs/figures/blob_charts.gp
# Analytic (cells = 0) has no error: drawn at 1e-3 px.
set datafile separator ','
set key off
set grid
set terminal pngcairo size 1200,500
set output 'docs/figures/blob_study.png'
set multiplot layout 1,2 title 'Blob (5 elements): analytic (cells 0) against meshes of N cells across, 512² orthographic rays'
set logscale xy
set xlabel 'max depth error over rays both hit (pixels; analytic at 1e-3)'
set ylabel 'memory: Embree + own geometry (bytes)'
plot 'docs/figures/blob_study.csv' skip 1 using (($10 > 1e-3) ? $10 : 1e-3):($5 + $6):(sprintf('%d', $1)) with labels point pt 7 ps 1 offset char 1,0.6
unset logscale y
set ylabel 'Mrays/s (one thread, rays one by one)'
plot 'docs/figures/blob_study.csv' skip 1 using (($10 > 1e-3) ? $10 : 1e-3):7:(sprintf('%d', $1)) with labels point pt 7 ps 1 offset char 1,0.6
unset multiplot
