#!/usr/bin/env bash
# check_faults.sh DELAM SRC - faults that must end in a clear error, never in a hang or
# in a verdict that says something false:
#   fifo-*       a FIFO (or a device) as the scene file or as a `delam check` input is
#                refused at once with exit 2 and a message naming it, within 5 s.
#   check-*      `delam check` judges only what it has verified: delam's own folder
#                passes; a run stopped by SIGTERM (summary.json complete: false), a
#                folder without summary.json, loads raised past delta 1 (W_ext 0.37 of
#                the work from the load curve's area), a delta that steps back by 2.0
#                under grip control, an energy.csv cut to its first tenth, a NUL or a
#                control byte are refused with exit 2 and the reason (row and column
#                for the bytes); the same step back under dissipation control is
#                judged; 2,000,000 rows are judged within 10 s.
# Prints TAP; exits 1 if a check failed.
set -u
delam=${1:?usage: check_faults.sh path/to/delam SRC}
src=${2:?usage: check_faults.sh path/to/delam SRC}
scene="$src/data/scenes/fig6.ini"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/delam-faults.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
n=0 fail=0
result() { # result ID WHY (empty WHY: pass)
  n=$((n + 1))
  if [ -z "$2" ]; then echo "ok $n - $1"; else fail=$((fail + 1)); echo "not ok $n - $1: $2"; fi
}
# exit status $1 and a line of err.txt matching $2, else why not
expect() {
  if [ "$rc" != "$1" ]; then echo "exit status $rc, not $1 ($(head -c 200 err.txt))"
  elif ! grep -qE -- "$2" err.txt; then echo "no message matching '$2': $(head -c 200 err.txt)"
  fi
}
cd "$tmp"
# one small run (fig6 at h 4, 3 s) that passes `delam check`: the base of the folders below
"$delam" run "$scene" --h 4 --threads 1 --quiet --out base >/dev/null 2>&1 || echo "# the base run failed"

# 1. FIFOs: timeout 5 turns a hang into exit 124
mkfifo fifo.ini
timeout 5 "$delam" run fifo.ini --out r >/dev/null 2>err.txt
rc=$?
result fifo-scene "$(expect 2 'fifo.ini: a FIFO, not a scene file')"
timeout 5 "$delam" check --scene /dev/null base >/dev/null 2>err.txt
rc=$?
result device-scene "$(expect 2 '/dev/null: a character device, not a scene file')"
for f in load.csv energy.csv final.csv scene.ini; do
  rm -rf ff && cp -r base ff && rm ff/$f && mkfifo ff/$f
  timeout 5 "$delam" check --scene "$scene" ff >/dev/null 2>err.txt
  rc=$?
  result "fifo-check-$f" "$(expect 2 "ff/$f: a FIFO, not a (CSV|scene) file")"
done
# 2. check: the base passes; then each fault in a copy of it
chk() { # chk FOLDER: runs delam check on it, rc and err.txt
  timeout 60 "$delam" check --scene "$scene" "$1" >out.txt 2>err.txt
  rc=$?
}
chk base
result check-base "$([ "$rc" = 0 ] || echo "exit $rc: $(tail -2 out.txt) $(head -c 300 err.txt)")"
"$delam" run "$scene" --h 1 --ppc 4 --threads 1 --quiet --out stopped >/dev/null 2>&1 &
pid=$!
for _ in $(seq 100); do [ -f stopped/scene.ini ] && break; sleep 0.1; done
sleep 1
kill -TERM "$pid"
wait "$pid"
chk stopped
result check-interrupted "$(expect 2 'summary.json says complete: false \(the run stopped at delta [0-9.e-]+.*not judged')"
cp -r base nosum && rm nosum/summary.json
chk nosum
result check-no-summary "$(expect 2 "scene.ini but no summary.json: the run has not finished")"
cp -r base raise
awk -F, 'BEGIN { OFS = "," } /^[#t]/ { print; next } { if ($2 > 1) $3 = 0.9; print }' base/load.csv >raise/load.csv
chk raise
result check-raised-loads "$(expect 2 "load.csv and energy.csv disagree: energy.csv's W_ext [0-9.]+ \\(data row [0-9]+\\) against [0-9.]+.*: 0.3[0-9] of the work apart")"
cp -r base back
awk -F, 'BEGIN { OFS = "," } /^[#t]/ { print; next } { if (++k == 5000) $2 -= 2.0; print }' base/load.csv >back/load.csv
chk back
result check-delta-back "$(expect 2 "back/load.csv: data row 5000: delta 0.5 is below the row before's 2.4995, but the grip only pulls")"
cp -r back backdiss && sed -i 's/^control = grip/control = dissipation/' backdiss/scene.ini
chk backdiss
why=""
grep -q 'control = dissipation' backdiss/scene.ini || why="scene.ini has no 'control = dissipation'"
[ "$rc" = 0 ] || [ "$rc" = 1 ] || why="not judged (exit $rc): $(head -c 200 err.txt)"
result check-delta-back-dissipation "$why"
cp -r base tenth && head -n 1002 base/energy.csv >tenth/energy.csv
chk tenth
result check-energy-tenth "$(expect 2 "energy.csv ends at t 500, load.csv at t 5000: they do not cover the same run")"
cp -r base nul && awk 'NR == 4001 { $0 = substr($0, 1, 7) "\\000" substr($0, 9) } { print }' base/load.csv | printf '%b' "$(cat)" >nul/load.csv
chk nul
result check-nul "$(expect 2 'nul/load.csv:4001: byte 8 of the line is a NUL byte \(0x00\)')"
cp -r base ctl && sed '300s/,/\x01,/' base/energy.csv >ctl/energy.csv
chk ctl
result check-control-byte "$(expect 2 'ctl/energy.csv:300: byte [0-9]+ of the line is a control byte \(0x01\)')"
# 2,000,000 rows (the load test's window sum made this quadratic: 69 s for 2.2 M)
mkdir big
awk 'BEGIN { print "delta,P_grip"; for (i = 1; i <= 2000000; i++) { d = i * 2.5e-7; printf "%.9g,%.9g\n", d, (d < 0.1875 ? 32 * d / 0.1875 : (d < 0.375 ? 32 * (0.375 - d) / 0.1875 : 0)) } }' >big/load.csv
start=$(date +%s.%N)
timeout 60 "$delam" check --scene "$scene" --h 4 --ppc 1 big >out.txt 2>err.txt
rc=$?
secs=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }')
echo "# check on 2,000,000 rows: $secs s, exit $rc"
why=""
if [ "$rc" != 0 ] && [ "$rc" != 1 ]; then why="exit $rc: $(head -c 200 err.txt)"
elif awk -v s="$secs" 'BEGIN { exit !(s > 10) }'; then why="$secs s, more than 10"
fi
result check-2m-rows "$why"

echo "1..$n"
[ "$fail" = 0 ]
