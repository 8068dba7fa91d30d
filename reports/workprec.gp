# Work-precision: RMS load error against CPU seconds, one line per ppc, one point per h;
# for the inclined scenes also the paper's method and the cohesive interface at 1 ppc where
# the scene file uses another
W = 1500; Hgt = 560
load gpdir.'/common.gp'
scs = "fig6 fig7 fig8"
set multiplot layout 1,3 title "Work-precision: each line one method and number of particles per cell, points h = 8, 4, 2 (, 1) from the left; runs that stopped early left out"
set logscale xy
set xlabel "CPU time of the run, s"
set ylabel "RMS load error / P_{max}"
set key below
set bmargin 8
do for [i=1:3] {
  sc = word(scs, i)
  set title sprintf("%s.ini", sc)
  pf = sprintf('data/sweep-%s-paper.dat', sc)
  fi = sprintf('data/sweep-%s-iface.dat', sc)
  if (exists_file(pf) && exists_file(fi)) {
    plot for [p in "1 4 9"] sprintf('data/sweep-%s-ppc%s.dat', sc, p) u 4:($5 > 0.5 ? $2 : 1/0) w lp pt 7 ps 1.3 lw 2 \
         title sprintf("scene file's method, %s ppc", p), \
         pf u 4:($5 > 0.5 ? $2 : 1/0) w lp pt 5 ps 1.3 lw 2 dt 2 lc rgb '#333333' title "paper's method, 1 ppc", \
         fi u 4:($5 > 0.5 ? $2 : 1/0) w lp pt 9 ps 1.5 lw 2 dt 4 lc rgb '#8b0000' title "interface, 1 ppc"
  } else {
  if (exists_file(pf)) {
    plot for [p in "1 4 9"] sprintf('data/sweep-%s-ppc%s.dat', sc, p) u 4:($5 > 0.5 ? $2 : 1/0) w lp pt 7 ps 1.3 lw 2 \
         title sprintf("scene file's method, %s ppc", p), \
         pf u 4:($5 > 0.5 ? $2 : 1/0) w lp pt 5 ps 1.3 lw 2 dt 2 lc rgb '#333333' title "paper's method, 1 ppc"
  } else {
    plot for [p in "1 4 9"] sprintf('data/sweep-%s-ppc%s.dat', sc, p) u 4:($5 > 0.5 ? $2 : 1/0) w lp pt 7 ps 1.3 lw 2 \
         title sprintf("%s ppc", p)
  }
  }
}
unset multiplot
