# USL (paper) against MUSL on the inclined scenes, h = 4
W = 1400; Hgt = 560
load gpdir.'/common.gp'
set multiplot layout 1,2 title "Update scheme: USL (paper) against modified USL, h = 4, 1 ppc"
labs = '"USL" "MUSL"'  # fig8: USL without the file's damping_beta (it needs MUSL)
set title "fig7, Mode I, {/Symbol a} = 60"
ids = id_fig7_h4_ppc1_u1_schemeusl.' '.id_fig7_h4_ppc1_u1_schememusl
sc = 'fig7'; xmax = 1.0
load gpdir.'/loadcurves.gp'
set title "fig8, Mode II, {/Symbol a} = 60"
ids = id_fig8_h4_ppc1_u1_schemeusl_damping_beta0.' '.id_fig8_h4_ppc1_u1_schememusl
sc = 'fig8'; xmax = 1.0
load gpdir.'/loadcurves.gp'
unset multiplot
