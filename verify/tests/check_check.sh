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
#   columns-sign another code's header names (u, F) and sign (compression positive) read
#                with --columns and --sign -1; without them the messages say so;
#   own-scene    a delam run with --set decohesion.U0 = 2 x the file's: `delam check DIR`
#                judges it against its own scene.ini (D_final's reference is the set U0
#                times the file's H, worked out here), `--scene fig6 DIR` refuses it
#                (exit 2, naming decohesion.U0 with both values), and `--scene fig6 --set
#                decohesion.U0=...` agrees with the folder and judges it;
#   wave-cap     an iface90 run with U0 1000 (its separation 1e3 out, the exact solution
#                at the grip speed 1.3e8 samples, 3 GB): exit 2 within 10 s, naming the
#                cap, not a verdict after minutes;
#   exact-curve  the closed form's own curve (`delam analytic --curve`, its header delta,P as
#                written: the elastic line as
#                one segment, rows unevenly spaced) passes: fig6 as an explicit run
#                (k_elastic = E H / L from the scene file, delta_sep within the 6 %), and
#                fig8's snapback as a static run, its delta_sep the closed form's to 1e-9
#                (the row at 2 % of the peak was 1.2 % off here, 10-17 % at stronger snapbacks);
#   degenerate   g = 1 (fig6 with bar.L doubled): k_soft's reference is infinite, so it is
#                skipped with the reason (not "reference inf, err -nan %"), and a curve
#                whose first row, its peak, is at 1e300 prints no nan: each number that
#                cannot be measured says why (k_elastic: no rows before the peak);
#   messages     a UTF-8 byte-order mark before the header is skipped (the curve is judged),
#                UTF-16 text is refused naming its mark, a CSV over 256 MiB is refused
#                naming that limit and docs/output-formats.md states the same limit, a
#                check.json that cannot be written names the reason (strerror).
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
sed '1s/P_grip/Pg/' other/load.csv > bad1/load.csv
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

# the closed form's own curves
E=$(awk -F' *= *' '/^\[/ { s = $0 } s == "[material]" && $1 == "E" { print $2 + 0 }' "$scene")
L=$(awk -F' *= *' '/^\[/ { s = $0 } s == "[bar]" && $1 == "L" { print $2 + 0 }' "$scene")
mkdir exact6 exact8
"$delam" analytic --curve exact6/load.csv >/dev/null # its own header, delta,P, read as it is
"$delam" check --scene "$scene" --h 4 exact6 >out.txt 2>&1
rc=$?
why=""
[ $rc = 0 ] || why="fig6's closed form: exit $rc: $(grep -E 'FAIL|check:' out.txt | head -3)"
kel=$(python3 -c 'import json, sys; print(next(c["measured"] for c in json.load(open(sys.argv[1]))["checks"] if c["name"] == "k_elastic"))' exact6/check.json 2>/dev/null)
[ -z "$why" ] && ! awk -v k="$kel" -v e="$E" -v h="$H" -v l="$L" 'BEGIN { exit !(k != "" && (k - e * h / l) ^ 2 <= 1e-20 * (e * h / l) ^ 2) }' &&
  why="k_elastic measured '$kel', not E H / L = $E x $H / $L"
"$delam" analytic --alpha 60 --snf 10 --stf 1 --s0 10 --curve exact8/load.csv >/dev/null && sed -i '1s/,P$/,P_grip/' exact8/load.csv
dsep=$("$delam" analytic --alpha 60 --snf 10 --stf 1 --s0 10 --json | python3 -c 'import json, sys; print(json.load(sys.stdin)["delta_sep"])')
"$delam" check --scene "$src/data/scenes/fig8.ini" --h 4 --set solver.type=static exact8 >out.txt 2>&1
rc=$?
[ -z "$why" ] && [ $rc != 0 ] && why="fig8's closed form, static: exit $rc: $(grep -E 'FAIL|check:' out.txt | head -3)"
got=$(python3 -c 'import json, sys; print(next(c["measured"] for c in json.load(open(sys.argv[1]))["checks"] if c["name"] == "delta_sep"))' exact8/check.json 2>/dev/null)
[ -z "$why" ] && ! awk -v g="$got" -v w="$dsep" 'BEGIN { exit !(g != "" && (g - w) ^ 2 <= 1e-18 * w ^ 2) }' &&
  why="fig8 static delta_sep measured '$got', the closed form's $dsep"
result exact-curve "$why"

