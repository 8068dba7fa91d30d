# Shared: plot load-deflection curves of the cases in `ids` (labels in `labs`) over the
# analytic curve of scene `sc`; xmax sets the range.
set xlabel "end displacement {/Symbol d} (dimensionless units, the paper's)"
set ylabel "load P (dimensionless units, the paper's)"
set xrange [0:xmax]
set yrange [*:*]
if (!exists("keypos")) keypos = "top right"
set key @keypos
n = words(ids)
# each curve its own saturated colour, each later one thinner, so that one lying on
# another still shows the one beneath as a coloured rim (Fig. 6(c): 4 and 9 ppc nearly
# coincide); the analytic curve last, thin and black, so that it hides none of them
lcols = "#1f4e9e #d62728 #2a9d3a #8e44ad #e07000 #555555 #17becf #bcbd22 #e377c2 #8c564b"
lwid(i) = n > 1 ? 4.0 - 2.5 * (i - 1) / (n - 1) : 2
# qs_id, if set: a run of the quasi-static solver, its rows (equilibrium states) as dots
# joined by a thin black line on top, labelled qs_lab; cleared after the plot
if (!exists("qs_id")) qs_id = ''
qs_plot = (strlen(qs_id) > 0) ? sprintf(", load_csv('%s') u 2:3 w lp lw 1.2 pt 7 ps 0.45 lc rgb 'black' title '%s'", qs_id, qs_lab) : ''
# zoom_x0, zoom_x1, if set (outside a multiplot): an inset over that range of delta
if (!exists("zoom_x0")) zoom_x0 = -1
if (zoom_x0 >= 0) { set multiplot }
pcmd = "plot for [i=1:n] load_csv(word(ids, i)) u 2:3 w l lw lwid(i) lc rgb word(lcols, (i - 1) % words(lcols) + 1) title word(labs, i), ".\
       "sprintf('data/ana-%s.csv', sc) u 1:2 w l lw 1.2 dt 2 lc rgb 'black' title 'analytic'".qs_plot
eval pcmd
if (zoom_x0 >= 0) {
  set origin 0.55, 0.3; set size 0.42, 0.5
  set xrange [zoom_x0:zoom_x1]; set yrange [zoom_y0:zoom_y1]
  unset xlabel; unset ylabel; unset key
  set title "zoom" offset 0,-0.8 font ',10'
  set object 1 rect from graph 0, graph 0 to graph 1, graph 1 behind fc rgb 'white' fs solid 1.0
  eval pcmd
  unset multiplot
  unset object 1
  zoom_x0 = -1
}
qs_id = ''
