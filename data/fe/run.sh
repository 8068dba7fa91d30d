#!/bin/sh
# Reruns the FreeFEM reference scripts of this directory and rewrites their .dat files.
#   data/fe/run.sh              all of them
#   data/fe/run.sh dcb.edp      only the ones named
# Needs FreeFEM (Debian: apt-get install freefem++, or make fe-data from the top);
# make check does not: the tests read the stored .dat files.
set -eu
cd "$(dirname "$0")"
FF=$(command -v FreeFem++-nw || command -v FreeFem++ || true)
if [ -z "$FF" ]; then
  echo "run.sh: FreeFEM not found (Debian: apt-get install freefem++)" >&2
  exit 1
fi
[ $# -gt 0 ] || set -- held_bar.edp dcb.edp els.edp
for s in "$@"; do
  [ -f "$s" ] || { echo "run.sh: no $s here" >&2; exit 1; }
  log=${s%.edp}.log
  start=$(date +%s)
  # FreeFEM's own exit status is unreliable after a caught error: look for the output too.
  if ! "$FF" -nw -v 0 "$s" > "$log" 2>&1 || grep -q "rror" "$log"; then
    echo "run.sh: $s failed, see data/fe/$log" >&2
    exit 1
  fi
  echo "run.sh: $s done in $(( $(date +%s) - start )) s (log data/fe/$log)"
done
