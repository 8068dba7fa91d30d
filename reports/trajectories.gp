# Shared: displacement trajectories at one end displacement d: arrows from (x0, y0)
# along the displacement times s, coloured by lambda.  Set id, d, s, ttl, endd.
set size ratio -1
set cbrange [0:1]
set cblabel "{/Symbol l}"
set xlabel "x"
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
plot f u (keep($1, $2) ? $1 : 1/0):2:(s*$5):(s*$6):7 w vectors head size 0.8,20 filled lc palette lw 1
} else {
  set label 1 sprintf("no picture: the run ended at {/Symbol d} = %.3g", endd) at graph 0.5,0.5 center
  plot 1/0
}
