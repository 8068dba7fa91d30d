#!/bin/sh
# slow_lock.sh - the picture of docs/interface.md, "What the churn is: one segment locks":
# lambda along fig7's line at delta 0.26-0.28 under a sixteenth of the paper's grip speed,
# at h 2 with 1 ppc and the file's step, 1 ppc and half of it, and 4 ppc and the file's.
# Usage: docs/figures/slow_lock.sh [DELAM] [OUTDIR]   (from the source tree; about 3 min)
# Writes OUTDIR/slow_lock.png (default: docs/figures) from runs in a temporary folder.
set -eu
delam=${1:-build/delam}
out=${2:-docs/figures}
[ -x "$delam" ] || { echo "slow_lock.sh: no delam at $delam (build first, or pass its path)" >&2; exit 2; }
[ -f data/scenes/fig7.ini ] || { echo "slow_lock.sh: run from the source tree (data/scenes/fig7.ini)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
run() { # name ppc dt
  echo "slow_lock.sh: fig7 h 2, $2 ppc, dt $3 ..." >&2
  "$delam" run data/scenes/fig7.ini --h 2 --ppc "$2" --dt "$3" --threads 1 --quiet \
    --set loading.speed=0.0000625 --set output.snapshots=0.26,0.27,0.275,0.28 \
    --set run.end_delta=0.285 --out "$tmp/$1" > /dev/null
}
run p1 1 0.025 &
pid=$!
run p1half 1 0.0125
wait "$pid" || { echo "slow_lock.sh: the 1 ppc run failed" >&2; exit 1; }
run p4 4 0.025
mkdir -p "$out"
gnuplot -e "dir='$tmp'; out='$out/slow_lock.png'" "$(dirname "$0")/slow_lock.gp"
echo "slow_lock.sh: -> $out/slow_lock.png" >&2
