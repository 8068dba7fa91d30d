# The bar at the paper's grip speed: the exact solution (analytic/ana_wave.c) against the
# quasi-static curve, fig6.ini (the paper's method) and iface90.ini (the interface)
W = 1400; Hgt = 600
load gpdir.'/common.gp'
set multiplot layout 1,2 title "Fig. 6's bar at the grip speed: the exact 1-D wave solution (cohesive plane) against the quasi-static curve"
set title "load against deflection, h = 2, 1 ppc"
set xlabel "end displacement {/Symbol d} (dimensionless units, the paper's)"
set ylabel "load P (dimensionless units, the paper's)"
set xrange [0.15:0.42]
set yrange [-3:35]
set key top right
f6 = rate_fig6_h2; fi = rate_iface_h2
plot 'data/ana-fig6.csv' u 1:2 w l lw 3 dt 2 lc rgb '#999999' title 'quasi-static (eq. 34)', \
     (have_rate ? 'data/wave.csv' : '/dev/null') u 1:2 w l lw 4 lc rgb 'black' title 'exact at the grip speed', \
     (f6 ne '' ? load_csv(f6) : '/dev/null') u 2:3 w l lw 1.8 lc rgb '#1f77b4' title 'fig6.ini (USL, band, flaw)', \
     (fi ne '' ? load_csv(fi) : '/dev/null') u 2:3 w l lw 1.8 lc rgb '#d62728' title 'iface90.ini (MUSL, interface)'
set title "RMS load error / P_{max} to {/Symbol l} = 0.98, 1 ppc"
set datafile separator whitespace
set datafile nocolumnheaders
set logscale xy
set xrange [0.8:10]
set yrange [*:*]
set xtics (1, 2, 4, 8)
set xlabel "grid spacing h (dimensionless units, the paper's)"
set ylabel "RMS load error / P_{max}"
set format y "10^{%T}"
set key top right
plot 'data/rate.dat' u 1:2 w lp pt 7 ps 1.4 lw 1.5 dt 2 lc rgb '#1f77b4' title 'fig6.ini vs quasi-static', \
     'data/rate.dat' u 1:3 w lp pt 6 ps 1.4 lw 1.5 lc rgb '#1f77b4' title 'fig6.ini vs exact', \
     'data/rate.dat' u 1:4 w lp pt 7 ps 1.4 lw 1.5 dt 2 lc rgb '#d62728' title 'iface90.ini vs quasi-static', \
     'data/rate.dat' u 1:5 w lp pt 6 ps 1.4 lw 1.5 lc rgb '#d62728' title 'iface90.ini vs exact'
unset multiplot
