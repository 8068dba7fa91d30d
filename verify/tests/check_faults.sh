#!/usr/bin/env bash
# check_faults.sh DELAM SRC - faults that must end in a clear error, never in a hang or
# in a verdict that says something false:
#   fifo-*       a FIFO (or a device) as the scene file or as a `delam check` input is
#                refused at once with exit 2 and a message naming it, within 5 s.
#   check-*      `delam check` judges only what it has verified: delam's own folder
#                passes; a run stopped by SIGTERM (summary.json complete: false), a
#                folder without summary.json or with a damaged one (another code's
#                summary.json without "complete" is no bar), loads raised past delta 1 (W_ext 0.37 of
#                the work from the load curve's area), a delta that steps back by 2.0
#                under grip control, an energy.csv cut to its first tenth, a NUL or a
#                control byte are refused with exit 2 and the reason (row and column
#                for the bytes); a step back under dissipation control or from the
#                static solver (which follows a snapback) is judged; an energy.csv of every 10th row is judged, its D dated by t;
#                2,000,000 rows are judged within 10 s.
#   check-summary-*  a summary.json cut short, with text after its object, whose
#                "complete" is "false", 0 or null, that is a FIFO or a directory, with
#                scene.ini and without (-1, -0), or missing beside delam's energy.csv
#                and final.csv alone: exit 2 naming the file and what it holds, on one
#                line (a newline in the run's error shown as '?': found by make fuzz-check).
#   writer-*     one writer per output folder: a second run into a folder a first run
#                is writing exits 2 naming the folder and the first's pid, and touches
#                nothing (the first's scene.ini still says ppc 4, its summary.json is
#                its own), and `delam check` refuses the folder while it is written;
#                once the first has ended, the same second run works there; a second
#                verify (or report) into a folder one is writing is refused the same way.
#   out-*        --out that is a regular file, a path under one, a symlink loop: exit 2
#                naming it; a full disk (a 300 KiB tmpfs, where mount is allowed): exit 1
#                naming the file that could not be written and why, no *.tmp and no
#                empty file left, and "partial results" only beside a summary.json
#                that says complete: false.
#   stop-*       SIGTERM to `delam verify` (then SIGINT and SIGHUP to reruns into the same
#                folder, then SIGTERM to `delam report`): exit 130 within 30 s, no
#                process it started still alive, verify.json written with exit_status
#                130, the stopped cases' summary.json saying complete: false; SIGKILL
#                to verify: its cases stop too (complete: false), none left running.
# Prints TAP; exits 1 if a check failed.
set -u
delam=${1:?usage: check_faults.sh path/to/delam SRC}
src=${2:?usage: check_faults.sh path/to/delam SRC}
scene="$src/data/scenes/fig6.ini"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/delam-faults.XXXXXX")
mnt=""
trap '[ -n "$mnt" ] && umount "$mnt"; rm -rf "$tmp"' EXIT
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
# another code's folder: its files without delam's schema lines
mkdir nosum2 && for f in load.csv energy.csv final.csv; do grep -v '^#' base/$f >nosum2/$f; done
echo '{"code": "another", "steps": 12}' >nosum2/summary.json
timeout 60 "$delam" check --scene "$scene" --h 4 --ppc 1 nosum2 >out.txt 2>err.txt
rc=$?
result check-foreign-summary "$([ "$rc" = 0 ] || echo "another code's summary.json without 'complete': exit $rc, $(head -c 200 err.txt)")"
cp -r base badsum && echo 'not json' >badsum/summary.json
chk badsum
result check-damaged-summary "$(expect 2 'badsum/summary.json: not whole JSON \(unexpected text at byte 1 of its 9 bytes\): the run.s record is damaged')"
# summary.json must be a regular file of one whole JSON object whose "complete" is
# literally true, with scene.ini or without (the folder is still delam's: its energy.csv
# and final.csv carry delam's schema lines)
sumcase() { # sumcase ID KEEP-SCENE-INI WHAT EXPECTED: WHAT is the summary's text, fifo, dir or none
  rm -rf sc && cp -r base sc && rm sc/summary.json
  [ "$2" = 1 ] || rm sc/scene.ini
  case $3 in
    fifo) mkfifo sc/summary.json ;;
    dir) mkdir sc/summary.json ;;
    none) ;;
    *) printf '%s' "$3" >sc/summary.json ;;
  esac
  timeout 10 "$delam" check --scene "$scene" --h 4 sc >out.txt 2>err.txt
  rc=$?
  result "check-summary-$1" "$(expect 2 "$4")"
}
for ini in 1 0; do
  sumcase cut-$ini $ini '{"complete": false' 'sc/summary.json: not whole JSON \(it ends before the JSON does, after 18 of its 18 bytes\)'
  sumcase string-$ini $ini '{"complete": "false"}' 'sc/summary.json: "complete" is "false", not true'
  sumcase zero-$ini $ini '{"complete": 0}' 'sc/summary.json: "complete" is 0, not true'
  sumcase null-$ini $ini '{"complete": null}' 'sc/summary.json: "complete" is null, not true'
  sumcase trailing-$ini $ini '{"complete": true} {' 'sc/summary.json: not whole JSON \(unexpected text at byte 20 of its 20 bytes\)'
  sumcase fifo-$ini $ini fifo 'sc/summary.json: a FIFO, not a regular file'
  sumcase dir-$ini $ini dir 'sc/summary.json: a directory, not a regular file'
