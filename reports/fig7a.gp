# Fig. 7(a): decohesion around the crack at delta = 0.24, 0.25, 0.26, 0.28 (h = 2)
W = 1100; Hgt = 900
load gpdir.'/common.gp'
id = pic_fig7; hw = pic_fig7_hw; endd = pic_fig7_end
ds = "0.24 0.25 0.26 0.28"; rows = 2; cols = 2
x0 = 70; x1 = 122; y0 = -2; y1 = 34
# the decohesion is still small at these deltas: the colour scale ends at the largest lambda shown
cbmax = lam_max_fig7a
ttl = sprintf("Fig. 7(a): fig7.ini, Mode I, {/Symbol a} = 60, {/Symbol l} near the crack, scale to %.3g\n%s (%s)", cbmax, pic_fig7_method, id)
load gpdir.'/particles.gp'
