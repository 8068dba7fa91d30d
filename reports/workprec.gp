# Work-precision: RMS load error against CPU seconds, one line per ppc, one point per h
W = 1500; Hgt = 520
load gpdir.'/common.gp'
scs = "fig6 fig7 fig8"
set multiplot layout 1,3 title "Work-precision: each line one number of particles per cell, points h = 8, 4, 2 (, 1) from the left; runs that stopped early left out"
set logscale xy
set xlabel "CPU time of the run, s"
set ylabel "RMS load error / P_{max}"
set key top right
do for [i=1:3] {
  set title word(scs, i)
  plot for [p in "1 4 9"] sprintf('data/sweep-%s-ppc%s.dat', word(scs, i), p) u 4:($5 > 0.5 ? $2 : 1/0) w lp pt 7 ps 1.3 lw 2 \
       title sprintf("%s ppc", p)
}
unset multiplot
