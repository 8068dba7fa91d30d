#!/usr/bin/env bash
# check_method.sh DELAM SRC - the method presets through `delam run`:
#   paper-is-13   --method paper on fig7 (h 8, 1 ppc, to delta 0.3) writes the same
#                 load.csv and energy.csv, byte for byte, as the paper's thirteen
#                 overrides (ver_paper_sets) on the file, and says so in summary.json;
#   every-file    each preset on each scene file starts (h 8, to delta 0.002; vibration
#                 one period): exit 0;
#   unknown       an unknown preset, in a file or by --method: exit 2, naming the file,
#                 the line (or the command line) and the presets allowed;
#   verify-method delam verify --quick --method band --list: each case with the preset.
# Prints TAP; exits 1 if a check failed.
set -u
delam=${1:?usage: check_method.sh path/to/delam SRC}
src=${2:?usage: check_method.sh path/to/delam SRC}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/delam-method.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
n=0 fail=0
result() {
  n=$((n + 1))
  if [ -z "$2" ]; then echo "ok $n - $1"; else fail=$((fail + 1)); echo "not ok $n - $1: $2"; fi
}
cd "$tmp"
run() { "$delam" run "$src/data/scenes/$1.ini" --h 8 --ppc 1 --threads 1 --quiet "${@:2}" >/dev/null 2>run.err; }
why=""
run fig7 --until 0.3 --method paper --out paper || why="--method paper: $(head -2 run.err)"
run fig7 --until 0.3 --set grid.shape=linear --set grid.fields=one --set decohesion.Le=cell \
  --set imperfection.stf_factor=1 --set time.scheme=usl --set grid.node_mass=limited --set time.damping=0 \
  --set time.damping_beta=0 --set imperfection.size=particle --set decohesion.path=free --set grid.motion=fixed \
  --set decohesion.reversed_shear=even --set imperfection.snf_factor=0.9 --out sets || why="$why; the 13 sets: $(head -2 run.err)"
for f in load.csv energy.csv; do
  [ -z "$why" ] && ! cmp -s paper/$f sets/$f && why="$f differs"
done
[ -z "$why" ] && ! grep -q '"preset":[[:space:]]*"paper"' paper/summary.json && why="summary.json does not name the preset"
[ -z "$why" ] && ! grep -q '"case":[[:space:]]*"fig7-h8-ppc1-paper' paper/summary.json && why="the case id does not name it"
result paper-is-13 "$why"

why=""
for s in fig6 fig7 fig8 a30 a45 iface90 vibration; do
  for m in paper band interface; do
    len="--until 0.002"
    [ $s = vibration ] && len="--set vibration.periods=1" # its delta is a time: the grip stands
    run $s --method $m $len --out $s-$m || why="$why $s --method $m: $(head -1 run.err);"
  done
done
result every-file "$why"

why=""
printf '[method]\npreset = paperr\n[bar]\nL = 192\n' > bad.ini
"$delam" run bad.ini >/dev/null 2>err.txt
rc=$?
[ $rc = 2 ] || why="a file's unknown preset: exit $rc"
grep -q "bad.ini:2: method.preset: 'paperr' is not allowed (paper .*band .*interface" err.txt || why="$why; message: $(head -1 err.txt)"
run fig7 --method bandd
rc=$?
[ $rc = 2 ] || why="$why; --method bandd: exit $rc"
grep -q "fig7.ini: command line: method.preset: 'bandd' is not allowed (paper .*band .*interface" run.err ||
  why="$why; message: $(head -1 run.err)"
result unknown "$why"

# delam verify --method: every case runs with the preset, and its id says so
why=""
"$delam" verify --quick --method band --scenes "$src/data/scenes" --list >list.txt 2>err.txt || why="exit $?: $(head -1 err.txt)"
total=$(wc -l <list.txt)
# a case the solver refuses is listed as a comment, "# id: reason"; its id names the preset too
with=$(( $(grep -c -- '--set method.preset=band .*--out [^ ]*-band' list.txt) + $(grep -c '^# [^ ]*-band[^ ]*: ' list.txt) ))
[ -z "$why" ] && { [ "$total" -gt 0 ] && [ "$with" = "$total" ]; } || why="$why; $with of $total cases run the preset"
result verify-method "$why"

echo "1..$n"
[ $fail = 0 ]
