#!/usr/bin/env bash
# check_parallel.sh DELAM SRC - the sweep split for an outside engine (docs/sweeps.md):
# `delam verify --quick --list` lines run by GNU parallel (as --sshlogin would run them,
# here on the local host ':'), then `delam verify --quick --merge`, give the same
# verify.csv as `delam verify --quick` (less wall times and the children's exit status,
# which a merge does not see; rows in case order) and byte-identical case files. Prints TAP; exits 1 if a check failed.
set -u
delam=${1:?usage: check_parallel.sh path/to/delam SRC}
src=${2:?usage: check_parallel.sh path/to/delam SRC}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/delam-par.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
n=0 fail=0
result() {
  n=$((n + 1))
  if [ -z "$2" ]; then echo "ok $n - $1"; else fail=$((fail + 1)); echo "not ok $n - $1: $2"; fi
}
cd "$src"
if ! command -v parallel >/dev/null; then
  echo "1..0 # SKIP GNU parallel is not installed (make deps installs it)"
  exit 0
fi
"$delam" verify --quick --out "$tmp/direct" >"$tmp/direct.log" 2>&1
rc_direct=$?
"$delam" verify --quick --list --out "$tmp/par" >"$tmp/jobs.txt" 2>"$tmp/list.err"
# one job a line; --sshlogin : is the local host, as a host list would be
parallel --will-cite --sshlogin 2/: --workdir "$src" --halt never <"$tmp/jobs.txt" >"$tmp/par.log" 2>&1
"$delam" verify --quick --merge "$tmp/par" >"$tmp/merge.log" 2>&1
rc_merge=$?
result exit-status "$([ "$rc_direct" = "$rc_merge" ] || echo "verify --quick exit $rc_direct, parallel + merge exit $rc_merge")"

# verify.csv without wall_s and exit_status, rows sorted; and the case folders' results
strip() { grep -v '^#' "$1" | python3 -c '
import csv, sys
rows = list(csv.reader(sys.stdin))
drop = {rows[0].index("wall_s"), rows[0].index("exit_status")}
out = [",".join(x for i, x in enumerate(r) if i not in drop) for r in rows]
print("\n".join(out[:1] + sorted(out[1:])))'; }
why=""
if ! diff <(strip "$tmp/direct/verify.csv") <(strip "$tmp/par/verify.csv") >"$tmp/diff.txt"; then
  why="verify.csv differs: $(head -3 "$tmp/diff.txt" | tr '\n' ' ')"
fi
result verify-csv "$why"
why=""
ncase=0
for d in "$tmp/direct"/*/; do
  c=$(basename "$d")
  ncase=$((ncase + 1))
  for f in load.csv energy.csv final.csv; do
    cmp -s "$d/$f" "$tmp/par/$c/$f" || { why="$c/$f differs"; break 2; }
  done
done
[ -z "$why" ] && [ "$ncase" -lt 2 ] && why="only $ncase case folders"
result case-files "$why"
echo "1..$n"
[ "$fail" = 0 ]