done
sumcase error-newline 1 '{"complete": false, "error": "line one
line two"}' 'sc/summary.json says complete: false \(the run stopped at delta nan: line one\?line two\)'
[ "$(wc -l <err.txt)" = 1 ] || result check-summary-one-line "the message has $(wc -l <err.txt) lines"
sumcase none-0 0 none "sc: delam's files \(energy.csv or final.csv with its schema line\) but no summary.json"
cp -r base raise
awk -F, 'BEGIN { OFS = "," } /^[#t]/ { print; next } { if ($2 > 1) $3 = 0.9; print }' base/load.csv >raise/load.csv
chk raise
result check-raised-loads "$(expect 2 "load.csv and energy.csv disagree: energy.csv's W_ext [0-9.]+ \\(data row [0-9]+\\) against [0-9.]+.*: 0.3[0-9] of the work apart")"
cp -r base back
awk -F, 'BEGIN { OFS = "," } /^[#t]/ { print; next } { if (++k == 5000) $2 -= 2.0; print }' base/load.csv >back/load.csv
chk back
result check-delta-back "$(expect 2 "back/load.csv: data row 5000: delta 0.5 is below the row before's 2.4995, but the grip only pulls")"
cp -r back backdiss && sed -i 's/^control = grip/control = dissipation/' backdiss/scene.ini
timeout 60 "$delam" check backdiss >out.txt 2>err.txt
rc=$?
why=""
grep -q 'control = dissipation' backdiss/scene.ini || why="scene.ini has no 'control = dissipation'"
[ "$rc" = 0 ] || [ "$rc" = 1 ] || why="not judged (exit $rc): $(head -c 200 err.txt)"
result check-delta-back-dissipation "$why"
# the static solver's own snapback (fig8: delta moves back from the peak's 0.43 to 0.19)
"$delam" run "$src/data/scenes/fig8.ini" --h 8 --ppc 4 --solver static --threads 1 --quiet --out staticback >/dev/null 2>&1
timeout 60 "$delam" check staticback >out.txt 2>err.txt
rc=$?
why=""
grep -q '^type = static' staticback/scene.ini || why="scene.ini has no 'type = static'"
awk -F, '/^[#t]/ || !NF { next } { if (n++ && $2 < d - 0.01) back = 1; d = $2 } END { exit !back }' staticback/load.csv ||
  why="load.csv's delta never steps back by 0.01"
[ "$rc" = 0 ] || [ "$rc" = 1 ] || why="not judged (exit $rc): $(head -c 200 err.txt)"
result check-delta-back-static-solver "$why"
cp -r base tenth && head -n 1002 base/energy.csv >tenth/energy.csv
chk tenth
result check-energy-tenth "$(expect 2 "energy.csv ends at t 500, load.csv at t 5000: they do not cover the same run")"
cp -r base dec && awk 'NR <= 2 || NR % 10 == 2' base/energy.csv >dec/energy.csv
chk dec
why=""
[ "$rc" = 0 ] || why="exit $rc: $(head -c 200 err.txt)"
[ -z "$why" ] && ! grep -q 'D_cut: [0-9.]* at the detected separation' out.txt && why="D_cut not dated by t: $(grep D_cut out.txt)"
result check-energy-every-10th-row "$why"
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

