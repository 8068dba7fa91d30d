# Fig. 3: sigma* against the dimensionless average strain E e / r0 (analytic, eq. 34),
# with the kernel's quasi-static runs of the same nine bars as points (report_qs.c)
W = 1400; Hgt = 600
load gpdir.'/common.gp'
qs = "0.8 1 1.2"
gs = "0.75 1.25 2"
set multiplot layout 1,3 title sprintf("Fig. 3: {/Symbol s}* = {/Symbol s}/r_0 against E e_{ave}/r_0; lines: closed form (eq. 34), points: the kernel (iface90.ini, static solver, h = %g, %d ppc)", f3k_h, f3k_ppc)
set xrange [0:2.2]
set yrange [0:1.45]
set ytics 0, 0.2, 1
set xlabel "average strain  E e_{ave} / r_0"
set ylabel "{/Symbol s}* = {/Symbol s} / r_0"
# the key above the curves (sigma* <= 1), one column: the lines by g, then one entry for
# the kernel's points (drawn in their g's colour); a point set only where it has a note
set key top left vertical maxrows 4 font ',10' samplen 1.5 spacing 1.1 width -2
do for [i=1:3] {
  set title sprintf("q = %s", word(qs, i))
  plot for [j=1:3] sprintf('data/fig3-q%s-g%s.csv', word(qs, i), word(gs, j)) u 1:2 w l lw 2.5 lc j \
       title sprintf("g = %s%s", word(gs, j), value(sprintf("f3_snap_%d_%d", i-1, j-1)) ? " (snapback)" : ""), \
       for [j=1:3] sprintf('data/fig3-kernel-q%s-g%s.csv', word(qs, i), word(gs, j)) u 1:2 w p pt 6 ps 0.7 lc j \
       title (!value(sprintf("f3k_have_%d_%d", i-1, j-1)) ? sprintf("g = %s: no kernel run", word(gs, j)) \
              : strlen(value(sprintf("f3k_note_%d_%d", i-1, j-1))) > 0 ? sprintf("g = %s kernel%s", word(gs, j), value(sprintf("f3k_note_%d_%d", i-1, j-1))) : ""), \
       1/0 w p pt 6 ps 1 lc rgb 'black' title "kernel (points)"
}
unset multiplot
