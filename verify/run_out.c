/*
 * run_out.c - the files of one run (run.c): load.csv and energy.csv, the particle
 * snapshots as CSV and VTK XML PolyData (.vtp), and the line's pieces, each written under
 * a temporary name and renamed into place when complete (docs/output-formats.md).
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io.h"
#include "run_out.h"
#include "summary.h"

FILE *ver_run_open_tmp(const char *dir, const char *name, char *tmp, size_t len, char *bad)
{
  char path[1100];
  snprintf(path, sizeof path, "%s/%s", dir, name);
  FILE *f = ver_io_open_tmp(path, tmp, len);
  if (!f) {
    const int e = errno;
    snprintf(bad, VER_RUN_BAD, "%s: cannot write: %s", path, strerror(e));
    errno = e;
  }
  return f;
}

int ver_run_commit(FILE *f, const char *tmp, char *bad)
{
  if (ver_io_commit(f, tmp) == 0)
    return 0;
  const int e = errno;
  char path[1100] = "";
  ver_io_tmp_final(tmp, path, sizeof path);
  snprintf(bad, VER_RUN_BAD, "%s: cannot write: %s", path, strerror(e));
  errno = e;
  return -1;
}

/* VTK XML (ParaView's .pvd reads only these; docs/output-formats.md): the file's
 * opening up to the Piece, whose counts the caller gives. */
static void vtp_head(FILE *f, const char *what, int schema, const char *stem, double t, size_t npts, size_t nverts,
                     size_t nlines)
{
  fprintf(f, "<?xml version=\"1.0\"?>\n<!-- delam %s schema %d %s t=%.9g -->\n"
          "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
          "<PolyData>\n<Piece NumberOfPoints=\"%zu\" NumberOfVerts=\"%zu\" NumberOfLines=\"%zu\" "
          "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n", what, schema, stem, t, npts, nverts, nlines);
}

