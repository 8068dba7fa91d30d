# Fig. 7(c): displacement trajectories at delta = 0.35 (h = 2)
W = 1300; Hgt = 380
load gpdir.'/common.gp'
hw = pic_fig7_hw; id = pic_fig7; endd = pic_fig7_end; d = 0.35; s = 10
ttl = sprintf("Fig. 7(c): fig7.ini, Mode I, displacements at {/Symbol d} = 0.35, scaled by %g\n%s (%s)", s, pic_fig7_method, id)
load gpdir.'/trajectories.gp'
