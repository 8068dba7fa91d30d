# Fig. 3: sigma* against the dimensionless average strain E e / r0 (analytic, eq. 34)
W = 1400; Hgt = 560
load gpdir.'/common.gp'
qs = "0.8 1 1.2"
gs = "0.75 1.25 2"
set multiplot layout 1,3 title "Fig. 3: analytic bar, {/Symbol s}* = {/Symbol s}/r_0 against E e_{ave}/r_0 (eq. 34)"
set xrange [0:2.2]
set yrange [0:1.05]
set xlabel "average strain  E e_{ave} / r_0"
set ylabel "{/Symbol s}* = {/Symbol s} / r_0"
set key below horizontal
do for [i=1:3] {
  set title sprintf("q = %s", word(qs, i))
  plot for [j=1:3] sprintf('data/fig3-q%s-g%s.csv', word(qs, i), word(gs, j)) u 1:2 w l lw 2.5 \
       title sprintf("g = %s%s", word(gs, j), value(sprintf("f3_snap_%d_%d", i-1, j-1)) ? " (snapback)" : "")
}
unset multiplot
