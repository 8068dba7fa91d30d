# Work-precision: RMS load error against CPU seconds, one line per ppc, one point per h;
# for the inclined scenes also one line per other method at 1 ppc: the paper's method, and
# the cohesive interface or the band method, whichever the scene file does not run.
# fig8 snaps back: its load error covers the rising branch only, where every method
# agrees, so its panel compares the explicit runs' dissipation error |D / (U0 area) - 1|
# instead.  The quasi-static solver (4 ppc, one line a panel) has the explicit lines'
# load error on fig6 and fig7, and on fig8, whose snapback it traces, its distance from
# the analytic path (its D is exact to the solver's tolerance, nothing to compare).
W = 1500; Hgt = 560
load gpdir.'/common.gp'
scs = "fig6 fig7 fig8"
set multiplot layout 1,3 title "Work-precision: each line one solver, method and number of particles per cell, points h = 8, 4, 2 (, 1) from the left; runs that stopped early left out"
set logscale xy
set xlabel "CPU time of the run, s"
set key below
set bmargin 10
do for [i=1:3] {
  sc = word(scs, i)
  ycol = sc eq "fig8" ? 3 : 2
  pt_line = sprintf(" u 4:($5 > 0.5 ? $%d : 1/0) w lp", ycol)
  set title sprintf("%s.ini%s", sc, ycol == 3 ? " (snapback): explicit lines dissipation error,\nstatic line distance from the analytic path" : ": load error")
  set ylabel (ycol == 3 ? "explicit: |D / (U_0 area) - 1|" : "RMS load error / P_{max}")
  pf = sprintf('data/sweep-%s-paper.dat', sc)
  fi = sprintf('data/sweep-%s-iface.dat', sc)
  fb = sprintf('data/sweep-%s-band.dat', sc)
  own = exists_file(pf) ? "explicit, scene file's method, " : "explicit, "
  cmd = "plot for [p in \"1 4 9\"] sprintf('data/sweep-%s-ppc%s.dat', sc, p)".pt_line. \
        " pt 7 ps 1.3 lw 2 title sprintf(\"".own."%s ppc\", p)"
  if (exists_file(pf)) { cmd = cmd.", pf".pt_line." pt 5 ps 1.3 lw 2 dt 2 lc rgb '#333333' title \"explicit, paper's method, 1 ppc\"" }
  if (exists_file(fi)) { cmd = cmd.", fi".pt_line." pt 9 ps 1.5 lw 2 dt 4 lc rgb '#8b0000' title \"explicit, interface, 1 ppc\"" }
  if (exists_file(fb)) { cmd = cmd.", fb".pt_line." pt 11 ps 1.5 lw 2 dt 4 lc rgb '#006400' title \"explicit, band method, 1 ppc\"" }
  fs = sprintf('data/sweep-%s-static.dat', sc)
  scol = sc eq "fig8" ? 2 : 3
  stit = sc eq "fig8" ? "static solver, 4 ppc (path distance, right)" : "quasi-static solver, 4 ppc"
  # fig8: the static line on its own axis (right), a distance along the path, not a D error
  sax = sc eq "fig8" ? "x1y2" : "x1y1"
  unset y2tics; unset y2label; unset logscale y2
  if (sc eq "fig8") { set y2tics (0.001, 0.002, 0.003, 0.004, 0.006); set logscale y2; set y2range [0.0015:0.006]; set format y2 "%.3f"; set y2label "static: distance from the analytic path / P_{max}" }
  if (exists_file(fs)) { cmd = cmd.sprintf(", fs u 5:($6 > 0.5 ? $%d : 1/0) axes %s w lp pt 13 ps 1.6 lw 2.5 lc rgb '#e07000' title \"%s\"", scol, sax, stit) }
  eval cmd
}
unset multiplot
