#!/usr/bin/env bash
# check_plot.sh DELAM SRC - `delam plot` (verify/cmd_plot.c):
#   plot-bar        fig6 at h 8: exit 0, DIR/plot.png a whole PNG (signature, IEND), the
#                   title with delam check's verdict (pass) and the closed form's Pmax 32;
#   plot-dcb        the DCB at h 8: a whole PNG; the reference drawn is data/fe/dcb.dat's
#                   delta_branch, P_branch (1e-6) at each of its a in (a0, L - 3 t], and the
#                   crack front panel is there;
#   plot-verdict    a check.json that says fail (a check named) is the title's verdict;
#   plot-foreign    a load.csv alone (another code's): drawn, "not judged" in the title, no
#                   reference; with --scene fig6 and --out FILE: judged, FILE written, not DIR's;
#   plot-bad        exit 2 with the reason: a folder without load.csv, no folder, a bad
#                   option, a load.csv without P_grip; --help exit 0;
#   plot-gnuplot    without gnuplot on PATH: exit 1 naming it, no PNG left behind.
# Prints TAP; exits 1 if a check failed.
set -u
delam=${1:?usage: check_plot.sh path/to/delam SRC}
src=${2:?usage: check_plot.sh path/to/delam SRC}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/delam-plot.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
n=0 fail=0
result() {
  n=$((n + 1))
  if [ -z "$2" ]; then echo "ok $n - $1"; else fail=$((fail + 1)); echo "not ok $n - $1: $2"; fi
}
cd "$tmp" || exit 1
export DELAM_SCENES="$src/data/scenes"
# png_whole FILE: why FILE is not a whole PNG, or nothing
png_whole() {
  [ -s "$1" ] || { echo "$1 missing or empty"; return; }
  [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || { echo "$1: no PNG signature"; return; }
  tail -c 8 "$1" | grep -q IEND || echo "$1: no IEND chunk at its end"
}

"$delam" run fig6 --h 8 --threads 1 --quiet --out bar >/dev/null 2>&1 || echo "# fig6 run failed"
"$delam" plot bar >bar.out 2>bar.err
rc=$?
why=""
[ "$rc" = 0 ] || why="exit $rc: $(head -2 bar.err)"
why="$why$(png_whole bar/plot.png)"
"$delam" plot bar --script >bar.gp 2>/dev/null
grep -q 'delam check: pass' bar.gp || why="$why; no 'delam check: pass' in the title"
grep -q 'closed form (delam analytic --curve), Pmax 32"' bar.gp || why="$why; no closed form with Pmax 32"
[ ! -e bar/check.json ] || why="$why; the check made for the title left bar/check.json"
result plot-bar "${why#; }"

"$delam" run dcb --h 8 --threads 1 --quiet --out dcb >/dev/null 2>&1 || echo "# dcb run failed"
"$delam" plot dcb >dcb.out 2>dcb.err
rc=$?
why=""
[ "$rc" = 0 ] || why="exit $rc: $(head -2 dcb.err)"
why="$why$(png_whole dcb/plot.png)"
"$delam" plot dcb --script >dcb.gp 2>/dev/null
grep -q "crack front against delta" dcb.gp || why="$why; no crack front panel"
# $ref's rows (delta P a) against the table's at its a in (64, 192 - 48]
bad=$(awk 'FNR == 1 {f++} f == 1 && /^\$ref/ {r = 1; next} f == 1 && r && /^EOD/ {r = 0} f == 1 && r {d[$3] = $1; P[$3] = $2}
  f == 2 && /^# a / {for (i = 2; i <= NF; i++) c[$i] = i - 1}
  f == 2 && !/^#/ && $1 > 64 && $1 <= 144 {m++; a = $1 + 0
    if (!(a in d)) {printf "a %s not drawn; ", a; next}
    e = (d[a] - $c["delta_branch"]) / $c["delta_branch"]; g = (P[a] - $c["P_branch"]) / $c["P_branch"]
    if (e > 1e-6 || e < -1e-6 || g > 1e-6 || g < -1e-6) printf "a %s: drawn %s %s, table %s %s; ", a, d[a], P[a], $c["delta_branch"], $c["P_branch"]}
  END {if (!m) print "no table rows"}' dcb.gp "$src/data/fe/dcb.dat")
[ -z "$bad" ] || why="$why; $bad"
result plot-dcb "${why#; }"

mkdir -p verdict && cp bar/load.csv bar/energy.csv bar/scene.ini bar/summary.json verdict/
printf '{"schema": 1, "verdict": "fail", "checks": [{"name": "peak_P", "verdict": "fail"}, {"name": "k_elastic", "verdict": "pass"}]}\n' \
  >verdict/check.json
"$delam" plot verdict --script >verdict.gp 2>verdict.err
rc=$?
why=""
[ "$rc" = 0 ] || why="exit $rc: $(head -2 verdict.err)"
grep -q 'delam check: fail (failed: peak_P) (check.json)' verdict.gp || why="$why; the title does not say check.json's fail (failed: peak_P)"
result plot-verdict "${why#; }"

mkdir -p foreign && cut -d, -f2,3 bar/load.csv >foreign/load.csv
"$delam" plot foreign >foreign.out 2>foreign.err
rc=$?
why=""
[ "$rc" = 0 ] || why="exit $rc: $(head -2 foreign.err)"
why="$why$(png_whole foreign/plot.png)"
grep -q 'delam check: not judged' foreign.out || why="$why; not 'not judged': $(head -1 foreign.out)"
"$delam" plot foreign --script >foreign.gp 2>/dev/null
grep -q 'no reference: no scene.ini' foreign.gp || why="$why; no 'no reference' note"
rm -f foreign/plot.png
"$delam" plot foreign --scene fig6 --out "$tmp/f6.png" >foreign6.out 2>foreign6.err
rc=$?
[ "$rc" = 0 ] || why="$why; --scene fig6: exit $rc: $(head -2 foreign6.err)"
why="$why$(png_whole "$tmp/f6.png")"
[ ! -e foreign/plot.png ] || why="$why; --out given, but foreign/plot.png written"
grep -q 'delam check: pass' foreign6.out || why="$why; --scene fig6 not judged pass: $(head -1 foreign6.out)"
result plot-foreign "${why#; }"

why=""
mkdir -p empty && cp bar/energy.csv empty/
"$delam" plot empty >/dev/null 2>e1.err; rc=$?
{ [ "$rc" = 2 ] && grep -q 'empty/load.csv: no such file' e1.err; } || why="$why; no load.csv: exit $rc $(head -1 e1.err)"
"$delam" plot nowhere >/dev/null 2>e2.err; rc=$?
{ [ "$rc" = 2 ] && grep -q 'nowhere: no such folder' e2.err; } || why="$why; no folder: exit $rc $(head -1 e2.err)"
"$delam" plot bar --colour red >/dev/null 2>e3.err; rc=$?
{ [ "$rc" = 2 ] && grep -q "unknown option '--colour'" e3.err; } || why="$why; bad option: exit $rc $(head -1 e3.err)"
mkdir -p nop && cut -d, -f1,2 bar/load.csv >nop/load.csv
"$delam" plot nop >/dev/null 2>e4.err; rc=$?
{ [ "$rc" = 2 ] && grep -q 'P_grip' e4.err; } || why="$why; no P_grip column: exit $rc $(head -1 e4.err)"
[ ! -e empty/plot.png ] && [ ! -e nop/plot.png ] || why="$why; a PNG written for a bad folder"
"$delam" plot --help >help.out 2>&1; rc=$?
{ [ "$rc" = 0 ] && grep -q '^usage: delam plot DIR' help.out; } || why="$why; --help: exit $rc"
result plot-bad "${why#; }"

why=""
rm -f bar/plot.png
PATH=/nonexistent "$delam" plot bar >/dev/null 2>g.err; rc=$?
{ [ "$rc" = 1 ] && grep -q 'gnuplot not found' g.err; } || why="exit $rc, want 1 naming gnuplot: $(head -1 g.err)"
ls bar | grep -q 'plot.png' && why="$why; a PNG or its temporary left: $(ls bar | grep plot.png)"
result plot-gnuplot "${why#; }"

echo "1..$n"
[ "$fail" -eq 0 ]
