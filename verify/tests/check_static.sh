#!/usr/bin/env bash
# check_static.sh DELAM SRC - the static path's branch, stability and refusals:
#   branch-same-build   iface90 with U0 0.01875 (g 0.1), h 4, 4 ppc: the uniform opening, the
#                       closed form's path (delam check's curve_path below 1e-5) and D = U0 H,
#                       on every build (rounding chose a one-sided opening, curve_path 0.030,
#                       on -O3 and the uniform one on -O0);
#   stability-snapback  fig8 at h 8 (g 0.45): det_sign +1 on the elastic rows below 95 % of
#                       Pmax, -1 on every row of the snapback between 5 % and 95 % after the
#                       peak (the 1-D chain's stiffness k - k_s < 0 where delta falls with P),
#                       summary.json naming a critical point at the peak's delta (eq. 30:
#                       Pmax, delta_peak = Pmax L / (E H), from the scene);
#   band-snapback       fig6's band with U0 0.125 (g 0.67), h 8 and 4: refused up front with
#                       exit 2 and the reason, no folder written (it stalled at h 4 after
#                       delta went to -0.018); the interface traces the same bar (curve_path
#                       below 1e-5);
#   tiny-end            fig6 static with end_delta 0.001 (below its first increment): ends at
#                       delta 0.001 exactly with P = E H / L x 0.001 (it stopped at 0.021).
# Prints TAP; exits 1 if a check failed.
set -u
delam=${1:?usage: check_static.sh DELAM SRC}
src=${2:?usage: check_static.sh DELAM SRC}
scenes=$src/data/scenes
tmp=$(mktemp -d "${TMPDIR:-/tmp}/delam-static.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
n=0 fail=0
result() { # result ID WHY (empty WHY: pass)
  n=$((n + 1))
  if [ -z "$2" ]; then echo "ok $n - $1"; else fail=$((fail + 1)); echo "not ok $n - $1: $2"; fi
}
# curve_path of delam check on folder $1 (empty if none)
curve_path() { "$delam" check "$1" 2>&1 | sed -n 's/.*curve_path: measured \([-0-9.e+]*\).*/\1/p' | head -n 1; }
below() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a != "" && a + 0 < b + 0) }'; }

"$delam" run "$scenes/iface90.ini" --solver static --h 4 --ppc 4 --threads 1 --quiet --set decohesion.U0=0.01875 \
  --set output.snapshots=0 --out g01 >/dev/null 2>err.txt
rc=$?
why=""
if [ $rc != 0 ]; then why="exit status $rc: $(head -c 300 err.txt)"
else
  cp=$(curve_path g01)
  below "$cp" 1e-5 || why="curve_path '$cp', want below 1e-5 (the uniform opening)"
  D=$(python3 -c "import json; print(json.load(open('g01/summary.json'))['D_final'])")
  below "$(awk -v d="$D" 'BEGIN { x = d / (0.01875 * 32) - 1; print x < 0 ? -x : x }')" 1e-6 || why="$why; D_final $D, want U0 H = 0.6"
fi
result branch-same-build "${why#; }"

"$delam" run "$scenes/fig8.ini" --solver static --h 8 --ppc 4 --threads 1 --quiet --set output.snapshots=0 \
  --out f8 >/dev/null 2>err.txt
rc=$?
why=""
if [ $rc != 0 ]; then why="exit status $rc: $(head -c 300 err.txt)"
else
  why=$(python3 - f8 "$scenes/fig8.ini" <<'PY'
import configparser, csv, json, math, sys
d, ini = sys.argv[1], sys.argv[2]
c = configparser.ConfigParser(inline_comment_prefixes=(";",))
c.read(ini)
f = lambda s, k: float(c[s][k])
a = math.radians(f("decohesion", "alpha"))
r0 = 1 / math.hypot(math.sin(a) ** 2 / f("decohesion", "snf"), math.sin(a) * math.cos(a) / f("decohesion", "stf"))
Pmax, dpk = r0 * f("bar", "H"), r0 * f("bar", "L") / f("material", "E")
rows = list(csv.DictReader(l for l in open(d + "/load.csv") if not l.startswith("#")))
P = [float(r["P_grip"]) for r in rows]
det = [r.get("det_sign") for r in rows]
ipk = max(range(len(P)), key=P.__getitem__)
bad = [i + 1 for i in range(len(P)) if (i < ipk and P[i] < 0.95 * Pmax and det[i] != "1")
       or (i > ipk and 0.05 * Pmax < P[i] < 0.95 * Pmax and det[i] != "-1")]
judged = sum(1 for i in range(len(P)) if (i < ipk and P[i] < 0.95 * Pmax) or (i > ipk and 0.05 * Pmax < P[i] < 0.95 * Pmax))
cp = json.load(open(d + "/summary.json")).get("critical_points", [])
if None in det: print("load.csv has no det_sign column")
elif judged < 12: print("only %d rows judged" % judged)
elif bad: print("det_sign wrong on rows %s" % bad[:10])
elif not cp or abs(cp[0]["delta"] / dpk - 1) > 1e-3 or abs(cp[0]["P"] / Pmax - 1) > 1e-3:
    print("first critical point %s, want at delta_peak %.6g, Pmax %.6g" % (cp[:1], dpk, Pmax))
PY
)
fi
result stability-snapback "$why"

for h in 8 4; do
  "$delam" run "$scenes/fig6.ini" --solver static --h $h --ppc 4 --threads 1 --quiet --set decohesion.U0=0.125 \
    --out band$h >/dev/null 2>err.txt
  rc=$?
  why=""
  [ $rc = 2 ] || why="exit status $rc, want 2"
  grep -q "snaps back (g = 0.667" err.txt || why="$why; no reason: $(head -c 300 err.txt)"
  [ -e band$h ] && why="$why; a folder was written"
  result "band-snapback-refused-h$h" "${why#; }"
done
"$delam" run "$scenes/fig6.ini" --solver static --method interface --h 8 --ppc 4 --threads 1 --quiet \
  --set decohesion.U0=0.125 --set output.snapshots=0 --out iface >/dev/null 2>err.txt
rc=$?
cp=$(curve_path iface)
why=""
[ $rc = 0 ] || why="exit status $rc: $(head -c 300 err.txt)"
below "$cp" 1e-5 || why="$why; curve_path '$cp', want below 1e-5"
result band-snapback-interface "${why#; }"

# a run's end before its first increment's: the linear state there
"$delam" run "$scenes/fig6.ini" --solver static --h 8 --ppc 4 --threads 1 --quiet --set run.end_delta=0.001 \
  --out tiny >/dev/null 2>err.txt
rc=$?
why=""
[ $rc = 0 ] || why="exit status $rc: $(head -c 300 err.txt)"
last=$(grep -v '^#' tiny/load.csv 2>/dev/null | tail -1)
w=$(echo "$last" | awk -F, -v E="$(sed -n 's/^E *= *//p' "$scenes/fig6.ini")" \
  -v H="$(sed -n 's/^H *= *//p' "$scenes/fig6.ini")" -v L="$(sed -n 's/^L *= *//p' "$scenes/fig6.ini")" \
  '{ if ($2 - 0.001 > 1e-12 || 0.001 - $2 > 1e-12) print "last delta " $2;
     else if ($3 / (E * H / L * 0.001) - 1 > 1e-8 || 1 - $3 / (E * H / L * 0.001) > 1e-8) print "P " $3 " against " E * H / L * 0.001 }')
[ -z "$w" ] || why="$why; $w"
result tiny-end "${why#; }"

echo "1..$n"
echo "# $((n - fail)) passed, $fail failed"
[ "$fail" = 0 ]
