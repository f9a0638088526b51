set terminal pngcairo size 900,900
set output 'velocityStep.png'
set multiplot layout 3,1 title 'frictionLawDriver: prescribed'
set xlabel 'time [s]'
set grid
set ylabel 'mu = tT/tN [-]'
plot 'velocityStep.dat' u 1:6 w l lw 2 notitle
set ylabel '|slip rate| [m/s]'
set logscale y
plot 'velocityStep.dat' u 1:(abs($3) > 0 ? abs($3) : 1/0) w l lw 2 notitle
unset logscale y
set ylabel 'contact age (state)'
plot 'velocityStep.dat' u 1:7 w l lw 2 notitle
unset multiplot
