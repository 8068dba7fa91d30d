/*
 * run_out.c - the files of one run (run.c): load.csv and energy.csv, the particle
 * snapshots as CSV and legacy VTK, and the interface's line pieces, each written under a
 * temporary name and renamed into place when complete (docs/output-formats.md).
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

/* decohesion.path = interface: the line's pieces with their segment's lambda and state,
 * <stem>-line.csv (docs/output-formats.md); nothing for the other paths. */
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
  if (ver_run_commit(f, tmp, bad)) {
    free(xy);
    return -1;
  }
  /* The same pieces as legacy VTK polydata, one line cell each, for ParaView. */
  snprintf(name, sizeof name, "%s-line.vtk", stem);
  if (!xy) /* no memory for the VTK copy: the CSV is written, the VTK left out */
    return 0;
  if (!(f = ver_run_open_tmp(dir, name, tmp, sizeof tmp, bad))) {
    free(xy);
    return -1;
  }
  mpm_sim_info in;
  mpm_sim_info_get(s, &in);
  fprintf(f, "# vtk DataFile Version 3.0\ndelam line.vtk schema %d %s t=%g\nASCII\nDATASET POLYDATA\nPOINTS %d double\n",
          VER_SCHEMA_LINE, stem, in.t, 2 * m);
  for (int i = 0; i < m; i++)
    fprintf(f, "%.9g %.9g 0\n%.9g %.9g 0\n", xy[6 * i], xy[6 * i + 1], xy[6 * i + 2], xy[6 * i + 3]);
  fprintf(f, "LINES %d %d\n", m, 3 * m);
  for (int i = 0; i < m; i++)
    fprintf(f, "2 %d %d\n", 2 * i, 2 * i + 1);
  fprintf(f, "CELL_DATA %d\nSCALARS lambda double 1\nLOOKUP_TABLE default\n", m);
  for (int i = 0; i < m; i++)
    fprintf(f, "%.9g\n", xy[6 * i + 4]);
  fprintf(f, "SCALARS state int 1\nLOOKUP_TABLE default\n");
  for (int i = 0; i < m; i++)
    fprintf(f, "%d\n", (int)xy[6 * i + 5]);
  free(xy);
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
  if (ver_run_commit(f, tmp, bad))
    return -1;
  /* Legacy VTK polydata, one vertex per particle, for ParaView. */
  snprintf(name, sizeof name, "%s.vtk", stem);
  if (!(f = ver_run_open_tmp(dir, name, tmp, sizeof tmp, bad)))
    return -1;
  const size_t nb = p->n - p->nhead; /* the bar's particles; the head is the machine */
  fprintf(f, "# vtk DataFile Version 3.0\ndelam particles.vtk schema %d %s t=%g\nASCII\nDATASET POLYDATA\nPOINTS %zu double\n",
          VER_SCHEMA_PARTICLES, stem, in.t, nb);
  for (size_t k = 0; k < p->n; k++)
    if (p->mat[k] != MPM_MAT_HEAD)
      fprintf(f, "%.9g %.9g 0\n", p->x[k], p->y[k]);
  fprintf(f, "VERTICES %zu %zu\n", nb, 2 * nb);
  for (size_t k = 0; k < nb; k++)
    fprintf(f, "1 %zu\n", k);
  fprintf(f, "POINT_DATA %zu\nVECTORS displacement double\n", nb);
  for (size_t k = 0; k < p->n; k++)
    if (p->mat[k] != MPM_MAT_HEAD)
      fprintf(f, "%.9g %.9g 0\n", p->x[k] - p->x0[k], p->y[k] - p->y0[k]);
  const char *fields[] = {"lambda", "sxx", "syy", "sxy"};
  const double *arrs[] = {p->lam, p->sxx, p->syy, p->sxy};
  for (int q = 0; q < 4; q++) {
    fprintf(f, "SCALARS %s double 1\nLOOKUP_TABLE default\n", fields[q]);
    for (size_t k = 0; k < p->n; k++)
      if (p->mat[k] != MPM_MAT_HEAD)
        fprintf(f, "%.9g\n", arrs[q][k]);
  }
  if (ver_run_commit(f, tmp, bad))
    return -1;
  return write_line(s, dir, stem, bad);
}

int ver_run_write_rows(const ver_run_row *r, long n, const char *dir, char *bad)
{
  char tmp[1100];
  FILE *f = ver_run_open_tmp(dir, "load.csv", tmp, sizeof tmp, bad);
  if (!f)
    return -1;
  /* crack_tip: the specimens with a pre-crack (docs/specimens.md) */
  const int tip = n > 0 && isfinite(r[0].tip);
  fprintf(f, "# delam load.csv schema %d\nt,delta,P_grip,P_fixed%s\n", VER_SCHEMA_LOAD, tip ? ",crack_tip" : "");
  for (long i = 0; i < n; i++)
    if (tip)
      fprintf(f, "%.9g,%.9g,%.9g,%.9g,%.9g\n", r[i].t, r[i].delta, r[i].Pg, r[i].Pf, r[i].tip);
    else
      fprintf(f, "%.9g,%.9g,%.9g,%.9g\n", r[i].t, r[i].delta, r[i].Pg, r[i].Pf);
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

