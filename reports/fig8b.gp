# Fig. 8(b): displacement trajectories at delta = 0.35 (h = 2)
W = 1300; Hgt = 380
load gpdir.'/common.gp'
hw = pic_fig8_hw; id = pic_fig8; endd = pic_fig8_end; d = 0.35; s = 10
ttl = sprintf("Fig. 8(b): fig8.ini, Mode II, displacements at {/Symbol d} = 0.35, scaled by %g\n%s (%s)", s, pic_fig8_method, id)
load gpdir.'/trajectories.gp'
