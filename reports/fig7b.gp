# Fig. 7(b): particles at delta = 0.7, 1.2, 1.7, 2.0 (h = 2)
W = 1200; Hgt = 1000
load gpdir.'/common.gp'
id = pic_fig7; hw = pic_fig7_hw; endd = pic_fig7_end
ds = "0.7 1.2 1.7 2.0"; rows = 4; cols = 1
x0 = -8; x1 = 196; y0 = -8; y1 = 44
ttl = sprintf("Fig. 7(b): fig7.ini, Mode I, {/Symbol a} = 60, particles coloured by {/Symbol l}\n%s (%s)", pic_fig7_method, id)
load gpdir.'/particles.gp'
