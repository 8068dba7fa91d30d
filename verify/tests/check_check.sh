#!/usr/bin/env bash
# check_check.sh DELAM SRC - `delam check` on folders "another code" wrote:
#   own-run      delam's own Fig. 6 run at h 4, 4 ppc passes every check (exit 0) and
#                check.json says pass;
#   load-only    its load curve alone, columns reordered, extra columns, no schema line:
#                passes the checks it allows, and D / energy balance are left out;
#   twice-energy the same curve with the softening branch three times as long, so the
#                area under it (the energy the curve dissipates) is twice the paper's
#                U0 H / 2: exit 1, naming W_ext_final;
#   unusable     a missing column, a bad number, no load.csv: exit 2, naming file,
#                line and column;
#   own-scene    a delam run with --set decohesion.U0 = 2 x the file's: `delam check DIR`
#                judges it against its own scene.ini (D_final's reference is the set U0
#                times the file's H, worked out here), `--scene fig6 DIR` refuses it
#                (exit 2, naming decohesion.U0 with both values), and `--scene fig6 --set
#                decohesion.U0=...` agrees with the folder and judges it;
#   wave-cap     an iface90 run with U0 1000 (its separation 1e3 out, the exact solution
#                at the grip speed 1.3e8 samples, 3 GB): exit 2 within 10 s, naming the
#                cap, not a verdict after minutes.
# Prints TAP; exits 1 if a check failed.
set -u
delam=${1:?usage: check_check.sh path/to/delam SRC}
src=${2:?usage: check_check.sh path/to/delam SRC}
scene="$src/data/scenes/fig6.ini"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/delam-check.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
n=0 fail=0
result() {
  n=$((n + 1))
  if [ -z "$2" ]; then echo "ok $n - $1"; else fail=$((fail + 1)); echo "not ok $n - $1: $2"; fi
}
cd "$tmp"
"$delam" run "$scene" --h 4 --ppc 4 --threads 1 --quiet --out own >/dev/null 2>&1
"$delam" check --scene "$scene" own >out.txt 2>&1
rc=$?
why=""
[ $rc = 0 ] || why="exit $rc: $(grep -E 'FAIL|check:' out.txt | head -3)"
[ -z "$why" ] && ! grep -q '"verdict":[[:space:]]*"pass"' own/check.json 2>/dev/null && why="check.json does not say pass"
result own-run "$why"

# another code's folder: P_grip first, an extra column, delta last, no '#' line
mkdir other twice
awk -F, 'NR > 1 && $1 !~ /^#/ { if (!h) { print "P_grip,step,delta"; h = 1; next } print $3 "," NR "," $2 }' own/load.csv > other/load.csv
"$delam" check --scene "$scene" --h 4 --ppc 4 other >out.txt 2>&1
rc=$?
why=""
[ $rc = 0 ] || why="exit $rc: $(grep -E 'FAIL|check:' out.txt | head -3)"
[ -z "$why" ] && grep -q "D_final\|energy_residual" out.txt && why="D_final or energy_residual judged without energy.csv"
result load-only "$why"

# twice the energy: delta' = dpk + 3 (delta - dpk) past the peak
python3 - own/load.csv twice/load.csv <<'PY'
import csv, sys
rows = [r for r in csv.reader(open(sys.argv[1])) if r and not r[0].startswith('#')]
head, data = rows[0], [[float(x) for x in r] for r in rows[1:]]
d, p = head.index('delta'), head.index('P_grip')
k = max(range(len(data)), key=lambda i: data[i][p])
dpk = data[k][d]
w = lambda rs: sum(0.5 * (rs[i][p] + rs[i - 1][p]) * (rs[i][d] - rs[i - 1][d]) for i in range(1, len(rs)))
w0 = w(data)
for r in data:
    if r[d] > dpk:
        r[d] = dpk + 3 * (r[d] - dpk)
with open(sys.argv[2], 'w') as f:
    f.write('delta,P_grip\n')
    for r in data:
        f.write('%.9g,%.9g\n' % (r[d], r[p]))
print('area %.4g -> %.4g' % (w0, w(data)), file=sys.stderr)
PY
"$delam" check --scene "$scene" --h 4 --ppc 4 twice >out.txt 2>&1
rc=$?
why=""
[ $rc = 1 ] || why="exit $rc, not 1"
[ -z "$why" ] && ! grep -q "^check: fail, failed:.*W_ext_final" out.txt && why="the verdict line does not name W_ext_final: $(grep '^check:' out.txt | head -1)"
result twice-energy "$why"

