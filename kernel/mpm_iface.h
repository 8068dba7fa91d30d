/*
 * mpm_iface.h - the crack as a cohesive interface between two velocity fields
 * (decohesion.path = interface, mpm_iface.c), private to kernel/.
 */
#ifndef DELAM_MPM_IFACE_H
#define DELAM_MPM_IFACE_H

#include <stdint.h>

#include "mpm_kernel.h"

/* One interface: the line at alpha through the flaw, cut into segments of MPM_IFACE_SEG h
 * along it.  Per node (nnx * nny): its segment and its share of the line.  Per segment:
 * its length, strengths, state and the paper's lambda. */
#define MPM_IFACE_SEG 2.0      /* segment length, in cells (docs/findings.md) */
#define MPM_IFACE_REACH 2.5    /* split nodes: within this many h (|sin a| + |cos a|) of the line */
enum { MPM_SEG_STUCK = 0, MPM_SEG_SOFT = 1, MPM_SEG_OPEN = 2 };

struct mpm_iface {
  double lx, ly;           /* the line's point: the flaw particle's reference centre    */
  double nx, ny, tx, ty;   /* its normal (sin a, -cos a) and direction (cos a, sin a)    */
  double on;               /* a reference centre within this of the line lies on it     */
  int share;               /* decohesion.share: MPM_SHARE_STICK or MPM_SHARE_LINE        */
  int stick_onset;         /* 1: a stuck segment softens once its stick traction reaches
                              the strength (the split beams; mpm_iface_grid)            */
  double smin, sw;         /* the first segment's start along the line, and the length  */
  double s0, s1;           /* the line on the bar: from y = 0 to y = H, along it         */
  int *owner;              /* per segment's place on the line: the segment it joined     */
  int nseg;
  int nnode;               /* split nodes (fixed for the run)                           */
  size_t *node;            /* their indices, in node order: what every step walks       */
  int *seg;                /* per node: its segment                                     */
  double *An;              /* per node: the line's length weighted by the node's uGIMP N */
  double *jx, *jy;         /* per node: the impulse that sticks the fields, this step    */
  double *A;               /* per segment: the line's length in it (sum of An)          */
  double *Ab;              /* per segment (scratch): sum An at its nodes holding both fields */
  double *snf, *stf;       /* per segment: strengths (the flaw by its length on the line) */
  double *lam;             /* per segment: lambda (eq. 10's, here of the segment)        */
  uint8_t *state;          /* per segment: MPM_SEG_*                                     */
  uint8_t *stuck;          /* per segment: stuck this step (MUSL shares v' there)        */
  double *r;               /* per segment: this step's scale of the stick impulses (1 stuck) */
  double *sn, *st, *sv;    /* per segment (scratch): sum An tn, An tt, An at the nodes    */
  double *wn;              /* per segment (scratch): the traction's work this step      */
  double *Tn, *Tt;         /* per segment (scratch): the stick impulses' sums            */
  double *ns;              /* per node (scratch): the particles' sum w V (tn, tt, 1)      */
  double *md;              /* per node: m dv of field 1 and 2 this step (x, y pairs): MUSL's B */
};

/* The interface through (lx, ly); marks the fields' split nodes (fixed for the run).
 * NULL when out of memory. */
mpm_iface *mpm_iface_alloc(mpm_sim *s, double lx, double ly);
void mpm_iface_free(mpm_iface *f);
/* After the second field's eq. 4 at every split node (mpm_fields_grid): the onset, the
 * law's impulses and the ledger. */
void mpm_iface_grid(mpm_sim *s);
/* MUSL (mpm_fields_musl): the softening segments' work on the opening v'2 - v'1, their
 * lambda, the segments that open and the cut; then the ledger's B at split nodes, and v'
 * shared where stuck. */
void mpm_iface_musl(mpm_sim *s);
/* sum U0 A min(lambda, 1) over the segments: eq. 10 on the line */
double mpm_iface_D(const mpm_sim *s);
/* x of the line at height y */
double mpm_iface_x_at(const mpm_iface *f, double y);

/* The side of a particle: 1 (the second field) when its reference centre is on the
 * normal's side of the line, 0 when it is on the other side or on the line (within
 * f->on, far above the rounding of the normal: at alpha 90, cos a = 6e-17 split the
 * column on the line between the sides at the flaw's height).  A particle keeps its side
 * for the whole run. */
static inline int mpm_iface_side(const mpm_iface *f, double x0, double y0)
{
  return f->nx * (x0 - f->lx) + f->ny * (y0 - f->ly) > f->on;
}

#endif
