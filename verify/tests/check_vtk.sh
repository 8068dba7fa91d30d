#!/usr/bin/env bash
# check_vtk.sh DELAM SRC - the VTK files a run writes, read back with VTK's own XML reader
# (Debian's python3-vtk9) against the CSV files beside them (check_vtk.py says what each
# check is), on three folders:
#   fig6-h8      the bar at h 8 with the scene's snapshots: particles only;
#   iface90-h8   the cohesive interface with snapshots: a .pvd of two parts, the
#                particles and the crack line;
#   dcb-h8       the split beam with snapshots: its line along y = 16.
# Skips (TAP plan 1..0) with the reason when no python3 has the vtk module.
# Prints TAP; exits 1 if a check failed.
set -u
delam=${1:?usage: check_vtk.sh path/to/delam SRC}
src=${2:?usage: check_vtk.sh path/to/delam SRC}
py=""
for p in python3 /usr/bin/python3; do # pyenv and venvs shadow Debian's python3
  if command -v "$p" >/dev/null && "$p" -c 'import vtkmodules.vtkIOXML' 2>/dev/null; then py=$p; break; fi
done
if [ -z "$py" ]; then
  echo "1..0 # SKIP no python3 with VTK's module vtkmodules (Debian: apt-get install python3-vtk9, or make deps)"
  exit 0
fi
tmp=$(mktemp -d "${TMPDIR:-/tmp}/delam-vtk.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
export DELAM_SCENES="$src/data/scenes"
for run in "fig6-h8 fig6" "iface90-h8 iface90 --set output.snapshots=0.1,0.3,0.45" \
  "dcb-h8 dcb --set output.snapshots=2,8"; do
  set -- $run
  out=$1
  shift
  "$delam" run "$@" --h 8 --threads 1 --quiet --out "$out" >/dev/null 2>"$out.err"
  rc=$?
  if [ "$rc" != 0 ]; then
    echo "not ok 1 - $out-run: delam run $* exited $rc: $(head -1 "$out.err")"
    echo "1..1"
    exit 1
  fi
done
"$py" "$src/verify/tests/check_vtk.py" fig6-h8 --line iface90-h8 --line-y 16 dcb-h8