why=""
mkdir bad1 bad2 bad3
sed '1s/P_grip/P/' other/load.csv > bad1/load.csv
"$delam" check --scene "$scene" bad1 >out.txt 2>&1; rc=$?
{ [ $rc = 2 ] && grep -q "bad1/load.csv:1: the header has no column 'P_grip'" out.txt; } || why="missing column: exit $rc, $(head -1 out.txt)"
awk 'NR == 5 { print "1.5,9,0.25e"; next } { print }' other/load.csv > bad2/load.csv
"$delam" check --scene "$scene" bad2 >out.txt 2>&1; rc=$?
[ -z "$why" ] && { { [ $rc = 2 ] && grep -q "bad2/load.csv:5:3: column 'delta': '0.25e'" out.txt; } || why="bad number: exit $rc, $(head -1 out.txt)"; }
awk 'NR == 5 { print "abc,x9,0.25"; next } { print }' other/load.csv > bad2/load.csv
"$delam" check --scene "$scene" bad2 >out.txt 2>&1; rc=$?
[ -z "$why" ] && { { [ $rc = 2 ] && grep -q "bad2/load.csv:5:1: column 'P_grip': 'abc'" out.txt; } || why="bad number: exit $rc, $(head -1 out.txt)"; }
"$delam" check --scene "$scene" bad3 >out.txt 2>&1; rc=$?
[ -z "$why" ] && { { [ $rc = 2 ] && grep -q "bad3/load.csv: no such file" out.txt; } || why="no load.csv: exit $rc, $(head -1 out.txt)"; }
result unusable "$why"

# a run of another problem than the scene file's: twice its U0
u0=$(awk -F' *= *' '/^\[/ { s = $0 } s == "[decohesion]" && $1 == "U0" { print $2 + 0 }' "$scene")
H=$(awk -F' *= *' '/^\[/ { s = $0 } s == "[bar]" && $1 == "H" { print $2 + 0 }' "$scene")
u2=$(awk -v u="$u0" 'BEGIN { printf "%.17g", 2 * u }')
"$delam" run "$scene" --h 8 --set decohesion.U0="$u2" --threads 1 --quiet --out twiceU0 >/dev/null 2>&1
"$delam" check twiceU0 >out.txt 2>&1
rc=$?
why=""
[ $rc = 0 ] || why="delam check DIR: exit $rc: $(grep -E 'FAIL|check:|delam check' out.txt | head -3)"
ref=$(python3 -c 'import json, sys; print(next(c["reference"] for c in json.load(open(sys.argv[1]))["checks"] if c["name"] == "D_final"))' twiceU0/check.json 2>/dev/null)
[ -z "$why" ] && ! awk -v r="$ref" -v u="$u2" -v h="$H" 'BEGIN { exit !(r != "" && (r - u * h) ^ 2 <= 1e-18 * (u * h) ^ 2) }' &&
  why="D_final's reference is '$ref', not U0 $u2 x H $H"
"$delam" check --scene "$scene" twiceU0 >out.txt 2>&1
rc=$?
[ -z "$why" ] && { { [ $rc = 2 ] && grep -q "twiceU0/scene.ini: .* decohesion.U0 ($u0 in fig6, $u2 in the run)" out.txt; } ||
  why="--scene fig6 on the U0 run: exit $rc, $(head -c 300 out.txt)"; }
"$delam" check --scene "$scene" --set decohesion.U0="$u2" twiceU0 >out.txt 2>&1
rc=$?
[ -z "$why" ] && [ $rc != 0 ] && why="--scene fig6 --set decohesion.U0=$u2: exit $rc, $(head -c 300 out.txt)"
result own-scene "$why"

"$delam" run "$src/data/scenes/iface90.ini" --h 8 --set decohesion.U0=1000 --set run.end_delta=0.3 --threads 1 \
  --quiet --out bigU0 >/dev/null 2>&1
start=$(date +%s.%N)
timeout 60 "$delam" check bigU0 >out.txt 2>&1
rc=$?
secs=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }')
why=""
{ [ $rc = 2 ] && grep -q "bigU0: curve_wave needs the exact solution at the grip speed, and .* above its cap of 4e+06" out.txt; } ||
  why="exit $rc after $secs s: $(head -c 300 out.txt)"
[ -z "$why" ] && awk -v s="$secs" 'BEGIN { exit !(s > 10) }' && why="$secs s"
result wave-cap "$why"

echo "1..$n"
[ "$fail" = 0 ]