"$delam" run "$scene" --h 8 --set bar.L=$((2 * L)) --threads 1 --quiet --out g1 >/dev/null 2>&1
"$delam" check g1 >out.txt 2>&1
why=""
grep -qE '^skip +g1 vs .* k_soft: not judged: .*vertical' out.txt || why="no skip line for k_soft: $(grep k_soft out.txt | head -c 300)"
[ -z "$why" ] && grep -qiE 'nan|reference inf' out.txt && why="$(grep -iE 'nan|reference inf' out.txt | head -2)"
[ -z "$why" ] && ! grep -q '"name":[[:space:]]*"k_soft",[[:space:]]*"reason"' <(tr -d '\n' <g1/check.json) &&
  why="check.json's skipped does not name k_soft"
mkdir huge
awk -F, 'NR == 1 || ++k != 1 { print; next } { print "1e300," $2 "," $3 }' other/load.csv >huge/load.csv
"$delam" check --scene "$scene" --h 4 --ppc 4 huge >out.txt 2>&1
rc=$?
[ -z "$why" ] && [ $rc != 1 ] && why="peak 1e300: exit $rc, not 1: $(head -c 200 out.txt)"
[ -z "$why" ] && grep -qi 'nan' out.txt && why="peak 1e300: $(grep -i nan out.txt | head -2)"
[ -z "$why" ] && ! grep -q 'k_elastic: not measured: fewer than 3 rows' out.txt && why="peak 1e300: k_elastic: $(grep k_elastic out.txt)"
result degenerate "$why"

mkdir bom utf16 large
printf '\357\273\277' >bom/load.csv && cat other/load.csv >>bom/load.csv
"$delam" check --scene "$scene" --h 4 --ppc 4 bom >out.txt 2>&1
rc=$?
why=""
[ $rc = 0 ] || why="UTF-8 BOM: exit $rc: $(head -c 200 out.txt)"
printf '\377\376d\000' >utf16/load.csv
"$delam" check --scene "$scene" utf16 >out.txt 2>&1
rc=$?
[ -z "$why" ] && { { [ $rc = 2 ] && grep -q "utf16/load.csv:1: UTF-16 text (it starts with the byte-order mark 0xff 0xfe)" out.txt; } ||
  why="UTF-16: exit $rc: $(head -c 200 out.txt)"; }
truncate -s 257M large/load.csv
"$delam" check --scene "$scene" large >out.txt 2>&1
rc=$?
[ -z "$why" ] && { { [ $rc = 2 ] && grep -q "large/load.csv: larger than 256 MiB: refused" out.txt; } ||
  why="257 MiB: exit $rc: $(head -c 200 out.txt)"; }
rm -f large/load.csv
[ -z "$why" ] && ! grep -q "CSV file of at most 256 MiB" "$src/docs/output-formats.md" && why="docs/output-formats.md does not say 256 MiB"
[ -z "$why" ] && grep -q "64 MiB" "$src/docs/output-formats.md" && why="docs/output-formats.md still says 64 MiB"
"$delam" check --scene "$scene" --h 4 --ppc 4 --out nowhere/check.json other >out.txt 2>&1
rc=$?
[ -z "$why" ] && { { [ $rc = 1 ] && grep -q "nowhere/check.json: cannot write: No such file or directory" out.txt; } ||
  why="--out nowhere/: exit $rc: $(grep 'delam check' out.txt | head -c 200)"; }
result messages "$why"

# another code's names and sign: u and F with compression positive; without --columns the
# message names the option, with it and --sign -1 the folder passes as load-only did, and
# without --sign the verdict fails and says the load is mostly negative
mkdir named
awk -F, 'NR > 1 && $1 !~ /^#/ { if (!h) { print "u,F"; h = 1; next } print $2 "," (-$3) }' own/load.csv > named/load.csv
why=""
"$delam" check --scene "$scene" --h 4 --ppc 4 named >out.txt 2>&1
rc=$?
[ $rc = 2 ] && grep -q -- "--columns delta=NAME,P_grip=NAME" out.txt || why="no --columns hint (exit $rc): $(head -2 out.txt)"
"$delam" check --scene "$scene" --h 4 --ppc 4 --columns delta=u,P_grip=F named >out.txt 2>&1
rc=$?
[ $rc = 1 ] && grep -q "mostly negative.*--sign -1" out.txt || why="$why; unsigned: exit $rc, want 1 with the --sign hint"
"$delam" check --scene "$scene" --h 4 --ppc 4 --columns delta=u,P_grip=F --sign -1 named >out.txt 2>&1
rc=$?
[ $rc = 0 ] || why="$why; mapped and signed: exit $rc: $(grep -E 'FAIL|check:' out.txt | head -3)"
result columns-sign "${why#; }"

echo "1..$n"
[ "$fail" = 0 ]
