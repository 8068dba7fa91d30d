"""check_vtk.py DIR... - every VTK file of delam's run folders read back with VTK's own
XML reader (python3-vtk9), against the CSV file beside it (docs/output-formats.md).

For each folder, one TAP line per check, its id `<folder>-<check>`:
  files       no legacy .vtk is written; each <stem>.csv of particles or line has its
              <stem>.vtp and the other way round;
  particles   each particle .vtp reads without a VTK error as vtkPolyData with one vertex
              per CSV row, the points at the CSV's x, y (z 0), the point arrays the CSV's
              columns but x, y plus `displacement` (ux, uy, 0), each equal to its column;
  line        each line .vtp (the interface, the split beams): one 2-point line cell per
              CSV row at xa, ya, xb, yb, cell arrays lambda and state equal to the CSV's;
              with --line there must be one, with --line-y Y too and every end on y = Y;
  pvd         snapshots.pvd (when there are snapshots): a VTK collection whose DataSets
              name only VTK XML files that VTK's type-detecting reader opens as
              vtkPolyData, one timestep per snap-d<delta>.csv at that delta, part 0 the
              particles and part 1 the line exactly where there is a line.
Arguments: [--line | --line-y Y] DIR, repeated (the option for the folder after it).  Exits 1 if a check failed.
"""
import csv
import glob
import os
import sys
import xml.etree.ElementTree as ET

from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkIOXML import vtkXMLGenericDataObjectReader, vtkXMLPolyDataReader

PARTICLE_COLS = ["x0", "y0", "x", "y", "ux", "uy", "lambda", "sxx", "syy", "sxy", "upn", "upt", "sep", "wcoh", "dis"]
LINE_COLS = ["xa", "ya", "xb", "yb", "lambda", "state"]


def read_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(l for l in f if not l.startswith("#")))
    return rows


def close(a, b):
    return abs(a - b) <= 1e-12 * max(1.0, abs(a), abs(b))


def read_vtp(path, generic=False):
    """The file through VTK's reader; (data, errors)."""
    r = vtkXMLGenericDataObjectReader() if generic else vtkXMLPolyDataReader()
    errors = []
    r.AddObserver(vtkCommand.ErrorEvent, lambda obj, ev: errors.append(ev))
    r.SetFileName(path)
    r.Update()
    data = r.GetOutputDataObject(0)
    if data is None or data.GetClassName() != "vtkPolyData":
        errors.append("not vtkPolyData: %s" % (data.GetClassName() if data else None))
    return data, errors


def arrays(attr):
    return {attr.GetArrayName(i): attr.GetArray(i) for i in range(attr.GetNumberOfArrays())}


def check_particles(vtp, csvp):
    """Why the particle file disagrees with its CSV, or ''."""
    data, err = read_vtp(vtp)
    if err:
        return "%s: %s" % (vtp, err[0])
    rows = read_csv(csvp)
    n = len(rows)
    if data.GetNumberOfPoints() != n or data.GetNumberOfVerts() != n or data.GetNumberOfCells() != n:
        return "%s: %d points, %d vertices, the CSV %d rows" % (vtp, data.GetNumberOfPoints(), data.GetNumberOfVerts(), n)
    got = arrays(data.GetPointData())
    want = set(PARTICLE_COLS) - {"x", "y"} | {"displacement"}
    if set(got) != want:
        return "%s: point arrays %s, want %s" % (vtp, sorted(got), sorted(want))
    disp = got["displacement"]
    if disp.GetNumberOfComponents() != 3:
        return "%s: displacement has %d components" % (vtp, disp.GetNumberOfComponents())
    for k, row in enumerate(rows):
        p = data.GetPoint(k)
        if not (close(p[0], float(row["x"])) and close(p[1], float(row["y"])) and p[2] == 0.0):
            return "%s: point %d at %s, the CSV's at %s, %s" % (vtp, k, p, row["x"], row["y"])
        d = disp.GetTuple3(k)
        if not (close(d[0], float(row["ux"])) and close(d[1], float(row["uy"])) and d[2] == 0.0):
            return "%s: displacement %d %s, the CSV's %s, %s" % (vtp, k, d, row["ux"], row["uy"])
        for c in want - {"displacement"}:
            if not close(got[c].GetTuple1(k), float(row[c])):
                return "%s: %s[%d] %r, the CSV's %s" % (vtp, c, k, got[c].GetTuple1(k), row[c])
    return ""