/* A cell block (Verts or Lines) of n cells of k consecutive points each. */
static void vtp_cells(FILE *f, const char *block, size_t n, size_t k)
{
  fprintf(f, "<%s>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n", block);
  for (size_t i = 0; i < n * k; i++)
    fprintf(f, "%zu\n", i);
  fprintf(f, "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
  for (size_t i = 1; i <= n; i++)
    fprintf(f, "%zu\n", i * k);
  fprintf(f, "</DataArray>\n</%s>\n", block);
}

/* The line's pieces (xa ya xb yb lambda state, m of them) as <stem>-line.vtp: one line
 * cell per piece, lambda and state as cell data, in reference coordinates. */
static int write_line_vtp(const mpm_sim *s, const double *xy, int m, const char *dir, const char *stem, char *bad)
{
  char tmp[1100], name[128];
  snprintf(name, sizeof name, "%s-line.vtp", stem);
  FILE *f = ver_run_open_tmp(dir, name, tmp, sizeof tmp, bad);
  if (!f)
    return -1;
  mpm_sim_info in;
  mpm_sim_info_get(s, &in);
  vtp_head(f, "line.vtp", VER_SCHEMA_LINE, stem, in.t, 2 * (size_t)m, 0, (size_t)m);
  fputs("<CellData Scalars=\"lambda\">\n<DataArray type=\"Float64\" Name=\"lambda\" format=\"ascii\">\n", f);
  for (int i = 0; i < m; i++)
    fprintf(f, "%.9g\n", xy[6 * i + 4]);
  fputs("</DataArray>\n<DataArray type=\"Int32\" Name=\"state\" format=\"ascii\">\n", f);
  for (int i = 0; i < m; i++)
    fprintf(f, "%d\n", (int)xy[6 * i + 5]);
  fputs("</DataArray>\n</CellData>\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n", f);
  for (int i = 0; i < m; i++)
    fprintf(f, "%.9g %.9g 0\n%.9g %.9g 0\n", xy[6 * i], xy[6 * i + 1], xy[6 * i + 2], xy[6 * i + 3]);
  fputs("</DataArray>\n</Points>\n", f);
  vtp_cells(f, "Lines", (size_t)m, 2);
  fputs("</Piece>\n</PolyData>\n</VTKFile>\n", f);
  return ver_run_commit(f, tmp, bad);
}

/* decohesion.path = interface (and the split beams' line): the line's pieces with their
 * segment's lambda and state, <stem>-line.csv and .vtp (docs/output-formats.md);
 * nothing where there is no line. */
static int write_line(const mpm_sim *s, const char *dir, const char *stem, char *bad)
{
  const int n = mpm_iface_pieces(s);
  if (n == 0)
    return 0;
  char tmp[1100], name[128];
  snprintf(name, sizeof name, "%s-line.csv", stem);
  FILE *f = ver_run_open_tmp(dir, name, tmp, sizeof tmp, bad);
  if (!f)
    return -1;
  fprintf(f, "# delam line.csv schema %d\nxa,ya,xb,yb,lambda,state\n", VER_SCHEMA_LINE);
  double *xy = malloc((size_t)n * 6 * sizeof *xy); /* xa ya xb yb lambda state, per written piece */
  int m = 0;
  for (int i = 0; i < n; i++) {
    double q[4], lam;
    int st;
    if (mpm_iface_piece(s, i, q, &lam, &st)) {
      fprintf(f, "%.9g,%.9g,%.9g,%.9g,%.9g,%d\n", q[0], q[1], q[2], q[3], lam, st);
      if (xy) {
        memcpy(xy + 6 * m, q, sizeof q);
        xy[6 * m + 4] = lam;
        xy[6 * m + 5] = st;
        m++;
      }
    }
  }
  /* no memory for the VTK copy: the CSV is written, the .vtp left out */
  const int rc = ver_run_commit(f, tmp, bad) ? -1 : xy ? write_line_vtp(s, xy, m, dir, stem, bad) : 0;
  free(xy);
  return rc;
}

/* The particle columns of <stem>.csv after x, y (which are the points of the .vtp). */
enum { P_X0, P_Y0, P_UX, P_UY, P_LAM, P_SXX, P_SYY, P_SXY, P_UPN, P_UPT, P_SEP, P_WCOH, P_DIS, P_NCOL };
static const char *const pcol_name[P_NCOL] = {"x0",  "y0",  "ux",  "uy",  "lambda", "sxx", "syy",
                                              "sxy", "upn", "upt", "sep", "wcoh",   "dis"};

static double pcol(const mpm_particle_view *p, size_t k, int c)
{
  switch (c) {
  case P_X0: return p->x0[k];
  case P_Y0: return p->y0[k];
  case P_UX: return p->x[k] - p->x0[k];
  case P_UY: return p->y[k] - p->y0[k];
  case P_LAM: return p->lam[k];
  case P_SXX: return p->sxx[k];
  case P_SYY: return p->syy[k];
  case P_SXY: return p->sxy[k];
  case P_UPN: return p->upn[k];
  case P_UPT: return p->upt[k];
  case P_SEP: return p->sep[k];
  case P_WCOH: return p->wcoh[k];
  default: return p->dis[k];
  }
}

/* <stem>.vtp: the bar's particles (not the head's) at their current positions, one
 * vertex each; point data: the displacement as a 3-vector (Warp By Vector) and every
 * column of <stem>.csv but x, y under its CSV name. */
static int write_particles_vtp(const mpm_particle_view *p, double t, const char *dir, const char *stem, char *bad)
{
  char tmp[1100], name[128];
  snprintf(name, sizeof name, "%s.vtp", stem);
  FILE *f = ver_run_open_tmp(dir, name, tmp, sizeof tmp, bad);
  if (!f)
    return -1;
  const size_t nb = p->n - p->nhead; /* the bar's particles; the head is the machine */
  vtp_head(f, "particles.vtp", VER_SCHEMA_PARTICLES, stem, t, nb, nb, 0);
  fputs("<PointData Scalars=\"lambda\" Vectors=\"displacement\">\n"
        "<DataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\" format=\"ascii\">\n", f);
  for (size_t k = 0; k < p->n; k++)
    if (p->mat[k] != MPM_MAT_HEAD)
      fprintf(f, "%.9g %.9g 0\n", p->x[k] - p->x0[k], p->y[k] - p->y0[k]);
  fputs("</DataArray>\n", f);
  for (int c = 0; c < P_NCOL; c++) {
    fprintf(f, "<DataArray type=\"%s\" Name=\"%s\" format=\"ascii\">\n", c == P_SEP ? "Int32" : "Float64",
            pcol_name[c]);
    for (size_t k = 0; k < p->n; k++)
      if (p->mat[k] != MPM_MAT_HEAD)
        fprintf(f, "%.9g\n", pcol(p, k, c));
    fputs("</DataArray>\n", f);
  }
  fputs("</PointData>\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n", f);
  for (size_t k = 0; k < p->n; k++)
    if (p->mat[k] != MPM_MAT_HEAD)
      fprintf(f, "%.9g %.9g 0\n", p->x[k], p->y[k]);
  fputs("</DataArray>\n</Points>\n", f);
  vtp_cells(f, "Verts", nb, 1);
  fputs("</Piece>\n</PolyData>\n</VTKFile>\n", f);
  return ver_run_commit(f, tmp, bad);
}

int ver_run_write_snapshot(const mpm_sim *s, const char *dir, const char *stem, char *bad)
{
  mpm_particle_view v;
  mpm_sim_particles(s, &v);
  const mpm_particle_view *p = &v;
  mpm_sim_info in;
  mpm_sim_info_get(s, &in);
  char tmp[1100], name[128];
  snprintf(name, sizeof name, "%s.csv", stem);
  FILE *f = ver_run_open_tmp(dir, name, tmp, sizeof tmp, bad);
  if (!f)
    return -1;
  fprintf(f, "# delam particles.csv schema %d\nx0,y0,x,y,ux,uy,lambda,sxx,syy,sxy,upn,upt,sep,wcoh,dis\n",
          VER_SCHEMA_PARTICLES);
  for (size_t k = 0; k < p->n; k++)
    if (p->mat[k] != MPM_MAT_HEAD)
      fprintf(f, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%d,%.9g,%.9g\n", p->x0[k], p->y0[k],
            p->x[k], p->y[k], p->x[k] - p->x0[k], p->y[k] - p->y0[k], p->lam[k], p->sxx[k], p->syy[k],
            p->sxy[k], p->upn[k], p->upt[k], p->sep[k], p->wcoh[k], p->dis[k]);
  if (ver_run_commit(f, tmp, bad) || write_particles_vtp(p, in.t, dir, stem, bad))
    return -1;
  return write_line(s, dir, stem, bad);
}

int ver_run_write_rows(const ver_run_row *r, long n, const char *dir, char *bad)
{
  char tmp[1100];
  FILE *f = ver_run_open_tmp(dir, "load.csv", tmp, sizeof tmp, bad);
  if (!f)
    return -1;
  /* crack_tip, zone_end: the specimens with a pre-crack (docs/specimens.md); det_sign:
   * the static solver's, last (docs/static.md, "Stability") */
  const int tip = n > 0 && isfinite(r[0].tip), det = n > 0 && isfinite(r[0].det);
  fprintf(f, "# delam load.csv schema %d\nt,delta,P_grip,P_fixed%s%s\n", VER_SCHEMA_LOAD, tip ? ",crack_tip,zone_end" : "",
          det ? ",det_sign" : "");
  for (long i = 0; i < n; i++) {
    fprintf(f, "%.9g,%.9g,%.9g,%.9g", r[i].t, r[i].delta, r[i].Pg, r[i].Pf);
    if (tip)
      fprintf(f, ",%.9g,%.9g", r[i].tip, r[i].zone);
    if (det)
      fprintf(f, ",%.0f", r[i].det);
    fputc('\n', f);
  }
  if (ver_run_commit(f, tmp, bad))
    return -1;
  if (!(f = ver_run_open_tmp(dir, "energy.csv", tmp, sizeof tmp, bad)))
    return -1;
  /* the ledger's booked terms after the energies (mpm.h mpm_energy, mpm_step.c "Energy") */
  fprintf(f, "# delam energy.csv schema %d\nt,W_ext,KE,SE,W_coh,D,L_bc,L_flip,L_scheme,W_head,L_contact,L_debris,L_damp\n",
          VER_SCHEMA_ENERGY);
  for (long i = 0; i < n; i++)
    fprintf(f, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", r[i].t, r[i].e.W_ext, r[i].e.KE,
            r[i].e.SE, r[i].e.W_coh, r[i].e.D, r[i].e.L_bc, r[i].e.L_flip, r[i].e.L_scheme, r[i].e.W_head,
            r[i].e.L_contact, r[i].e.L_debris, r[i].e.L_damp);
  return ver_run_commit(f, tmp, bad);
}

