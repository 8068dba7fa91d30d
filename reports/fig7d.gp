# Fig. 7(d): load against deflection, Mode I at 60 deg
load gpdir.'/common.gp'
ids = ''; labs = ''
do for [h in "8 4 2 1"] {
  key = (h eq '2') ? 'pic_fig7' : 'sw_fig7_h'.h.'_ppc1'
  id = value(key)
  if (strlen(id) > 0) {
    ids = ids.' '.id
    labs = labs.' "h = '.h.((h eq '2') ? ', scene file' : '').value(key.'_note').'"'
  }
}
# the paper's method beside the scene file's, where they differ (same grid)
if (strlen(paper_fig7) > 0) { ids = ids.' '.paper_fig7; labs = labs.' "h = 2, paper method"' }
# and the crack as a cohesive interface (decohesion.path = interface, same grid)
if (strlen(iface_fig7) > 0) { ids = ids.' '.iface_fig7; labs = labs.' "h = 2, interface"' }
# the scene file's method, without its grid (the key gives h; every curve is 1 ppc)
meth = pic_fig7_method; cut = strstrt(meth, ", h ="); if (cut > 1) { meth = meth[1:cut-1] }
set title sprintf("Fig. 7(d): fig7.ini, Mode I, {/Symbol a} = 60, 1 ppc (analytic g = %.3g)\nscene file: %s", g_fig7, meth)
sc = 'fig7'; xmax = 2.1
load gpdir.'/loadcurves.gp'
