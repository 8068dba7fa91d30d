#!/usr/bin/env bash
# check_bad.sh DELAM - every bad scene in data/bad/ and every bad option of
# `delam run` must be refused where it enters: exit status 2, exactly one line on
# stderr holding the expected fragment, and no output folder created or touched.
# A scene's expected fragment is its first line:  ; expect: FRAGMENT
# Prints TAP; exits 1 if a check failed.
set -u
delam=${1:?usage: check_bad.sh path/to/delam}
here=$(cd "$(dirname "$0")" && pwd)
scenes=$(cd "$here/../scenes" && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/delam-bad.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
n=0 pass=0 fail=0

# check ID FRAGMENT ARGS...: runs delam run ARGS --out $tmp/out, checks the rules.
check() {
  local id=$1 frag=$2 why=""
  shift 2
  n=$((n + 1))
  rm -rf "$tmp/out"
  "$delam" run "$@" --out "$tmp/out" --quiet >"$tmp/stdout" 2>"$tmp/stderr"
  local rc=$?
  local lines
  lines=$(wc -l <"$tmp/stderr")
  if [ "$rc" != 2 ]; then why="exit status $rc, not 2"
  elif [ "$lines" != 1 ]; then why="$lines lines on stderr, not 1"
  elif ! grep -qF -- "$frag" "$tmp/stderr"; then why="stderr lacks '$frag'"
  elif [ -e "$tmp/out" ]; then why="the output folder was created"
  elif [ -s "$tmp/stdout" ]; then why="something on stdout"
  fi
  if [ -z "$why" ]; then
    pass=$((pass + 1))
    echo "ok $n - $id"
  else
    fail=$((fail + 1))
    echo "not ok $n - $id: $why"
    sed 's/^/#   stderr: /' "$tmp/stderr"
  fi
}

# 1. One bad scene per rule.
for f in "$here"/bad_*.ini; do
  frag=$(sed -n '1s/^; expect: //p' "$f")
  if [ -z "$frag" ]; then
    n=$((n + 1)); fail=$((fail + 1))
    echo "not ok $n - $(basename "$f"): no '; expect: ' first line"
    continue
  fi
  check "scene-$(basename "$f" .ini)" "$frag" "$f"
done

# 2. Bad options of delam run on a good scene.
fig6=$scenes/fig6.ini
check opt-unknown "unknown option '--bogus'" "$fig6" --bogus
check opt-h-word "--h: 'abc' is not a number > 0" "$fig6" --h abc
check opt-h-missing "--h: '--out' is not a number > 0" "$fig6" --h
check opt-h-not-dividing "grid.h: 7 does not divide bar.L = 192" "$fig6" --h 7
check opt-ppc-3 "command line: grid.ppc: 3 is not a perfect square" "$fig6" --ppc 3
check opt-ppc-huge "grid.ppc: 10000 is out of range (a perfect square from 1 to 1024" "$fig6" --ppc 10000
check opt-ppc-fraction "grid.ppc: '2.5' is not an integer" "$fig6" --ppc 2.5
check opt-dt-zero "--dt: '0' is not a number > 0" "$fig6" --dt 0
check opt-dt-cfl "command line: time.dt: 1 is at or above the CFL bound" "$fig6" --dt 1
check opt-until-nan "--until: 'nan' is not a number > 0" "$fig6" --until nan
check opt-threads-word "--threads: 'x' is not a number > 0" "$fig6" --threads x
check opt-set-nokey "'nokey': expected section.key=value" "$fig6" --set nokey
check opt-set-unknown "material.Ex=1: unknown key (allowed in [material]: E, nu, rho)" "$fig6" --set material.Ex=1
check opt-set-section "nosuch.E=1: unknown key (allowed sections: method, specimen, bar," "$fig6" --set nosuch.E=1
check opt-set-range "command line: material.nu: 0.5 is out of range (in (-1, 0.5))" "$fig6" --set material.nu=0.5
check opt-set-junk "command line: material.E: '10x' is not a number" "$fig6" --set material.E=10x
check opt-set-empty "command line: material.E: empty value" "$fig6" --set material.E=
# a scene saved as UTF-16 (its byte-order mark names it, not a line's shape)
{ printf '\xff\xfe'; cat "$fig6"; } >"$tmp/utf16.ini"
check utf16 "utf16.ini:1: the file is UTF-16 text (its byte-order mark FF FE)" "$tmp/utf16.ini"
check opt-set-damping-from "command line: time.damping_from: 'later' is not allowed (start" "$scenes/fig8.ini" --set time.damping_from=later
check opt-set-imp-size "command line: imperfection.size: 'big' is not allowed (particle" "$scenes/fig7.ini" --set imperfection.size=big
check opt-set-damping-limited "time.damping: 1.0472 needs grid.node_mass = lumped" "$scenes/fig8.ini" --set decohesion.path=line --set grid.shape=linear --set time.scheme=usl --set grid.node_mass=limited --set time.damping_beta=0
check opt-set-beta-usl "time.damping_beta: 0.0625 needs time.scheme = musl" "$scenes/fig8.ini" --set time.scheme=usl
check opt-method "command line: method.preset: 'fast' is not allowed (paper (the paper's method), band" "$fig6" --method fast
check opt-method-missing "--method needs a preset (paper, band or interface)" "$fig6" --method
check opt-rule-iface "fig7.ini:5: decohesion.path: interface needs grid.fields = two, grid.shape = gimp, time.scheme = musl" "$scenes/fig7.ini" --set grid.fields=one
check opt-rule-share "command line: decohesion.share: line needs decohesion.path = interface, alpha = 90 and grid.motion = stretch (here: path interface, alpha 60, motion fixed; allowed otherwise: share = stick)" "$scenes/fig7.ini" --set decohesion.share=line
check opt-rule-laid "command line: grid.weights: laid needs grid.motion = stretch (here: motion fixed" "$scenes/fig7.ini" --set grid.weights=laid
check opt-set-newline "a control character" "$fig6" --set "material.E=1
2"
check opt-no-scene "no scene file"
check opt-two-scenes "one scene file only" "$fig6" "$fig6"
check file-missing "nosuch.ini: cannot open: No such file or directory" "$tmp/nosuch.ini"
check file-directory "a directory, not a scene file" "$here"
printf '[bar]\nL = 192\x00\n' >"$tmp/nul.ini"
check file-nul "nul.ini:2: a NUL byte: not a text file" "$tmp/nul.ini"

# 3. An existing output folder is not touched by a refused scene.
n=$((n + 1))
mkdir -p "$tmp/keep"
echo '{"complete": true}' >"$tmp/keep/summary.json"
before=$(ls -l --time-style=+%s.%N "$tmp/keep"; md5sum "$tmp/keep/summary.json")
"$delam" run "$here/bad_E_zero.ini" --out "$tmp/keep" --quiet 2>/dev/null
rc=$?
after=$(ls -l --time-style=+%s.%N "$tmp/keep"; md5sum "$tmp/keep/summary.json")
if [ "$rc" = 2 ] && [ "$before" = "$after" ]; then
  pass=$((pass + 1)); echo "ok $n - existing-out-untouched"
else
  fail=$((fail + 1)); echo "not ok $n - existing-out-untouched: exit $rc, folder changed: $([ "$before" = "$after" ] && echo no || echo yes)"
fi

echo "1..$n"
echo "# $pass passed, $fail failed"
[ "$fail" = 0 ]
