#!/usr/bin/env bash
# check_faults.sh DELAM SRC - faults that must end in a clear error, never in a hang or
# in a verdict that says something false:
#   fifo-*       a FIFO (or a device) as the scene file or as a `delam check` input is
#                refused at once with exit 2 and a message naming it, within 5 s.
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
echo "1..$n"
[ "$fail" = 0 ]
