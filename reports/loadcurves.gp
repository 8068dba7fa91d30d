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
plot sprintf('data/ana-%s.csv', sc) u 1:2 w l lw 5 lc rgb '#bbbbbb' title 'analytic', \
     for [i=1:n] load_csv(word(ids, i)) u 2:3 w l lw (n > 1 ? 3.2 - 2.0 * (i - 1) / (n - 1) : 2) dt i title word(labs, i)
