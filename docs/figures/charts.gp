# Charts of rayo's sphere-method study; regenerate with: rayo bench accuracy -o docs/figures
set datafile separator ','
set key off
set grid
set logscale xy
set xlabel 'time per frame (s, BVH build + render, all cores)'
set ylabel 'RMSE against bruteforce/double'
set terminal pngcairo size 900,600
set output 'docs/figures/accuracy_flake.png'
set title 'Sphere methods, scene "flake": time against error (circled: auto; 0 drawn at 1e-7)'
plot 'docs/figures/accuracy.csv' skip 1 using (strcol(1) eq 'flake' ? $5 : NaN):(($7 > 1e-7) ? $7 : 1e-7):(strcol(2).(strcol(3) eq '-' ? '' : '/'.strcol(3))) with labels point pt 7 ps 1 offset char 1,0.6 font ',8', \
     '' skip 1 using (strcol(1) eq 'flake' && $4 == 1 ? $5 : NaN):(($7 > 1e-7) ? $7 : 1e-7) with points pt 6 ps 3 lw 2
set terminal svg size 900,600
set output 'docs/figures/accuracy_flake.svg'
set title 'Sphere methods, scene "flake": time against error (circled: auto; 0 drawn at 1e-7)'
plot 'docs/figures/accuracy.csv' skip 1 using (strcol(1) eq 'flake' ? $5 : NaN):(($7 > 1e-7) ? $7 : 1e-7):(strcol(2).(strcol(3) eq '-' ? '' : '/'.strcol(3))) with labels point pt 7 ps 1 offset char 1,0.6 font ',8', \
     '' skip 1 using (strcol(1) eq 'flake' && $4 == 1 ? $5 : NaN):(($7 > 1e-7) ? $7 : 1e-7) with points pt 6 ps 3 lw 2
set terminal pngcairo size 900,600
set output 'docs/figures/accuracy_far.png'
set title 'Sphere methods, scene "far": time against error (circled: auto; 0 drawn at 1e-7)'
plot 'docs/figures/accuracy.csv' skip 1 using (strcol(1) eq 'far' ? $5 : NaN):(($7 > 1e-7) ? $7 : 1e-7):(strcol(2).(strcol(3) eq '-' ? '' : '/'.strcol(3))) with labels point pt 7 ps 1 offset char 1,0.6 font ',8', \
     '' skip 1 using (strcol(1) eq 'far' && $4 == 1 ? $5 : NaN):(($7 > 1e-7) ? $7 : 1e-7) with points pt 6 ps 3 lw 2
set terminal svg size 900,600
set output 'docs/figures/accuracy_far.svg'
set title 'Sphere methods, scene "far": time against error (circled: auto; 0 drawn at 1e-7)'
plot 'docs/figures/accuracy.csv' skip 1 using (strcol(1) eq 'far' ? $5 : NaN):(($7 > 1e-7) ? $7 : 1e-7):(strcol(2).(strcol(3) eq '-' ? '' : '/'.strcol(3))) with labels point pt 7 ps 1 offset char 1,0.6 font ',8', \
     '' skip 1 using (strcol(1) eq 'far' && $4 == 1 ? $5 : NaN):(($7 > 1e-7) ? $7 : 1e-7) with points pt 6 ps 3 lw 2
set terminal pngcairo size 900,600
set output 'docs/figures/accuracy_close.png'
set title 'Sphere methods, scene "close": time against error (circled: auto; 0 drawn at 1e-7)'
plot 'docs/figures/accuracy.csv' skip 1 using (strcol(1) eq 'close' ? $5 : NaN):(($7 > 1e-7) ? $7 : 1e-7):(strcol(2).(strcol(3) eq '-' ? '' : '/'.strcol(3))) with labels point pt 7 ps 1 offset char 1,0.6 font ',8', \
     '' skip 1 using (strcol(1) eq 'close' && $4 == 1 ? $5 : NaN):(($7 > 1e-7) ? $7 : 1e-7) with points pt 6 ps 3 lw 2
set terminal svg size 900,600
set output 'docs/figures/accuracy_close.svg'
set title 'Sphere methods, scene "close": time against error (circled: auto; 0 drawn at 1e-7)'
plot 'docs/figures/accuracy.csv' skip 1 using (strcol(1) eq 'close' ? $5 : NaN):(($7 > 1e-7) ? $7 : 1e-7):(strcol(2).(strcol(3) eq '-' ? '' : '/'.strcol(3))) with labels point pt 7 ps 1 offset char 1,0.6 font ',8', \
     '' skip 1 using (strcol(1) eq 'close' && $4 == 1 ? $5 : NaN):(($7 > 1e-7) ? $7 : 1e-7) with points pt 6 ps 3 lw 2
set terminal pngcairo size 900,600
set output 'docs/figures/stability.png'
set datafile separator whitespace
set key outside right
set title 'Wrong hit/miss rate against distance/radius (disk rays; 0 drawn at 0.01%)'
set xlabel 'distance / radius'
set ylabel 'wrong hit/miss (%)'
plot for [i=0:8] 'docs/figures/stability_chart.dat' index i using 1:2 with linespoints title columnheader(1)
set datafile separator ','
set key off
set terminal svg size 900,600
set output 'docs/figures/stability.svg'
set datafile separator whitespace
set key outside right
set title 'Wrong hit/miss rate against distance/radius (disk rays; 0 drawn at 0.01%)'
set xlabel 'distance / radius'
set ylabel 'wrong hit/miss (%)'
plot for [i=0:8] 'docs/figures/stability_chart.dat' index i using 1:2 with linespoints title columnheader(1)
set datafile separator ','
set key off
