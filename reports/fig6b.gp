# Fig. 6(b): fig6 load against deflection for h = 8, 4, 2, 1 (1 ppc)
load gpdir.'/common.gp'
ids = ''; labs = ''
do for [h in "8 4 2 1"] {
  id = value('sw_fig6_h'.h.'_ppc1')
  if (strlen(id) > 0) { ids = ids.' '.id; labs = labs.' "h = '.h.value('sw_fig6_h'.h.'_ppc1_note').'"' }
}
set title "Fig. 6(b): fig6.ini ({/Symbol a} = 90), USL, 1 particle per cell"
sc = 'fig6'; xmax = 0.6
load gpdir.'/loadcurves.gp'
