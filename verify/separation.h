/*
 * separation.h - when has the bar separated?  (prefix ver_sep_)  The run's stop rule
 * asks this after every output row; it is kept apart from the time loop so that it can
 * be tested on made-up particles and loads.  Two tests, and the first one counts:
 *  - kinematically (cut): the separated particles (lambda past the threshold, eqs.
 *    56-58) cover every row of particles, so no row still holds the bar together;
 *  - by the load: after the peak, the grip and fixed-end loads averaged over a window
 *    of win rows (the bar's longest period, 4 L / c, so that ringing averages out)
 *    both fall below frac x the peak; delta is the window's centre.
 * Inclined bands need the kinematic test: one velocity per cell keeps a few % of the
 * load on the grip after the band has failed, and the load test never fires.
 */
#ifndef DELAM_VER_SEPARATION_H
#define DELAM_VER_SEPARATION_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
  int nrow;              /* rows of particles (H / (h / sqrt(ppc)))        */
  double dy;             /* their spacing                                  */
  uint8_t *cut;          /* per row: holds a separated particle            */
  long win;              /* load window, in output rows                    */
  double frac;           /* load threshold, fraction of the peak           */
  double *ring;          /* the last win rows: delta, grip and fixed load  */
  long nseen;            /* output rows seen                               */
  double sum_g, sum_f;   /* running sums of the window's loads             */
  double amax;           /* largest |load| seen: bounds their rounding     */
  double delta_cut;      /* first delta of the cut test; -1 before         */
  double delta_load;     /* first delta of the load test; -1 before        */
  double delta_sep;      /* the first of the two; -1 before                */
} ver_sep;

/* Sets up the detector for a bar of height H, spacing h with ppc particles a cell, a
 * window of win >= 1 rows and a load threshold frac.  0, or -1 (out of memory). */
int ver_sep_init(ver_sep *d, double H, double h, int ppc, long win, double frac);
void ver_sep_free(ver_sep *d);

/* The cut test over n particles at reference heights y0 with separation flags sep;
 * particles with mat[k] == skip_mat are not part of the bar (mat may be NULL). */
/* decohesion.path = interface: the kernel's cut (every segment of the line open) is the
 * separation by particle rows; the first call sets delta_cut. */
void ver_sep_through(ver_sep *d, double delta);
void ver_sep_cut(ver_sep *d, const double *y0, const uint8_t *sep, const uint8_t *mat, int skip_mat, size_t n,
                 double delta);

/* The load test, after each output row (and after ver_sep_cut for that row, if it is
 * called): its delta and interval-averaged grip and fixed-end loads, and the largest
 * grip load so far (peak) and where (delta_peak).  Sets delta_sep.  O(1) a row except
 * where the window's mean is within rounding of the threshold (then O(win)). */
void ver_sep_load(ver_sep *d, double delta, double Pg, double Pf, double peak, double delta_peak);

/* A static run's separation from its exact rows: where the line through the row before
 * (d0, P0) and the first row at or under the test's load (d1, P1) reaches the load at
 * separation Ps (0 at lambda = 1; near it the branch is straight, eq. 34 at q 1); d1
 * where the load did not fall between them. */
double ver_sep_static(double d0, double P0, double d1, double P1, double Ps);

#endif
