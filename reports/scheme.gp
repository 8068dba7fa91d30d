# USL (paper) against MUSL on the inclined scenes, h = 4
W = 1400; Hgt = 560
load gpdir.'/common.gp'
set multiplot layout 1,2 title "Update scheme: USL (paper) against modified USL, h = 4, 1 ppc"
labs = '"USL" "MUSL"'  # fig8: USL without the file's damping_beta (it needs MUSL)
# each file: where it runs the interface (MUSL only), the band method's pair
set title "fig7, Mode I, {/Symbol a} = 60".(strstrt(scheme_fig7_usl, 'path_line') > 0 ? ", band method" : "")
ids = scheme_fig7_usl.' '.scheme_fig7_musl
sc = 'fig7'; xmax = 1.0
load gpdir.'/loadcurves.gp'
set title "fig8, Mode II, {/Symbol a} = 60".(strstrt(scheme_fig8_usl, 'path_line') > 0 ? ", band method" : "")
ids = scheme_fig8_usl.' '.scheme_fig8_musl
sc = 'fig8'; xmax = 1.0
load gpdir.'/loadcurves.gp'
unset multiplot
