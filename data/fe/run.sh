#!/bin/sh
# Reruns the FreeFEM reference scripts of this directory and rewrites their .dat files.
#   data/fe/run.sh              every job below
#   data/fe/run.sh dcb els      only the jobs of the scripts named (held_bar, dcb, els, full_check)
# Needs FreeFEM (Debian: apt-get install freefem++, or make fe-data from the top);
# make check does not: the tests read the stored .dat files.
set -eu
cd "$(dirname "$0")"
FF=$(command -v FreeFem++-nw || command -v FreeFem++ || true)
if [ -z "$FF" ]; then
  echo "run.sh: FreeFEM not found (Debian: apt-get install freefem++)" >&2
  exit 1
fi
# script, output, options
JOBS="held_bar held_bar.dat
dcb dcb.dat -H 32 -nu 0.25 -a0 32 -a1 176
dcb dcb_nu045.dat -H 32 -nu 0.45 -a0 32 -a1 176
dcb dcb_H24.dat -H 24 -nu 0.25
dcb dcb_H24_nu045.dat -H 24 -nu 0.45
dcb dcb_H48.dat -H 48 -nu 0.25
dcb dcb_H48_nu045.dat -H 48 -nu 0.45
els els.dat -H 32 -nu 0.25 -a0 32 -a1 176
els els_nu045.dat -H 32 -nu 0.45 -a0 32 -a1 176
els els_H24.dat -H 24 -nu 0.25
els els_H24_nu045.dat -H 24 -nu 0.45
els els_H48.dat -H 48 -nu 0.25
els els_H48_nu045.dat -H 48 -nu 0.45
full_check full_check.dat -h0 1"
echo "$JOBS" | while read -r s out opts; do
  if [ $# -gt 0 ]; then
    want=0; for w in "$@"; do [ "${w%.edp}" = "$s" ] && want=1; done
    [ $want = 1 ] || continue
  fi
  log=${out%.dat}.log
  start=$(date +%s)
  # FreeFEM's exit status is not always set after an error: look at the log as well.
  # shellcheck disable=SC2086
  if ! "$FF" -nw -v 0 "$s.edp" $opts -out "$out" > "$log" 2>&1 || grep -qiE "error|exception" "$log"; then
    echo "run.sh: $s.edp $opts failed, see data/fe/$log" >&2
    exit 1
  fi
  echo "run.sh: $out done in $(( $(date +%s) - start )) s"
done
