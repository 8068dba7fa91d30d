# Fig. 7(d): load against deflection, Mode I at 60 deg
load gpdir.'/common.gp'
ids = pic_fig7; labs = '"h = 2 (scene file)"'
do for [h in "8 4 1"] {
  id = value('sw_fig7_h'.h.'_ppc1')
  if (strlen(id) > 0) { ids = ids.' '.id; labs = labs.' "h = '.h.'"' }
}
set title sprintf("Fig. 7(d): Mode I, {/Symbol a} = 60 (analytic g = %.3g)", g_fig7)
sc = 'fig7'; xmax = 2.1
load gpdir.'/loadcurves.gp'
