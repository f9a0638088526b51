set terminal pngcairo size 900,900
set output 'holdSlide.png'
set multiplot layout 3,1 title 'frictionLawDriver: prescribed'
set xlabel 'time [s]'
set grid
set ylabel 'mu = tT/tN [-]'
plot 'holdSlide.dat' u 1:6 w l lw 2 notitle
set ylabel '|slip rate| [m/s]'
set logscale y
plot 'holdSlide.dat' u 1:(abs($3) > 0 ? abs($3) : 1/0) w l lw 2 notitle
unset logscale y
set ylabel 'contact age (state)'
plot 'holdSlide.dat' u 1:7 w l lw 2 notitle
unset multiplot
