#!/usr/bin/env bash
# check_angles.sh DELAM SRC - `delam verify --angles` (the files' method on
# bands and modes they were not written for): its case list, read from `--list`, must be
# every inclined bar scene file of data/scenes (alpha not 90, read here from the files
# themselves; the split beams are not the bar) at alpha 30, 45, 60 and 75 less its own, and at all four with its snf and
# stf exchanged (the other mode), each at h 4 and 2 and ppc 1 and 4, and nothing else; a
# merge of a folder that holds none of those cases must fail (a lost case cannot pass).
# Prints TAP; exits 1 if a check failed.
set -u
delam=${1:?usage: check_angles.sh path/to/delam SRC}
src=${2:?usage: check_angles.sh path/to/delam SRC}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/delam-ang.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
n=0 fail=0
result() {
  n=$((n + 1))
  if [ -z "$2" ]; then echo "ok $n - $1"; else fail=$((fail + 1)); echo "not ok $n - $1: $2"; fi
}
cd "$src"
# what the list must be, from the scene files: "scene alpha h ppc snf stf" per case
# ("-" for a traction the case leaves as the file has it)
: >"$tmp/want"
for f in data/scenes/*.ini; do
  s=$(basename "$f" .ini)
  a=$(sed -n 's/^alpha *= *\([0-9.]*\).*/\1/p' "$f" | head -1)
  sn=$(sed -n 's/^snf *= *\([0-9.]*\).*/\1/p' "$f" | head -1)
  st=$(sed -n 's/^stf *= *\([0-9.]*\).*/\1/p' "$f" | head -1)
  grep -q '^mode *=' "$f" && continue                   # the free-vibration scene
  grep -q '^type *= *\(dcb\|els\)' "$f" && continue     # a split beam, not the bar
  [ -z "$a" ] || [ "$a" = 90 ] && continue              # the grid's own direction
  for b in 30 45 60 75; do
    for h in 4 2; do for p in 1 4; do
      [ "$b" = "$a" ] || echo "$s $b $h $p - -" >>"$tmp/want"
      echo "$s $b $h $p $st $sn" >>"$tmp/want"       # the other mode: the two exchanged
    done; done
  done
done
"$delam" verify --angles --list --out "$tmp/v" >"$tmp/jobs.txt" 2>"$tmp/list.err"
result list-exit "$([ $? = 0 ] || cat "$tmp/list.err")"
# what it is: the scene, the alpha override, --h and --ppc of each line
sed -n 's#.*/\([a-z0-9_]*\)\.ini --h \([0-9.]*\) --ppc \([0-9]*\) .*decohesion\.alpha=\([0-9.]*\).*#\1 \4 \2 \3#p' \
  "$tmp/jobs.txt" >"$tmp/got.base"
sed 's#.*decohesion\.snf=\([0-9.]*\) --set decohesion\.stf=\([0-9.]*\) .*#\1 \2#; t; s#.*#- -#' \
  "$tmp/jobs.txt" >"$tmp/got.modes"
paste -d ' ' "$tmp/got.base" "$tmp/got.modes" >"$tmp/got"
result every-line-sets-alpha "$([ "$(wc -l <"$tmp/got.base")" = "$(wc -l <"$tmp/jobs.txt")" ] ||
  echo "$(wc -l <"$tmp/jobs.txt") lines, $(wc -l <"$tmp/got.base") with decohesion.alpha")"
sort "$tmp/want" >"$tmp/want.s"
sort "$tmp/got" >"$tmp/got.s"
result list-is-the-rule "$(diff "$tmp/want.s" "$tmp/got.s" | head -5 | tr '\n' ' ')"
result list-not-empty "$([ -s "$tmp/want.s" ] || echo 'no inclined scene file found')"
mkdir -p "$tmp/empty"
"$delam" verify --angles --merge "$tmp/empty" >"$tmp/merge.log" 2>&1
rc=$?
result merge-of-nothing-fails "$([ $rc = 1 ] || echo "exit $rc, want 1")"
result merge-mode "$(grep -q '"mode":[[:space:]]*"angles"' "$tmp/empty/verify.json" 2>/dev/null || echo 'verify.json has no mode angles')"
echo "1..$n"
[ $fail = 0 ]
