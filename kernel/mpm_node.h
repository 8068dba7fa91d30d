/*
 * mpm_node.h - the node record as one vector, shared by the step's passes
 * (mpm_step.c: bilinear shapes; mpm_gimp.c: uGIMP shapes).  Private to kernel/.
 */
#ifndef DELAM_MPM_NODE_H
#define DELAM_MPM_NODE_H

#include <stddef.h>
#include <string.h>

#include "mpm_kernel.h"

/* Nodes with less mass than this fraction of a particle's are treated as empty. */
#define MPM_MASS_EPS 1e-12

/* A node record as one vector (GCC's vector extension; without AVX it is split into
 * SSE2 pairs, with AVX-512 it is one register).  Elementwise arithmetic rounds exactly
 * as the scalar code would, so the vector width never changes a result.  memcpy moves
 * a record in and out without aliasing questions; it compiles to one load or store. */
typedef double mpm_v8 __attribute__((vector_size(64)));
/* lanes 0-7 are m, px, py, fx, fy, qx, qy, pad: the vectors below are written in it */
_Static_assert(sizeof(mpm_node) == 64 && offsetof(mpm_node, px) == 8 && offsetof(mpm_node, fx) == 24 &&
                   offsetof(mpm_node, qx) == 40,
               "mpm_node must be the eight lanes m, px, py, fx, fy, qx, qy, pad");

/* The gathers need only (px, py, fx, fy): four doubles inside the record's cache line. */
typedef double mpm_v4 __attribute__((vector_size(32)));
enum { GPX = 0, GPY = 1, GFX = 2, GFY = 3 }; /* lanes of the gathered four */

static inline mpm_v4 node_load4(const mpm_node *n)
{
  mpm_v4 v;
  memcpy(&v, &n->px, sizeof v);
  return v;
}

static inline void node_add(mpm_node *n, mpm_v8 d)
{
  mpm_v8 v;
  memcpy(&v, n, sizeof v);
  v += d;
  memcpy(n, &v, sizeof v);
}

#endif
