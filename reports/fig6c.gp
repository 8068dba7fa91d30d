# Fig. 6(c): fig6 load against deflection for 1, 4, 9 ppc on h = 8
load gpdir.'/common.gp'
ids = ''; labs = ''
do for [p in "1 4 9"] {
  id = value('sw_fig6_h8_ppc'.p)
  if (strlen(id) > 0) { ids = ids.' '.id; labs = labs.' "'.p.' per cell'.value('sw_fig6_h8_ppc'.p.'_note').'"' }
}
set title "Fig. 6(c): fig6.ini ({/Symbol a} = 90), USL, h = 8"
sc = 'fig6'; xmax = 0.6
load gpdir.'/loadcurves.gp'
