#!/usr/bin/env bash
# check_seeded.sh DELAM SRC - a seeded defect turns `delam verify` red (docs/verification.md,
# "A seeded defect"): six cheap cases of the --full list (fig6 at h 8 with 1 and 4 ppc,
# iface90 at h 8 explicit and static, fig7 at h 8, the DCB at h 4), run as `--list` prints
# them and once more with the law's U0 1.05 times the scene's (--set decohesion.U0 on each
# line: the kernel dissipates 1.05 U0 while verify's references are built from the list's
# scenes), each set judged by `delam verify --merge`:
#   clean      the cases as listed: exit 0, no check fails;
#   seeded     U0 x 1.05: exit 1, and these checks fail, each against a reference the run
#              did not make: D_final on the five bars (U0 x area, 2 %), W_ext_final on the
#              explicit 90-deg bars (UF x area, 3 %), curve_wave on iface90 (the exact
#              solution at the grip speed), curve_path on the static run, branch on the DCB
#              (the LEFM branch of data/fe).
# Prints TAP; exits 1 if a check failed.
set -u
delam=${1:?usage: check_seeded.sh path/to/delam SRC}
src=${2:?usage: check_seeded.sh path/to/delam SRC}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/delam-seed.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
n=0 fail=0
result() {
  n=$((n + 1))
  if [ -z "$2" ]; then echo "ok $n - $1"; else fail=$((fail + 1)); echo "not ok $n - $1: $2"; fi
}
cd "$src"
"$delam" verify --full --list --out "$tmp/clean" >"$tmp/list.txt" 2>"$tmp/list.err" ||
  { echo "Bail out! verify --full --list: $(head -1 "$tmp/list.err")"; exit 1; }
ids="fig6-h8-ppc1 fig6-h8-ppc4 iface90-h8-ppc1 iface90-h8-ppc4-static fig7-h8-ppc1 dcb-h4-ppc4"
: >"$tmp/sub.txt"
for id in $ids; do
  grep -E "/$id\$" "$tmp/list.txt" >>"$tmp/sub.txt" || { echo "Bail out! $id is not in the --full list"; exit 1; }
done
# the scenes' U0 (0.375 in every file the subset runs) times 1.05
u0=$(awk -F'[=;]' '/^U0[[:space:]]*=/ {gsub(/[[:space:]]/, "", $2); print $2; exit}' data/scenes/fig6.ini)
seed=$(awk -v u="$u0" 'BEGIN {printf "%.17g", 1.05 * u}')
sed "s#$tmp/clean/#$tmp/seeded/#; s#\$# --set decohesion.U0=$seed#" "$tmp/sub.txt" >"$tmp/seeded.txt"
sh "$tmp/sub.txt" >/dev/null 2>&1
sh "$tmp/seeded.txt" >/dev/null 2>&1
"$delam" verify --merge "$tmp/clean" >"$tmp/clean.out" 2>&1
rc=$?
why=""
[ "$rc" = 0 ] || why="exit $rc, want 0; $(grep -E '^FAIL' "$tmp/clean.out" | cut -c1-120 | head -3 | tr '\n' ';')"
result clean "$why"
"$delam" verify --merge "$tmp/seeded" >"$tmp/seeded.out" 2>&1
rc=$?
why=""
[ "$rc" = 1 ] || why="exit $rc, want 1 (a failed check)"
for want in "fig6-h8-ppc1 D_final" "fig6-h8-ppc4 D_final" "iface90-h8-ppc1 D_final" "iface90-h8-ppc4-static D_final" \
  "fig7-h8-ppc1 D_final" "fig6-h8-ppc1 W_ext_final" "fig6-h8-ppc4 W_ext_final" "iface90-h8-ppc1 W_ext_final" \
  "iface90-h8-ppc1 curve_wave" "iface90-h8-ppc4-static curve_path" "dcb-h4-ppc4 branch"; do
  grep -qE "^FAIL +$want:" "$tmp/seeded.out" || why="$why; $want not failed"
done
result seeded "${why#; }"
echo "1..$n"
[ "$fail" = 0 ]