# 3. two writers: A (h 2, 4 ppc, about 40 s alone) is stopped once B has been refused
"$delam" run "$scene" --h 2 --ppc 4 --threads 1 --quiet --out shared >/dev/null 2>errA.txt &
pidA=$!
for _ in $(seq 100); do [ -f shared/scene.ini ] && break; sleep 0.1; done
timeout 60 "$delam" run "$scene" --h 4 --ppc 1 --threads 1 --quiet --out shared >/dev/null 2>err.txt
rc=$?
why=$(expect 2 "shared: another delam process \\(pid $pidA\\) is writing this folder")
[ -z "$why" ] && ! grep -q '^ppc = 4' shared/scene.ini && why="scene.ini no longer says ppc 4: $(grep '^ppc' shared/scene.ini)"
result writer-second-refused "$why"
chk shared
result check-while-running "$(expect 2 "shared: a delam process \\(pid $pidA\\) is writing this folder now: not judged")"
kill -TERM "$pidA"
wait "$pidA"
rcA=$?
why=""
if [ "$rcA" != 130 ]; then why="the first run's exit status $rcA, not 130"
elif ! grep -q '"ppc":[[:space:]]*4' shared/summary.json || ! grep -q '"complete":[[:space:]]*false' shared/summary.json
then why="summary.json is not the stopped ppc-4 run's"
elif ls shared/*.tmp >/dev/null 2>&1; then why="temporaries left: $(cd shared && echo *.tmp)"
fi
result writer-first-intact "$why"
touch marker
sleep 0.1
timeout 60 "$delam" run "$scene" --h 4 --ppc 1 --threads 1 --quiet --out shared >/dev/null 2>err.txt
rc=$?
why=""
if [ "$rc" != 0 ]; then why="exit $rc: $(head -c 200 err.txt)"
elif ! grep -q '^ppc = 1' shared/scene.ini || ! grep -q '"complete":[[:space:]]*true' shared/summary.json
then why="the folder is not the new run's"
elif [ -n "$(find shared -type f ! -newer marker ! -name .delam.lock)" ]
then why="files of the first run left: $(find shared -type f ! -newer marker ! -name .delam.lock | tr '\n' ' ')"
fi
result writer-rerun-after "$why"

# 4. --out that cannot be a folder: exit 2, named
touch afile
ln -s loop loop
for out in afile afile/sub loop; do
  timeout 60 "$delam" run "$scene" --h 4 --quiet --out "$out" >/dev/null 2>err.txt
  rc=$?
  result "out-not-a-folder $out" "$(expect 2 "^delam run: $out: cannot create the folder: (Not a directory|Too many levels of symbolic links)")"
done
# a full disk: a 300 KiB tmpfs holds the scene and a few snapshots of an h 4 run, not all
mkdir disk
if mount -t tmpfs -o size=300k tmpfs disk 2>/dev/null; then
  mnt=$tmp/disk
  timeout 60 "$delam" run "$scene" --h 4 --threads 1 --quiet --out disk/r >/dev/null 2>err.txt
  rc=$?
  why=$(expect 1 "^delam run: disk/r/[a-z0-9.-]+: cannot write: No space left on device")
  [ -z "$why" ] && ls disk/r/*.tmp >/dev/null 2>&1 && why="temporaries left: $(cd disk/r && echo *.tmp)"
  [ -z "$why" ] && [ -n "$(find disk/r -type f -empty ! -name .delam.lock)" ] && why="empty files: $(find disk/r -type f -empty)"
  if [ -z "$why" ] && grep -q 'partial results' err.txt && ! grep -q '"complete":[[:space:]]*false' disk/r/summary.json 2>/dev/null
  then why="'partial results' said without a summary.json saying complete: false"
  fi
  result out-full-disk "$why"
else
  n=$((n + 1))
  echo "ok $n - out-full-disk # SKIP mount -t tmpfs is not allowed here"
fi

# 5. signals to the commands that start children
descendants() { # every process under pid $1 (from /proc: ps may not be installed)
  local c
  for c in $(cat /proc/[0-9]*/stat 2>/dev/null |
             awk -v p="$1" '{ s = $0; sub(/^.*\) /, "", s); split(s, f, " "); if (f[2] == p) print $1 }'); do
    echo "$c"
    descendants "$c"
  done
}
# stop_cmd SIG ID CMD...: starts CMD, waits for it to have children, sends SIG, checks
stop_cmd() {
  local sig=$1 id=$2 kids k alive="" t=0
  shift 2
  "$@" >stop.out 2>stop.err &
  local pid=$!
  kids=""
  while [ $t -lt 100 ] && [ -z "$kids" ]; do sleep 0.1; t=$((t + 1)); kids=$(descendants "$pid"); done
  sleep 2
  kids=$(descendants "$pid")
  kill -s "$sig" "$pid"
  for _ in $(seq 300); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
  if kill -0 "$pid" 2>/dev/null; then
    result "$id" "still running 30 s after SIG$sig"
    kill -KILL "$pid"
    return
  fi
  wait "$pid"
  rc=$?
  for k in $kids; do kill -0 "$k" 2>/dev/null && alive="$alive $k"; done
  if [ -z "$kids" ]; then why="it had started no child"
  elif [ -n "$alive" ]; then why="left running:$alive"; kill -KILL $alive
  elif [ "$rc" != 130 ]; then why="exit status $rc, not 130 ($(tail -c 200 stop.err))"
  else why=$(stop_extra)
  fi
  result "$id" "$why"
}
stop_extra() { # verify: verify.json says 130; every case summary says complete: false or true
  if ! grep -q '"exit_status":[[:space:]]*130' v/verify.json 2>/dev/null; then echo "verify.json lacks exit_status 130"
  elif ! grep -l '"complete":[[:space:]]*false' v/*/summary.json >/dev/null 2>&1; then echo "no stopped case says complete: false"
  fi
}
stop_cmd TERM stop-verify-sigterm "$delam" verify --quick --jobs 2 --out v
stop_cmd INT stop-verify-rerun-sigint "$delam" verify --quick --jobs 2 --out v
# a second sweep (here --merge) into a folder a sweep is writing: refused, pid named
"$delam" verify --quick --jobs 2 --out v >/dev/null 2>&1 &
pid=$!
for _ in $(seq 100); do [ -n "$(descendants "$pid")" ] && break; sleep 0.1; done
timeout 60 "$delam" verify --merge v >/dev/null 2>err.txt
rc=$?
result writer-verify-refused "$(expect 2 "v: another delam process \\(pid $pid\\) is writing this folder")"
kill -TERM "$pid"
wait "$pid"
# the same for two reports into one --out
"$delam" report --out rep2/out --cache rep2/cache --scenes "$src/data/scenes" --gp "$src/reports" >/dev/null 2>&1 &
pid=$!
for _ in $(seq 100); do [ -n "$(descendants "$pid")" ] && break; sleep 0.1; done
timeout 60 "$delam" report --out rep2/out --cache rep2/other --scenes "$src/data/scenes" --gp "$src/reports" \
  >/dev/null 2>err.txt
rc=$?
result writer-report-refused "$(expect 2 "rep2/out: another delam process \\(pid $pid\\) is writing this folder")"
kill -TERM "$pid"
wait "$pid"
stop_cmd HUP stop-verify-sighup "$delam" verify --quick --jobs 2 --out v
# SIGKILL cannot be caught: the cases get SIGTERM from the system as their parent dies
"$delam" verify --quick --jobs 2 --out v >/dev/null 2>&1 &
pid=$!
kids=""
for _ in $(seq 100); do kids=$(descendants "$pid"); [ -n "$kids" ] && break; sleep 0.1; done
sleep 2
kids=$(descendants "$pid")
kill -KILL "$pid"
wait "$pid" 2>/dev/null
alive=""
for _ in $(seq 300); do
  alive=""
  for k in $kids; do kill -0 "$k" 2>/dev/null && alive="$alive $k"; done
  [ -z "$alive" ] && break
  sleep 0.1
done
why=""
if [ -z "$kids" ]; then why="it had started no child"
elif [ -n "$alive" ]; then why="left running 30 s after:$alive"; kill -KILL $alive
elif ! grep -l '"complete":[[:space:]]*false' v/*/summary.json >/dev/null 2>&1; then why="no case stopped cleanly"
fi
result stop-verify-sigkill "$why"
stop_extra() { grep -q 'REPORT.md and index.html not written' stop.err || echo "no word of what was not written"; }
stop_cmd TERM stop-report-sigterm "$delam" report --out rep/out --cache rep/cache --scenes "$src/data/scenes" --gp "$src/reports"

echo "1..$n"
[ "$fail" = 0 ]
