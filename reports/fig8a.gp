# Fig. 8(a): particles at delta = 0.7, 1.2, 1.7, 2.0 (h = 2)
W = 1200; Hgt = 1000
load gpdir.'/common.gp'
id = pic_fig8; hw = pic_fig8_hw; endd = pic_fig8_end
ds = "0.7 1.2 1.7 2.0"; rows = 4; cols = 1
x0 = -8; x1 = 196; y0 = -8; y1 = 44
ttl = sprintf("Fig. 8(a): fig8.ini, Mode II, {/Symbol a} = 60, particles coloured by {/Symbol l}\n%s (%s)", pic_fig8_method, id)
load gpdir.'/particles.gp'
