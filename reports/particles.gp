# Shared: particle pictures coloured by lambda (with decohesion.path = interface, the
# line's segments drawn over them in their lambda).  Set before loading: id (case), ds
# (list of end displacements), rows, cols, hw (half the particle spacing), endd (where
# the run ended), ttl, and optionally x0, x1, y0, y1 (the window).
set multiplot layout rows,cols title ttl
set size ratio -1
if (exists("cbmax")) { set cbrange [0:cbmax] } else { set cbrange [0:1] }
set cblabel "{/Symbol l}"
set xlabel "x (x and y in dimensionless units, the paper's)"
set ylabel "y"
unset key
unset grid
if (!exists("x0")) { x0 = -8; x1 = 196; y0 = -4; y1 = 36 }
set xrange [x0:x1]
set yrange [y0:y1]
do for [i=1:words(ds)] {
  d = real(word(ds, i))
  f = snap(id, d)
  set title sprintf("{/Symbol d} = %.2f", d)
  fl = snapl(id, d)
  if (exists_file(f) && exists_file(fl)) {
    # the interface: particles never soften; the line (reference position) in black
    # under its segments' lambda
    plot f u 3:4:(1.04*hw):(1.04*hw):7 w boxxy fs solid 1.0 noborder lc palette, \
         fl u 1:2:($3-$1):($4-$2) w vectors nohead lw 9 lc rgb 'black', \
         fl u 1:2:($3-$1):($4-$2):5 w vectors nohead lw 5 lc palette
  } else {
    if (exists_file(f)) {
      plot f u 3:4:(1.04*hw):(1.04*hw):7 w boxxy fs solid 1.0 noborder lc palette
    } else {
      set label 1 sprintf("no picture: the run ended at {/Symbol d} = %.3g", endd) at graph 0.5,0.5 center
      plot 1/0
      unset label 1
    }
  }
}
unset multiplot
