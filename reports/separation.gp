# Separation threshold 0.98 against 0.8 (fig6, h = 8, 4 ppc)
load gpdir.'/common.gp'
ids = id_fig6_h8_ppc4_u0_6_separation0_98.' '.id_fig6_h8_ppc4_u0_6_separation0_8
labs = '"threshold 0.98 (paper)" "threshold 0.8"'
set title "Separation threshold: fig6, h = 8, 4 particles per cell"
sc = 'fig6'; xmax = 0.6
load gpdir.'/loadcurves.gp'
