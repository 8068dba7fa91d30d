# Fig. 6(b): fig6 load against deflection for h = 8, 4, 2, 1 (1 ppc)
load gpdir.'/common.gp'
ids = ''; labs = ''
do for [h in "8 4 2 1"] {
  id = value('sw_fig6_h'.h.'_ppc1')
  if (strlen(id) > 0) { ids = ids.' '.id; labs = labs.' "h = '.h.value('sw_fig6_h'.h.'_ppc1_note').'"' }
}
set title "Fig. 6(b): fig6.ini ({/Symbol a} = 90), USL, 1 particle per cell"
sc = 'fig6'; xmax = 0.6
# the softening branch, where the curves part, enlarged
zoom_x0 = 0.17; zoom_x1 = 0.31; zoom_y0 = 12; zoom_y1 = 33; keypos = 'top left'
load gpdir.'/loadcurves.gp'
