/*
 * mpm_specimen.h - the specimens (private to kernel/): the body, where it is held and
 * loaded, and where its crack runs, one table row each (mpm_specimen.c lists them; the
 * bar of the paper is the first, mpm_spec_bar.c; the double cantilever beam and the
 * end-loaded split share mpm_spec_beam.c).  The solvers read a specimen only through
 * this table: the constrained node components as a list (mpm_bc), the line of the
 * interface, the area the crack may open and what it does once the body is cut.
 */
#ifndef DELAM_MPM_SPECIMEN_H
#define DELAM_MPM_SPECIMEN_H

#include <stdint.h>

#include "mpm_kernel.h"

/* The run's lattice: the body's cells, the grid's padding, the particle counts. */
typedef struct {
  double h;
  int cx, cy;       /* the body's cells in x and y                                     */
  int pad, padl;    /* empty cells around it; on the left (the head's travel besides)  */
  int padv;         /* empty cells below and above it (pad, and the arms' travel)      */
  int n1;           /* particles per cell along x and y                               */
  int headc;        /* cells of the rigid head beyond x = 0 (0: none)                 */
  size_t nbar, nhead, np; /* the body's particles, the head's, all                     */
} mpm_layout;

/* A constrained component of a node: held at c times the loading's displacement delta
 * (the static solver) or its rate (the explicit step); c = 0 holds it at rest.  The
 * load P_grip is work-conjugate to delta, P = sum c R over the list (R the reaction,
 * tension positive at the bar's grip), P_fixed the sum of the x reactions where fixed
 * is set (the static solver: of every x component held at rest). */
enum { MPM_BC_ANY = -1, MPM_BC_NEAR = 0, MPM_BC_FAR = 1 };
typedef struct mpm_bc {
  int node;         /* grid node                                                      */
  uint8_t comp;     /* 0: x, 1: y                                                     */
  uint8_t fixed;    /* 1: its reaction counts in P_fixed                              */
  int8_t side;      /* MPM_BC_ANY, or only the particles on that side of the interface
                       (the static solver's split node: its near or far slot)          */
  double c;         /* the held value per unit delta                                  */
} mpm_bc;

typedef struct mpm_specimen_type {
  const char *name;
  /* the layout's cells left of x = 0 beyond the margin (the grip's travel), and of them
   * those the rigid head's particles fill (the bar's loading machine) */
  void (*left_cells)(const mpm_scene *sc, int *left, int *head);
  /* the steady velocity of the loading at reference (x, y), the body's start (no wave
   * from the loaded ends: the explicit step) */
  void (*start_velocity)(const mpm_scene *sc, double x, double y, double *vx, double *vy);
  /* cells below and above the body beyond the margin, for its ends' travel in y */
  int (*rise_cells)(const mpm_scene *sc);
  /* the head's particles after the body's (NULL: none) */
  void (*place_head)(mpm_sim *s, const mpm_layout *l);
  /* the explicit step's end for the loading machine's particles (the bar's rigid head:
   * its motion and its ledger, W_head); NULL: none */
  void (*step_end)(mpm_sim *s);
  /* the constrained components into out (at most the count with out NULL); returns how
   * many.  The explicit step and the static solver take them in this order. */
  int (*bcs)(const mpm_sim *s, const mpm_layout *l, mpm_bc *out);
  /* the interface's line: a point of it (the flaw's particle at imp) */
  void (*line_point)(const mpm_sim *s, size_t imp, double *lx, double *ly);
  /* D's full value: U0 times the line's length the crack may open (the static solver's
   * scale of the dissipation) */
  double (*dis_full)(const mpm_scene *sc);
  /* the static solver's largest dissipation increment: a tenth of dis_full on the bar;
   * U0 h on the split beams, so that the rows resolve the front's advance node by node */
  double (*dis_step_max)(const mpm_scene *sc);
  /* 1 where the line at (x, y) starts open (a pre-crack); NULL: nowhere */
  int (*precrack)(const mpm_scene *sc, double x, double y);
  /* 1: the explicit interface's two fields are laid on the line (mpm_iface.c); 0: the
   * specimen is solved statically only */
  int explicit_iface;
  /* segments of the static interface, in cells along the line (0: one per node) */
  double seg_cells;
  /* the static solver once the body is cut: the node whose y to hold so that the cut
   * part's vertical rigid motion is fixed (eq: the solver's unknowns, MPM_DOF_* where
   * held); -1: none */
  int (*pin_node)(const mpm_sim *s, const int *eq);
} mpm_specimen_type;

extern const mpm_specimen_type mpm_spec_bar, mpm_spec_dcb, mpm_spec_els;
/* The row of sc->specimen. */
const mpm_specimen_type *mpm_specimen_of(const mpm_scene *sc);

#endif
