# Fig. 6(c): fig6 load against deflection for 1, 4, 9 ppc on h = 8
load gpdir.'/common.gp'
ids = ''; labs = ''
do for [p in "1 4 9"] {
  id = value('sw_fig6_h8_ppc'.p)
  if (strlen(id) > 0) { ids = ids.' '.id; labs = labs.' "'.p.' per cell'.value('sw_fig6_h8_ppc'.p.'_note').'"' }
}
set title "Fig. 6(c): fig6.ini ({/Symbol a} = 90), USL, h = 8"
sc = 'fig6'; xmax = 0.6
# the softening branch, where the curves part, enlarged
zoom_x0 = 0.17; zoom_x1 = 0.31; zoom_y0 = 12; zoom_y1 = 33; keypos = 'top left'
load gpdir.'/loadcurves.gp'
