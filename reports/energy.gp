# Energies against the end displacement for each paper scene's own run (its scene
# file as written): external work, strain energy, kinetic energy, cohesive work (the
# work of the decohesion tractions) and dissipation, from energy.csv (columns by name).
W = 1500; Hgt = 560
load gpdir.'/common.gp'
set multiplot layout 1,3 title "Energies against {/Symbol d}, each paper scene from its scene file"
set xlabel "end displacement {/Symbol d}"
set ylabel "energy"
set key below horizontal
set bmargin 9
scs = "fig6 fig7 fig8"
do for [i=1:3] {
  sc = word(scs, i)
  id = value('pic_'.sc)
  spd = value('pic_'.sc.'_speed')
  f = sprintf('data/%s/energy.csv', id)
  set title sprintf("%s.ini (%s)\n%s", sc, id, value('pic_'.sc.'_method')) font ",10"
  if (strlen(id) > 0 && exists_file(f)) {
    plot f u (column("t")*spd):(column("W_ext")) w l lw 2.5 title 'W_{ext}', \
         '' u (column("t")*spd):(column("SE")) w l lw 2 title 'SE (strain)', \
         '' u (column("t")*spd):(column("KE")) w l lw 2 title 'KE (kinetic)', \
         '' u (column("t")*spd):(column("W_coh")) w l lw 2 dt 2 title 'W_{coh}', \
         '' u (column("t")*spd):(column("D")) w l lw 2 title 'D (dissipated)'
  } else {
    set label 1 "no run" at graph 0.5,0.5 center
    plot 1/0 notitle
    unset label 1
  }
}
unset multiplot
