# The split beams (report_spec.c): the DCB (top) and the ELS (bottom) on the static
# solver at h 4 and 2, 4 ppc; left the load against the opening, right the crack tip
# (load.csv: t,delta,P_grip,P_fixed,crack_tip,...) against it; the references of delam
# check; the bottom row the errors of `delam check` against h (h 8, 4, 2: spec-conv.csv).
# Units: the model's own (E = 1024, arms t = 16 thick, G_c = 0.1875 per unit area).
W = 1800; Hgt = 1850
load gpdir.'/common.gp'
set multiplot layout 3,2 title sprintf("Split beams on the static solver (dcb.ini; the ELS: specimen.type = els, snf 10, stf 1), %d ppc, against 2-D finite elements (data/fe) and beam theory", spec_ppc)
run(s, h) = value(sprintf('spec_%s_h%g', s, h))
runlab(s, h) = sprintf('MPM h = %g (t / %g)%s', h, 16 / h, value(sprintf('spec_%s_h%g_note', s, h)))
# the runs: h 4 thick and black, h 2 thinner and red; the cohesive beam (grey, wide)
# beneath them, the LEFM branches (dashed, dotted) over them, so that each shows
runs = "4 2"; rc(i) = i == 1 ? 'black' : '#d62728'; rw(i) = i == 1 ? 2.6 : 1.6
fe_lc = '#1f77b4'; beam_lc = '#2ca02c'; el_lc = '#9467bd'
set xlabel "opening {/Symbol d} of the arms' ends (dimensionless model units; arms t = 16)"

# --- DCB: P against delta ---
set title sprintf("DCB (mode I): load P on one arm against the arms' opening {/Symbol d}\n(pre-crack a_0 = %g; G_c = 0.1875)", spec_dcb_a0)
set ylabel "P, force per unit width on one arm (dimensionless, E = 1024)"
set xrange [0:15]; set yrange [0:4]
set key bottom right font ',11' samplen 3 width -6
plot 'data/spec-dcb-czm.csv' u 1:2 w l lw 7 lc rgb '#bbbbbb' title 'cohesive beam (Timoshenko arm on the law)', \
     for [i=1:2] load_csv(run('dcb', word(runs, i) + 0)) u 2:3 w l lw rw(i) lc rgb rc(i) title runlab('dcb', word(runs, i) + 0), \
     'data/spec-dcb-elastic.csv' u 1:2 w l lw 1.5 dt 4 lc rgb el_lc title sprintf('elastic line P = {/Symbol d} / C(a_0), 2-D FE C(a_0) = %.4g', spec_dcb_C0), \
     'data/spec-dcb-fe.csv' u 2:3 w l lw 1.8 dt 2 lc rgb fe_lc title "2-D LEFM branch, FE: P = (2 G_c / C'(a))^{1/2}", \
     'data/spec-dcb-beam.csv' u 2:3 w l lw 2 dt 3 lc rgb beam_lc title 'LEFM branch, corrected beam theory'

# --- DCB: crack tip against delta ---
set title "DCB: crack tip against {/Symbol d}\n(runs: the farthest separated node of the line; the cohesive beam: where its law has separated)"
set ylabel "crack tip x (dimensionless model units; bar length L = 192)"
set yrange [56:168]
set key top left font ',11' samplen 3 width -4
plot 'data/spec-dcb-czm.csv' u 1:3 w l lw 7 lc rgb '#bbbbbb' title 'cohesive beam', \
     for [i=1:2] load_csv(run('dcb', word(runs, i) + 0)) u 2:5 w l lw rw(i) lc rgb rc(i) title runlab('dcb', word(runs, i) + 0), \
     'data/spec-dcb-fe.csv' u 2:1 w l lw 1.8 dt 2 lc rgb fe_lc title '2-D LEFM branch, FE: crack length a'

# --- ELS: P against delta ---
set title sprintf("ELS (mode II): total load P on both arms against their deflection {/Symbol d}\n(pre-crack a_0 = %g < 0.55 L: the LEFM branch snaps back, {/Symbol d} falling as a grows from a_0)", spec_els_a0)
set ylabel "P, force per unit width on both arms (dimensionless, E = 1024)"
set xlabel "deflection {/Symbol d} of the arms' ends (dimensionless model units; arms t = 16)"
set xrange [0:17]; set yrange [0:10]
set key bottom right font ',11' samplen 3 width -6
plot for [i=1:2] load_csv(run('els', word(runs, i) + 0)) u 2:3 w l lw rw(i) lc rgb rc(i) title runlab('els', word(runs, i) + 0), \
     'data/spec-els-elastic.csv' u 1:2 w l lw 1.5 dt 4 lc rgb el_lc title sprintf('elastic line P = {/Symbol d} / C(a_0), 2-D FE C(a_0) = %.4g', spec_els_C0), \
     'data/spec-els-fe.csv' u 2:3 w l lw 1.8 dt 2 lc rgb fe_lc title '2-D LEFM branch, FE (turns back: snapback)', \
     'data/spec-els-beam.csv' u 2:3 w l lw 2 dt 3 lc rgb beam_lc title 'LEFM branch, corrected beam theory'

# --- ELS: crack tip against delta ---
set title "ELS: crack tip against {/Symbol d}\n(runs: the farthest separated node of the line)"
set ylabel "crack tip x (dimensionless model units; bar length L = 192)"
set yrange [56:184]
set key bottom right font ',11' samplen 3 width -4
plot for [i=1:2] load_csv(run('els', word(runs, i) + 0)) u 2:5 w l lw rw(i) lc rgb rc(i) title runlab('els', word(runs, i) + 0), \
     'data/spec-els-fe.csv' u 2:1 w l lw 1.8 dt 2 lc rgb fe_lc title '2-D LEFM branch, FE: crack length a'

# --- convergence in h: delam check's errors (spec-conv.csv: spec, h, compliance, peak, branch) ---
conv = 'data/spec-conv.csv'
set logscale xy; set xrange [1.6:10]; set xtics (2, 4, 8); set format y '%g'
set xlabel "grid spacing h (cells across an arm: 16 / h)"
set title "Compliance before initiation against the 2-D FE C(a_0): |C / C_{FE} - 1|\n(first order: the crack tip's singular field)"
set ylabel "relative error of the compliance"
set yrange [1e-3:0.2]
set key top left font ',11' samplen 3
plot conv u ($1 == 0 ? $2 : NaN):3 w lp pt 7 ps 1.6 lw 2.6 lc rgb 'black' title 'DCB (mode I)', \
     conv u ($1 == 1 ? $2 : NaN):3 w lp pt 5 ps 1.6 lw 2.6 lc rgb '#d62728' title 'ELS (mode II)', \
     0.0092 * x w l dt 2 lw 1.5 lc rgb '#777777' title 'slope 1'
set title "The load: DCB peak against the cohesive beam; the propagation branch (RMS)\nagainst the 2-D LEFM branch once the front is 2 t past a_0"
set ylabel "relative error"
set yrange [1e-3:0.2]
plot conv u ($1 == 0 ? $2 : NaN):4 w lp pt 7 ps 1.6 lw 2.6 lc rgb 'black' title 'DCB peak load (the beam differs from the 2-D continuum by about 0.4 %)', \
     conv u ($1 == 0 ? $2 : NaN):5 w lp pt 6 ps 1.6 lw 2 dt 2 lc rgb 'black' title 'DCB branch RMS', \
     conv u ($1 == 1 ? $2 : NaN):5 w lp pt 4 ps 1.6 lw 2 dt 2 lc rgb '#d62728' title 'ELS branch RMS'
unset multiplot
