#!/usr/bin/env bash
# check_provenance.sh DELAM - a run can be reproduced from its own folder:
#   version      `delam --version` names the version that summary.json and scene.ini carry;
#   by-name      `delam run fig6` works from an empty folder (no ./data/scenes);
#   scene-ini    the run's scene.ini, run again, gives byte-identical load.csv and energy.csv;
#   case-ids     runs that differ in an override get different default folders, and
#                summary.json lists the overrides and the effective scene;
#   name=value   --h=4 and --h 4 give the same run;
#   formats-doc  every key of summary.json and every column of load.csv, energy.csv and
#                final.csv is described in docs/output-formats.md (given SRC).
# Prints TAP; exits 1 if a check failed.
set -u
delam=${1:?usage: check_provenance.sh path/to/delam [SRC]}
src=${2:-}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/delam-prov.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
n=0 fail=0
result() { # result ID WHY (empty WHY: pass)
  n=$((n + 1))
  if [ -z "$2" ]; then echo "ok $n - $1"; else fail=$((fail + 1)); echo "not ok $n - $1: $2"; fi
}
json() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2]))" "$@"; }
cd "$tmp"

ver=$("$delam" --version | sed -n 's/^delam //p' | head -1)
"$delam" run fig6 --h=4 --until=0.05 --quiet >/dev/null 2>err.txt
d=out/fig6-h4-ppc1-end_delta0.05-stop_margin0
why=""
[ -n "$ver" ] || why="delam --version printed no version"
[ -z "$why" ] && [ ! -f "$d/summary.json" ] && why="no $d/summary.json ($(head -1 err.txt); folders: $(ls out 2>/dev/null))"
[ -z "$why" ] && [ "$(json "$d/summary.json" 'd["version"]')" != "$ver" ] && why="summary.json version is not '$ver'"
[ -z "$why" ] && ! head -1 "$d/scene.ini" | grep -qF "delam $ver" && why="scene.ini's first line does not name delam $ver"
result version "$why"
result by-name "$([ -f "$d/load.csv" ] || echo "delam run fig6 from an empty folder wrote no load.csv")"

why=""
"$delam" run "$d/scene.ini" --quiet --out again >/dev/null 2>err.txt || why="the scene.ini does not run: $(head -1 err.txt)"
for f in load.csv energy.csv; do
  [ -z "$why" ] && ! cmp -s "$d/$f" "again/$f" && why="$f differs when run from scene.ini"
done
result scene-ini "$why"

why=""
"$delam" run fig6 --h 4 --until 0.05 --set material.E=2048 --quiet >/dev/null 2>err.txt
e=out/fig6-h4-ppc1-E2048-end_delta0.05-stop_margin0
[ -d "$e" ] || why="no folder $e ($(ls out))"
[ -z "$why" ] && ls out | grep -q '[=+]' && why="a folder name with '=' or an exponent: $(ls out)"
[ -z "$why" ] && [ "$(ls out | wc -l)" != 2 ] && why="expected 2 case folders, found: $(ls out)"
[ -z "$why" ] && ! json "$e/summary.json" '"material.E=2048" in d["overrides"] and "E = 2048" in d["effective_scene"]' | grep -q True &&
  why="summary.json does not list the override and the effective scene"
[ -z "$why" ] && cmp -s "$d/load.csv" "$e/load.csv" && why="E = 2048 gave the same load.csv as E = 1024"
result case-ids "$why"

"$delam" run fig6 --h 4 --until 0.05 --quiet --out spaced >/dev/null 2>&1
result name=value "$(cmp -s "$d/load.csv" spaced/load.csv || echo "--h=4 and --h 4 differ")"

if [ -n "$src" ]; then
  doc="$src/docs/output-formats.md"
  missing=$(python3 - "$d" "$doc" <<'PY'
import csv, json, re, sys
d, doc = sys.argv[1], open(sys.argv[2]).read()
names = list(json.load(open(d + "/summary.json")))
for f in ("load.csv", "energy.csv", "final.csv"):
    rows = [r for r in csv.reader(open(d + "/" + f)) if r and not r[0].startswith("#")]
    names += rows[0]
print(" ".join(sorted({k for k in names if not re.search(r"(?<![A-Za-z0-9_])" + re.escape(k) + r"(?![A-Za-z0-9_])", doc)})))
PY
)
  result formats-doc "$([ -z "$missing" ] || echo "not in docs/output-formats.md: $missing")"
fi

echo "1..$n"
[ "$fail" = 0 ]
