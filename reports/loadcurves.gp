# Shared: plot load-deflection curves of the cases in `ids` (labels in `labs`) over the
# analytic curve of scene `sc`; xmax sets the range.
set xlabel "end displacement {/Symbol d}"
set ylabel "load P"
set xrange [0:xmax]
set yrange [*:*]
if (!exists("keypos")) keypos = "top right"
set key @keypos
n = words(ids)
# each later curve thinner and dashed differently, so that one lying on another still
# shows the one beneath (Fig. 6(c): 4 and 9 ppc nearly coincide)
# qs_id, if set: a run of the quasi-static solver, its rows (equilibrium states) as dots
# joined by a thin black line on top, labelled qs_lab; cleared after the plot
if (!exists("qs_id")) qs_id = ''
qs_plot = (strlen(qs_id) > 0) ? sprintf(", load_csv('%s') u 2:3 w lp lw 1.2 pt 7 ps 0.45 lc rgb 'black' title '%s'", qs_id, qs_lab) : ''
plot sprintf('data/ana-%s.csv', sc) u 1:2 w l lw 5 lc rgb '#bbbbbb' title 'analytic', \
     for [i=1:n] load_csv(word(ids, i)) u 2:3 w l lw (n > 1 ? 3.2 - 2.0 * (i - 1) / (n - 1) : 2) dt i title word(labs, i) @qs_plot
qs_id = ''
