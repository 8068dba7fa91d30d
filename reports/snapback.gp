# Snapback scenes: analytic g < 1 against the runs
# the curves fill each panel (the peak, the drop, the ringing about P = 0, the static
# branch back): every key goes below its panel
W = 1800; Hgt = 620
load gpdir.'/common.gp'
set bmargin 8
set multiplot layout 1,3 title "Snapback scenes (analytic g < 1: the load should drop vertically at the peak; black: the static solver, which follows the branch back)"
set title sprintf("a45, {/Symbol a} = 45 (g = %.3g)", g_a45)
ids = id_a45_h4_ppc1.' '.id_a45_h2_ppc1; labs = '"h = 4" "h = 2"'
sc = 'a45'; xmax = 1.1
keypos = "below left Left reverse font ',10' samplen 2 maxcols 1"
qs_id = qs_a45; qs_lab = sprintf('static h %g, %d ppc: path %.2g%s', qs_a45_h, qs_a45_ppc, qs_a45_path, qs_a45_note)
load gpdir.'/loadcurves.gp'
set title sprintf("a30, {/Symbol a} = 30 (g = %.3g)", g_a30)
ids = id_a30_h4_ppc1.' '.id_a30_h2_ppc1
sc = 'a30'; xmax = 1.1
keypos = "below left Left reverse font ',10' samplen 2 maxcols 1"
qs_id = qs_a30; qs_lab = sprintf('static h %g, %d ppc: path %.2g%s', qs_a30_h, qs_a30_ppc, qs_a30_path, qs_a30_note)
load gpdir.'/loadcurves.gp'
set title sprintf("fig8, Mode II, {/Symbol a} = 60 (g = %.3g)", g_fig8)
ids = pic_fig8; labs = '"h = 2"'
sc = 'fig8'; xmax = 1.1
keypos = "below left Left reverse font ',10' samplen 2 maxcols 1"
qs_id = qs_fig8; qs_lab = sprintf('static h %g, %d ppc: path %.2g%s', qs_fig8_h, qs_fig8_ppc, qs_fig8_path, qs_fig8_note)
load gpdir.'/loadcurves.gp'
unset multiplot
