# Fig. 6(a): fig6 particles coloured by lambda at delta = 0.25, 0.5, 3.0, 5.0 (fig6.ini as written)
W = 1200; Hgt = 1000
load gpdir.'/common.gp'
id = pic_fig6; hw = pic_fig6_hw; endd = pic_fig6_end
ds = "0.25 0.5 3.0 5.0"; rows = 4; cols = 1
ttl = sprintf("Fig. 6(a): fig6.ini, {/Symbol a} = 90\n%s (%s)", pic_fig6_method, id)
load gpdir.'/particles.gp'
