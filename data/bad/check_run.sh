#!/usr/bin/env bash
# check_run.sh DELAM - what `delam run` does when a run goes wrong after it started:
#   nonfinite  a time step far above the CFL bound (--allow-unstable) stops the run with
#              exit status 1 and a message naming the step, the particle and the field;
#   sigterm,   a signal stops the run cleanly: exit status 130, summary.json with
#   sigint,    "complete": false, no *.tmp file left behind;
#   sighup
#   determinism  the same scene run twice gives byte-identical load.csv, energy.csv,
#              final.csv (and snapshots); summary.json differs only in its timings;
#              and 1 and 2 threads give the same files;
#   list-merge `verify --list` lines run by hand, then `verify --merge` checks them;
#   uniform-bifurcation  fig6 without its flaw, static, h 8 and 4, and with a flaw of
#              1e-6 at h 8: exit 1 naming the bifurcation, the linear branch's rows to it
#              (det_sign +1) in load.csv and the tie in summary.json's critical_points;
#   made-energy  fig6 at h 8, 1 ppc with dt 0.12 (0.7 of the CFL bound) blows up after
#              separation (D 2.9 U0 H): exit 1 naming the energy made, complete: false; with
#              --allow-unstable it runs on, summary.json says unstable: true and check
#              refuses it (exit 2); the paper's dt 0.1 runs complete and stable.
# Prints TAP; exits 1 if a check failed.
set -u
delam=${1:?usage: check_run.sh path/to/delam}
here=$(cd "$(dirname "$0")" && pwd)
fig6=$(cd "$here/../scenes" && pwd)/fig6.ini
tmp=$(mktemp -d "${TMPDIR:-/tmp}/delam-run.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
n=0 fail=0

result() { # result ID WHY (empty WHY: pass)
  n=$((n + 1))
  if [ -z "$2" ]; then echo "ok $n - $1"; else fail=$((fail + 1)); echo "not ok $n - $1: $2"; fi
}

# "complete": false in summary.json, and no *.tmp file, in folder $1; else why not.
partial_ok() {
  if [ ! -f "$1/summary.json" ]; then echo "no summary.json"
  elif ! grep -q '"complete":[[:space:]]*false' "$1/summary.json"; then echo "summary.json does not say complete: false"
  elif ls "$1"/*.tmp >/dev/null 2>&1; then echo "*.tmp files left: $(cd "$1" && echo *.tmp)"
  fi
}

# 1. Non-finite: E = 1e300 puts the CFL bound near 1e-150, so dt = 0.1 is far above
#    it; without decohesion nothing caps the stress, which overflows at once.
out=$tmp/nonfinite
"$delam" run "$fig6" --set decohesion.model=0 --set material.E=1e300 --allow-unstable \
  --out "$out" --quiet >/dev/null 2>"$tmp/err"
rc=$?
why=""
if [ "$rc" != 1 ]; then why="exit status $rc, not 1"
elif ! grep -qE 'non-finite value: step [0-9]+: particle at X = [-0-9.e+]+, Y = [-0-9.e+]+: [a-z_]+ is not finite' "$tmp/err"
then why="no message naming step, particle and field: $(head -1 "$tmp/err")"
else why=$(partial_ok "$out")
fi
result nonfinite "$why"

# 2. Signals: a run of some seconds (h = 1, 4 particles per cell, one thread), stopped
#    a second after it has started its time loop (the output folder exists by then).
for sig in TERM INT HUP; do
  out=$tmp/sig$sig
  "$delam" run "$fig6" --h 1 --ppc 4 --threads 1 --out "$out" --quiet >/dev/null 2>"$tmp/err" &
  pid=$!
  for _ in $(seq 100); do [ -d "$out" ] && break; sleep 0.1; done
  sleep 1
  kill -s "$sig" "$pid"
  wait "$pid"
  rc=$?
  why=""
  if [ "$rc" != 130 ]; then why="exit status $rc, not 130 ($(head -1 "$tmp/err"))"
  elif ! grep -q 'stopped by a signal at step' "$tmp/err"; then why="no 'stopped by a signal' message"
  else why=$(partial_ok "$out")
  fi
  result "sig${sig,,}" "$why"
done

# 3. Determinism: two runs into two folders, compared byte by byte.  One thread, as
#    OpenMP threads that wait by spinning are slow when the cores are shared.
for k in 1 2; do
  "$delam" run "$fig6" --until 0.1 --set output.snapshots=0.05 --threads 1 --out "$tmp/det$k" --quiet >/dev/null 2>&1 ||
    echo "# run $k failed"
done
why=""
for f in load.csv energy.csv final.csv final.vtp snap-d0.050.csv snap-d0.050.vtp snapshots.pvd; do
  cmp -s "$tmp/det1/$f" "$tmp/det2/$f" || why="$why $f differs or is missing;"
done
timings='"(wall_s|cpu_s|updates_per_s)"'
if ! diff <(grep -vE "$timings" "$tmp/det1/summary.json") <(grep -vE "$timings" "$tmp/det2/summary.json") >/dev/null
then why="$why summary.json differs beyond its timings"
fi
result determinism "$why"

# 4. The same with one thread and with two: the scatter is coloured so that the sums
#    do not depend on the thread count.  Passive waiting: spinning threads on shared
#    cores make this tiny run take seconds.
OMP_WAIT_POLICY=passive "$delam" run "$fig6" --until 0.1 --set output.snapshots=0.05 --threads 2 --out "$tmp/det3" --quiet >/dev/null 2>&1
why=""
for f in load.csv energy.csv final.csv; do
  cmp -s "$tmp/det1/$f" "$tmp/det3/$f" || why="$why $f differs or is missing;"
done
result determinism-threads "$why"

# 5. A sweep dispatched by hand: `verify --list` prints runnable lines; two of them run,
#    then `verify --merge` (no --quick/--full) checks exactly the two folders it finds.
why=""
scenes=$(cd "$here/../scenes" && pwd)
if ! "$delam" verify --quick --list --scenes "$scenes" --out "$tmp/sweep" >"$tmp/list" 2>"$tmp/err"; then
  why="verify --list failed: $(head -c 300 "$tmp/err")"
else
  grep -E -- '/fig6-h8-ppc(1|4)$' "$tmp/list" | while read -r line; do
    eval "$line" >/dev/null 2>&1 || echo "# failed: $line"
  done
  "$delam" verify --merge "$tmp/sweep" --scenes "$scenes" >"$tmp/merge" 2>&1
  rc=$?
  if [ "$rc" != 0 ]; then why="merge exit status $rc: $(tail -n 1 "$tmp/merge")"
  elif ! grep -q '^verify: 2 cases' "$tmp/merge"; then why="merge did not find exactly 2 cases: $(tail -n 1 "$tmp/merge")"
  elif ! grep -q '"mode":[[:space:]]*"found"' "$tmp/sweep/verify.json"; then why="verify.json does not say mode found"
  fi
fi
result list-merge "$why"

# a uniform bar without its flaw, statically, h 8 and 4 (and at h 8 with a flaw of 1e-6,
# within the first grip increment's 1e-4 of the rest: that increment starts them all):
# every particle of the band reaches its strength at once, a bifurcation the uniform
# softening branch would follow to a dissipation of 13 U0 H; the run follows the linear
# branch to it, stops with exit 1 and names it: load.csv's rows with det_sign end at the
# closed form's initiation of the weakest particle, delta = f snf L / E = f 0.1875, P =
# f snf H = f 32 (f the flaw's factor), and summary.json's critical_points names the tie
for c in 8:1 4:1 8:0.999999; do
  h=${c%%:*} f=${c#*:}
  o=$tmp/noflaw$h-$f
  "$delam" run "$fig6" --solver static --h $h --ppc 4 --threads 1 --quiet --set imperfection.snf_factor=$f \
    --out "$o" >/dev/null 2>"$o.err"
  rc=$?
  why=""
  [ "$rc" = 1 ] || why="exit status $rc, want 1"
  grep -q "reach their strength together.*bifurcates" "$o.err" || why="$why; no reason: $(head -c 300 "$o.err")"
  w=$(partial_ok "$o")
  [ -z "$w" ] || why="$why; $w"
  w=$(python3 - "$o" "$f" <<'PY'
import csv, json, sys
d, f = sys.argv[1], float(sys.argv[2])
rows = list(csv.DictReader(l for l in open(d + "/load.csv") if not l.startswith("#")))
s = json.load(open(d + "/summary.json"))
c = s.get("critical_points", [])
dd, PP = f * 0.1875, f * 32
if not rows or "det_sign" not in rows[0]: print("load.csv has no det_sign column")
elif any(r["det_sign"] != "1" for r in rows): print("det_sign not +1 on the linear branch")
elif abs(float(rows[-1]["delta"]) - dd) > 1e-9 or abs(float(rows[-1]["P_grip"]) - PP) > 1e-7:
    print("last row delta %s P %s, want %.9g, %.9g" % (rows[-1]["delta"], rows[-1]["P_grip"], dd, PP))
elif len(c) != 1 or c[0]["kind"] != "tie of a uniform state" or c[0]["increment"] != len(rows) \
        or abs(c[0]["delta"] - dd) > 1e-9 or abs(c[0]["P"] - PP) > 1e-7:
    print("critical_points %s, want one tie at increment %d, delta %.9g, P %.9g" % (c, len(rows), dd, PP))
PY
)
  [ -z "$w" ] || why="$why; $w"
  result "uniform-bifurcation-h$h-flaw$f" "${why#; }"
done

# a blow-up never says complete: the run watches the energy it makes
why=""
"$delam" run "$fig6" --dt 0.12 --threads 1 --quiet --out "$tmp/made" >/dev/null 2>"$tmp/made.err"
rc=$?
[ "$rc" = 1 ] || why="dt 0.12: exit $rc, want 1"
grep -q "made energy" "$tmp/made.err" || why="$why; no 'made energy' on stderr: $(head -c 200 "$tmp/made.err")"
grep -q '"complete":[[:space:]]*false' "$tmp/made/summary.json" 2>/dev/null || why="$why; summary.json not complete: false"
"$delam" run "$fig6" --dt 0.12 --allow-unstable --threads 1 --quiet --out "$tmp/madeu" >/dev/null 2>&1
rc=$?
[ "$rc" = 0 ] || why="$why; --allow-unstable: exit $rc, want 0"
grep -q '"unstable":[[:space:]]*true' "$tmp/madeu/summary.json" 2>/dev/null || why="$why; summary.json not unstable: true"
"$delam" check "$tmp/madeu" >/dev/null 2>&1
rc=$?
[ "$rc" = 2 ] || why="$why; check on the unstable folder: exit $rc, want 2"
"$delam" run "$fig6" --threads 1 --quiet --out "$tmp/paper" >/dev/null 2>&1
rc=$?
[ "$rc" = 0 ] || why="$why; the paper's dt: exit $rc, want 0"
grep -q '"unstable"' "$tmp/paper/summary.json" 2>/dev/null && why="$why; the paper's dt marked unstable"
result made-energy "${why#; }"

echo "1..$n"
echo "# $((n - fail)) passed, $fail failed"
[ "$fail" = 0 ]
