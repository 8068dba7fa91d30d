# Shared: displacement trajectories at one end displacement d: arrows from (x0, y0)
# along the displacement times s, coloured by lambda (with the interface, the crack line's
# pieces at their lambda, thick).  Set id, d, s, ttl, endd.
set size ratio -1
set cbrange [0:1]
set cblabel "{/Symbol l}"
set xlabel "x (x and y in dimensionless units, the paper's)"
set ylabel "y"
unset key
unset grid
set xrange [-6:198]
set yrange [-4:36]
set title ttl
f = snap(id, d)
if (exists_file(f)) {
  # every second particle in x and y, so that the arrows do not overlap
keep(x, y) = (int(floor(x / (2*hw))) % 2 == 0 && int(floor(y / (2*hw))) % 2 == 0)
fl = snapl(id, d)
if (exists_file(fl)) {
  # the interface: the particles keep lambda 0 and the crack line carries it, drawn thick
  plot f u (keep($1, $2) ? $1 : 1/0):2:(s*$5):(s*$6):7 w vectors head size 0.8,20 filled lc palette lw 1, \
       fl u 1:2:($3-$1):($4-$2):5 w vectors nohead lw 5 lc palette
} else {
  plot f u (keep($1, $2) ? $1 : 1/0):2:(s*$5):(s*$6):7 w vectors head size 0.8,20 filled lc palette lw 1
}
} else {
  set label 1 sprintf("no picture: the run ended at {/Symbol d} = %.3g", endd) at graph 0.5,0.5 center
  plot 1/0
}
