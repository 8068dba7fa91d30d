# common.gp - loaded first by every figure script of `delam report`.
# gnuplot runs in the report folder (reports/out) with fmt ('png' or 'svg'), gpdir
# (this folder) and name (the figure) set on the command line; W and Hgt may be set
# by the script before loading this file.
if (!exists("W")) W = 1000
if (!exists("Hgt")) Hgt = 650
if (fmt eq 'svg') {
  set terminal svg size W,Hgt dynamic enhanced font 'Helvetica,13' background rgb 'white'
} else {
  set terminal pngcairo size W,Hgt enhanced font 'Helvetica,12' background rgb 'white'
}
set output name.'.'.fmt
load 'data/vars.gp'
set datafile separator comma
set datafile columnheaders
set key box opaque
set grid lc rgb '#dddddd'
# lambda colour scale: intact blue, damaged yellow-red, separated (lambda >= 1) dark red
set palette defined (0 '#1f3f8f', 0.005 '#5fb8e8', 0.1 '#6cc46c', 0.3 '#f2e05a', 0.7 '#e8752a', 1 '#8b0000')
exists_file(f) = int(system(sprintf("[ -r '%s' ] && echo 1 || echo 0", f)))
snap(id, d) = sprintf('data/%s/snap-d%.3f.csv', id, d)
# decohesion.path = interface: the line's segments with their lambda
snapl(id, d) = sprintf('data/%s/snap-d%.3f-line.csv', id, d)
load_csv(id) = sprintf('data/%s/load.csv', id)