def check_line(vtp, csvp, line_y):
    """Why the line file disagrees with its CSV (or y = line_y), or ''."""
    data, err = read_vtp(vtp)
    if err:
        return "%s: %s" % (vtp, err[0])
    rows = read_csv(csvp)
    m = len(rows)
    if m == 0 or data.GetNumberOfLines() != m or data.GetNumberOfCells() != m or data.GetNumberOfPoints() != 2 * m:
        return "%s: %d lines, %d points, the CSV %d rows" % (vtp, data.GetNumberOfLines(), data.GetNumberOfPoints(), m)
    got = arrays(data.GetCellData())
    if set(got) != {"lambda", "state"}:
        return "%s: cell arrays %s, want lambda, state" % (vtp, sorted(got))
    for k, row in enumerate(rows):
        cell = data.GetCell(k)
        if cell.GetNumberOfPoints() != 2:
            return "%s: cell %d has %d points" % (vtp, k, cell.GetNumberOfPoints())
        a, b = data.GetPoint(cell.GetPointId(0)), data.GetPoint(cell.GetPointId(1))
        want = [float(row[c]) for c in ("xa", "ya", "xb", "yb")]
        if not all(close(u, v) for u, v in zip((a[0], a[1], b[0], b[1]), want)):
            return "%s: cell %d from %s to %s, the CSV's %s" % (vtp, k, a, b, want)
        if line_y is not None and not (close(a[1], line_y) and close(b[1], line_y)):
            return "%s: cell %d from %s to %s, not on y = %g" % (vtp, k, a, b, line_y)
        for c in ("lambda", "state"):
            if not close(got[c].GetTuple1(k), float(row[c])):
                return "%s: %s[%d] %r, the CSV's %s" % (vtp, c, k, got[c].GetTuple1(k), row[c])
    return ""


def check_pvd(d):
    """Why snapshots.pvd does not describe the folder's snapshots, or ''."""
    snaps = sorted(glob.glob(os.path.join(d, "snap-d*.csv")))
    deltas = sorted({os.path.basename(s)[6:].split("-")[0].replace(".csv", "") for s in snaps})
    pvd = os.path.join(d, "snapshots.pvd")
    if not deltas:
        return "a snapshots.pvd without snapshots" if os.path.exists(pvd) else ""
    try:
        root = ET.parse(pvd).getroot()
    except (OSError, ET.ParseError) as e:
        return "%s: %s" % (pvd, e)
    if root.tag != "VTKFile" or root.get("type") != "Collection":
        return "%s: not a VTK collection" % pvd
    seen = {}
    for ds in root.iter("DataSet"):
        f = ds.get("file", "")
        if not f.endswith(".vtp"):  # ParaView's collection reader picks its reader by the extension
            return "%s: DataSet file %s is not VTK XML PolyData" % (pvd, f)
        _, err = read_vtp(os.path.join(d, f), generic=True)
        if err:
            return "%s: %s: %s" % (pvd, f, err[0])
        seen[(float(ds.get("timestep")), ds.get("part"))] = f
    want = {}
    for s in deltas:
        want[(float(s), "0")] = "snap-d%s.vtp" % s
        if os.path.exists(os.path.join(d, "snap-d%s-line.csv" % s)):
            want[(float(s), "1")] = "snap-d%s-line.vtp" % s
    if seen != want:
        return "%s: DataSets %s, want %s" % (pvd, sorted(seen.items()), sorted(want.items()))
    return ""


def check_files(d):
    """Why the folder's VTK files do not pair with its CSV files, or ''."""
    legacy = glob.glob(os.path.join(d, "*.vtk"))
    if legacy:
        return "legacy VTK written: %s" % " ".join(sorted(legacy))
    stems = lambda ext: {os.path.basename(p)[: -len(ext)] for p in glob.glob(os.path.join(d, "*" + ext))}
    csvs = {s for s in stems(".csv") if s.startswith("snap-d") or s.startswith("final")}
    vtps = stems(".vtp")
    if csvs != vtps or not vtps:
        return "CSV without .vtp: %s; .vtp without CSV: %s" % (sorted(csvs - vtps) or "none", sorted(vtps - csvs) or "none")
    return ""


def main(argv):
    n = fail = 0
    line_y, want_line = None, False

    def result(cid, why):
        nonlocal n, fail
        n += 1
        if why:
            fail += 1
            print("not ok %d - %s: %s" % (n, cid, why))
        else:
            print("ok %d - %s" % (n, cid))

    i = 0
    while i < len(argv):
        if argv[i] == "--line":
            want_line = True
            i += 1
            continue
        if argv[i] == "--line-y":
            line_y, want_line = float(argv[i + 1]), True
            i += 2
            continue
        d = argv[i]
        name = os.path.basename(os.path.normpath(d))
        i += 1
        result(name + "-files", check_files(d))
        why, lines = "", 0
        for vtp in sorted(glob.glob(os.path.join(d, "*.vtp"))):
            csvp = vtp[:-4] + ".csv"
            if vtp.endswith("-line.vtp"):
                lines += 1
                why = why or check_line(vtp, csvp, line_y)
        result(name + "-line", why if lines or not want_line else "no line file, want one")
        why = ""
        for vtp in sorted(glob.glob(os.path.join(d, "*.vtp"))):
            if not vtp.endswith("-line.vtp"):
                why = why or check_particles(vtp, vtp[:-4] + ".csv")
        result(name + "-particles", why)
        result(name + "-pvd", check_pvd(d))
        line_y, want_line = None, False
    print("1..%d" % n)
    return 1 if fail else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
