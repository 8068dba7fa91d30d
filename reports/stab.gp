# Stability: time-step sweep on fig6, h = 8, 1 ppc, to delta 0.5
W = 1400; Hgt = 580
load gpdir.'/common.gp'
set multiplot layout 1,2 title sprintf("Time-step sweep: fig6, h = 8, 1 ppc (dt_{crit} = h/c = %.4f)", dt_crit8)
set logscale y
set xlabel "dt / dt_{crit}"
set ylabel "RMS load error / P_{max}"
set xrange [0:1.2]
set yrange [*:2]
set arrow 1 from 1, graph 0 to 1, graph 1 nohead dt 2 lc rgb '#888888'
set arrow 2 from 0.1/dt_crit8, graph 0 to 0.1/dt_crit8, graph 1 nohead dt 3 lc rgb '#4444aa'
set label 2 sprintf("the paper's dt = 0.1\n= %.2f dt_{crit}", 0.1/dt_crit8) at 0.1/dt_crit8, graph 0.7 right offset -0.5,0 font ',10' tc rgb '#4444aa'
set arrow 3 from 1/sqrt(2), graph 0 to 1/sqrt(2), graph 1 nohead dt 2 lc rgb '#cc6666'
set label 3 "h/(c{/Symbol \326}2)" at 1/sqrt(2), graph 0.5 right offset -0.5,0 font ',10' tc rgb '#cc6666'
set label 4 "h/c" at 1, graph 0.5 right offset -0.5,0 font ',10' tc rgb '#888888'
set key top left
set title "outcome of each run (blown up: drawn at the top)"
plot 'data/stab.dat' u 1:($3 == 0 ? $4 : 1/0) w p pt 7 ps 2 lc rgb '#2a9d2a' title 'stable', \
     '' u 1:($3 == 1 ? $4 : 1/0) w p pt 9 ps 2.2 lc rgb '#e08a00' title 'noisy', \
     '' u 1:($3 == 2 ? 1.5 : 1/0) w p pt 2 ps 2.5 lw 3 lc rgb '#cc0000' title 'blown up'
unset arrow; unset label
unset logscale y
set yrange [*:*]
set title "load curves of the runs that were not blown up (label: dt / dt_{crit})"
ids = stab_ids
labs = stab_labs
sc = 'fig6'; xmax = 0.5
load gpdir.'/loadcurves.gp'
unset multiplot
