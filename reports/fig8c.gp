# Fig. 8(c): load against deflection, Mode II at 60 deg
load gpdir.'/common.gp'
ids = ''; labs = ''
do for [h in "8 4 2 1"] {
  key = (h eq '2') ? 'pic_fig8' : 'sw_fig8_h'.h.'_ppc1'
  id = value(key)
  if (strlen(id) > 0) {
    ids = ids.' '.id
    labs = labs.' "h = '.h.((h eq '2') ? ', scene file' : '').value(key.'_note').'"'
  }
}
# the paper's method beside the scene file's, where they differ (same grid)
if (strlen(paper_fig8) > 0) { ids = ids.' '.paper_fig8; labs = labs.' "h = 2, paper method"' }
# and the crack as a cohesive interface (decohesion.path = interface, same grid)
if (strlen(iface_fig8) > 0) { ids = ids.' '.iface_fig8; labs = labs.' "h = 2, interface"' }
# the scene file's method, without its grid (the key gives h; every curve is 1 ppc)
meth = pic_fig8_method; cut = strstrt(meth, ", h ="); if (cut > 1) { meth = meth[1:cut-1] }
set title sprintf("Fig. 8(c): fig8.ini, Mode II, {/Symbol a} = 60, 1 ppc (analytic g = %.3g: snapback)\nscene file: %s", g_fig8, meth)
sc = 'fig8'; xmax = 2.1
# the quasi-static solver's run, traced through the snapback (report_qs.c)
qs_id = qs_fig8; qs_lab = sprintf('static, h = %g, %d ppc, interface, path %.2g%s', qs_fig8_h, qs_fig8_ppc, qs_fig8_path, qs_fig8_note)
load gpdir.'/loadcurves.gp'
