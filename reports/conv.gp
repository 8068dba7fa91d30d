# Convergence: curve error and dissipation error against h (1 ppc), fitted orders
W = 1300; Hgt = 620
load gpdir.'/common.gp'
scs = "fig6 fig7 fig8"
set multiplot layout 1,2 title "Convergence under refinement (1 particle per cell; lines: least-squares fit err = C h^p; open circles: runs that stopped early, not fitted)"
set logscale xy
set xrange [0.8:10]
set xtics (1, 2, 4, 8)
set xlabel "grid spacing h"
# below the plots: inside, the key would hide points of some scene
set key below horizontal
set bmargin 7
set format y "10^{%T}"
set ylabel "RMS load error / P_{max}"
set title "load-deflection curve"
plot for [i=1:3] sprintf('data/sweep-%s-ppc1.dat', word(scs, i)) u 1:($5 > 0.5 ? $2 : 1/0) w p pt 7 ps 1.5 lc i \
       title sprintf("%s (p = %.2f)", word(scs, i), value('p_curve_'.word(scs, i))), \
     for [i=1:3] sprintf('data/sweep-%s-ppc1.dat', word(scs, i)) u 1:($5 > 0.5 ? 1/0 : $2) w p pt 6 ps 1.5 lc i notitle, \
     for [i=1:3] exp(value('c_curve_'.word(scs, i))) * x**value('p_curve_'.word(scs, i)) w l dt 2 lc i notitle
set ylabel "|D / D_{analytic} - 1|"
set title "dissipated energy at the end of the run"
set yrange [3e-7:*]
set key below horizontal maxcols 2
set bmargin 9
# an error below 1e-12 is rounding (the interface's D is U0 area by construction): it has
# no place on a log axis and no order, so it is drawn at a floor and left out of the fit
rnd = 1e-12; flr = 1e-6
plot for [i=1:3] sprintf('data/sweep-%s-ppc1.dat', word(scs, i)) u 1:($5 > 0.5 && $3 >= rnd ? $3 : 1/0) w p pt 7 ps 1.5 lc i \
       title (value('exact_diss_'.word(scs, i)) ? sprintf("%s (exact)", word(scs, i)) \
              : sprintf("%s (p = %.2f)", word(scs, i), value('p_diss_'.word(scs, i)))), \
     for [i=1:3] sprintf('data/sweep-%s-ppc1.dat', word(scs, i)) u ($1 * (0.94 + 0.04 * i)):($3 < rnd ? flr : 1/0) w p pt 11 ps 1.8 lc i notitle, \
     1/0 w p pt 11 ps 1.8 lc rgb "black" title "exact to rounding (drawn at 10^{-6})", \
     for [i=1:3] sprintf('data/sweep-%s-ppc1.dat', word(scs, i)) u 1:($5 > 0.5 || $3 < rnd ? 1/0 : $3) w p pt 6 ps 1.5 lc i notitle, \
     for [i=1:3] (value('exact_diss_'.word(scs, i)) ? 1/0 : exp(value('c_diss_'.word(scs, i))) * x**value('p_diss_'.word(scs, i))) w l dt 2 lc i notitle
unset multiplot
