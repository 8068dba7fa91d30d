# Work-precision: RMS load error against CPU seconds, one line per ppc, one point per h;
# for the inclined scenes also one line per other method at 1 ppc: the paper's method, and
# the cohesive interface or the band method, whichever the scene file does not run.
# fig8 snaps back: its load error covers the rising branch only, where every method
# agrees, so its panel compares the dissipation error |D / (U0 area) - 1| of every run,
# the quasi-static solver's included; an error below 1e-12 is rounding (the interface's
# D is U0 area by construction) and is drawn on a floor line, as in conv.gp.
W = 1500; Hgt = 560
load gpdir.'/common.gp'
scs = "fig6 fig7 fig8"
set multiplot layout 1,3 title "Work-precision: each line one solver, method and number of particles per cell, points h = 8, 4, 2 (, 1) from the left; runs that stopped early left out"
set logscale xy
set format y "10^{%T}"
set xlabel "CPU time of the run, s"
set key below
set bmargin 10
rnd = 1e-12; flr = 1e-6
do for [i=1:3] {
  sc = word(scs, i)
  ycol = sc eq "fig8" ? 3 : 2
  yv(v) = (sc eq "fig8" && v < rnd) ? flr : v
  pt_line = sprintf(" u 4:($5 > 0.5 ? yv($%d) : 1/0) w lp", ycol)
  set title sprintf("%s.ini%s", sc, ycol == 3 ? " (snapback): dissipation error\n(floor line: exact to rounding, below 10^{-12})" : ": load error")
  set ylabel (ycol == 3 ? "|D / (U_0 area) - 1|" : "RMS load error / P_{max}")
  if (sc eq "fig8") { set yrange [3e-7:30]; set arrow 1 from graph 0, first flr to graph 1, first flr nohead dt 3 lc rgb '#888888' } else { set yrange [*:*]; unset arrow 1 }
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
  # the static table: h, curve_path, curve_err, abs_diss_err, cpu_s, complete, ...
  scol = sc eq "fig8" ? 4 : 3
  if (exists_file(fs)) { cmd = cmd.sprintf(", fs u 5:($6 > 0.5 ? yv($%d) : 1/0) w lp pt 13 ps 1.6 lw 2.5 lc rgb '#e07000' title \"quasi-static solver, 4 ppc\"", scol) }
  eval cmd
}
unset multiplot
