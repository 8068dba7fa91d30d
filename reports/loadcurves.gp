# Shared: plot load-deflection curves of the cases in `ids` (labels in `labs`) over the
# analytic curve of scene `sc`; xmax sets the range.
set xlabel "end displacement {/Symbol d}"
set ylabel "load P"
set xrange [0:xmax]
set yrange [*:*]
if (!exists("keypos")) keypos = "top right"
set key @keypos
n = words(ids)
plot sprintf('data/ana-%s.csv', sc) u 1:2 w l lw 4 lc rgb '#999999' title 'analytic', \
     for [i=1:n] load_csv(word(ids, i)) u 2:3 w l lw 1.8 title word(labs, i)
