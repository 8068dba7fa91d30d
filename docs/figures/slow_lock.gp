# slow_lock.gp - called by slow_lock.sh with dir (the three runs) and out (the PNG)
set terminal pngcairo size 1500,520 font ",11"
set output out
set datafile separator ","
set multiplot layout 1,3 title "fig7.ini at h 2, a sixteenth of the grip speed: lambda of each segment of the line against its height" font ",13"
set xlabel "height of the segment's middle, y"
set ylabel "lambda"
set xrange [0:32]
set yrange [0:1]
set grid
set key top right
ds = "0.260 0.270 0.275 0.280"
f(r, d) = sprintf("%s/%s/snap-d%s-line.csv", dir, r, d)
do for [r in "p1 p1half p4"] {
  set title (r eq "p1" ? "1 ppc, the file's step 0.025: the bottom segment locks" : r eq "p1half" ? "1 ppc, half the step (0.0125): uniform" : "4 ppc, the file's step: uniform")
  plot for [d in ds] f(r, d) skip 2 using (($2 + $4) / 2):5 with linespoints pt 7 ps 0.8 lw 2 title "delta ".d
}
unset multiplot
