# Fig. 8(c): load against deflection, Mode II at 60 deg
load gpdir.'/common.gp'
ids = pic_fig8; labs = '"h = 2 (scene file)"'
do for [h in "8 4 1"] {
  id = value('sw_fig8_h'.h.'_ppc1')
  if (strlen(id) > 0) { ids = ids.' '.id; labs = labs.' "h = '.h.'"' }
}
set title sprintf("Fig. 8(c): Mode II, {/Symbol a} = 60 (analytic g = %.3g: snapback)", g_fig8)
sc = 'fig8'; xmax = 2.1
load gpdir.'/loadcurves.gp'
