# Energies against the end displacement for each paper scene's own run (its scene
# file as written), from energy.csv (columns by name): external work, strain and
# kinetic energy, cohesive work, dissipation, and every loss the ledger books (the
# held nodes' L_bc, the FLIP projection's L_flip, the scheme's L_scheme, the loading
# head's W_head, contact, debris and the damper's L_damp); L_flip and L_scheme, the two
# halves of one exchange between the FLIP update and the scheme's strain (equal and
# opposite, +-63 on fig8), as their sum; the dashed line is the
# dissipation expected at the end, U0 x failure area (= 2 UF x area, Model 1, q = 1).
W = 1800; Hgt = 660
load gpdir.'/common.gp'
set multiplot layout 1,3 title "Energies against {/Symbol d}, each paper scene from its scene file"
set xlabel "end displacement {/Symbol d} (dimensionless units, the paper's)"
set ylabel "energy (dimensionless units, the paper's)"
set key below horizontal maxrows 4 font ",10"
set bmargin 11
set tmargin 5
scs = "fig6 fig7 fig8"
do for [i=1:3] {
  sc = word(scs, i)
  id = value('pic_'.sc)
  spd = value('pic_'.sc.'_speed')
  dsep = value('pic_'.sc.'_Dsep')
  f = sprintf('data/%s/energy.csv', id)
  set title sprintf("%s.ini\n%s", sc, value('pic_'.sc.'_method')) font ",10"
  if (strlen(id) > 0 && exists_file(f)) {
    plot f u (column("t")*spd):(column("W_ext")) w l lw 2.5 lc rgb '#000000' title 'W_{ext}', \
         '' u (column("t")*spd):(column("SE")) w l lw 2 lc rgb '#1f77b4' title 'SE (strain)', \
         '' u (column("t")*spd):(column("KE")) w l lw 2 lc rgb '#17becf' title 'KE (kinetic)', \
         '' u (column("t")*spd):(column("D")) w l lw 3 lc rgb '#d62728' title 'D (dissipated)', \
         '' u (column("t")*spd):(column("W_coh")) w l lw 2 lc rgb '#ff9896' dt 2 title 'W_{coh}', \
         '' u (column("t")*spd):(column("L_damp")) w l lw 2 lc rgb '#2ca02c' title 'L_{damp}', \
         '' u (column("t")*spd):(column("L_flip") + column("L_scheme")) w l lw 1.5 lc rgb '#9467bd' title 'L_{flip} + L_{scheme}', \
         '' u (column("t")*spd):(column("L_bc")) w l lw 1.5 lc rgb '#e377c2' title 'L_{bc}', \
         '' u (column("t")*spd):(column("W_head")) w l lw 1.5 lc rgb '#7f7f7f' title 'W_{head}', \
         '' u (column("t")*spd):(column("L_contact")) w l lw 1.5 lc rgb '#bcbd22' dt 3 title 'L_{contact}', \
         '' u (column("t")*spd):(column("L_debris")) w l lw 1.5 lc rgb '#ff7f0e' dt 3 title 'L_{debris}', \
         dsep w l lw 1 lc rgb '#d62728' dt 4 title 'U_0 area = 2 U_F area'
  } else {
    set label 1 "no run" at graph 0.5,0.5 center
    plot 1/0 notitle
    unset label 1
  }
}
unset multiplot
