/*
 * metrics_path.c - ver_curve_path (metrics.h): a run's distance from the analytic path
 * in (delta / delta_peak, P / Pmax), snapback included, linear in the rows whatever their
 * values.
 */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdlib.h>

#include "metrics.h"

/* The analytic path of ver_curve_path in (delta / delta_peak, P / Pmax): the elastic
 * line, the softening branch at PATH_NS + 1 points, then P = 0 (one long segment), and
 * the branch's segments in blocks of PATH_BLK with their bounding boxes, so that a distance is
 * found without visiting every segment: a block whose box is no nearer than the best
 * segment so far cannot hold a nearer one.  Where the branch's P never rises (every
 * bar: P falls with sigma*, eq. 34) the blocks are ordered in P and the search runs out
 * from the block at the point's P, stopping each way once the P gap alone is no nearer. */
enum { PATH_NS = 2000, PATH_NP = PATH_NS + 3, PATH_BLK = 32, PATH_NB = (PATH_NS + PATH_BLK - 1) / PATH_BLK };
typedef struct {
  double x[PATH_NP], y[PATH_NP];        /* the path's points; segment j joins j and j + 1 */
  double bx0[PATH_NB], bx1[PATH_NB];    /* block b: the branch's segments 1 + b PATH_BLK  */
  double by0[PATH_NB], by1[PATH_NB];    /* .. + PATH_BLK - 1: x and y bounds of their points */
  int falls;                            /* 1: y never rises along the branch              */
} path_poly;

/* The first and one past the last segment of block b. */
static int blk_first(int b)
{
  return 1 + b * PATH_BLK;
}
static int blk_end(int b)
{
  return 1 + (b + 1) * PATH_BLK < PATH_NS + 1 ? 1 + (b + 1) * PATH_BLK : PATH_NS + 1;
}

static void path_blocks(path_poly *pp)
{
  pp->falls = 1;
  for (int j = 2; j <= PATH_NS + 1; j++)
    pp->falls = pp->falls && pp->y[j] <= pp->y[j - 1];
  for (int b = 0; b < PATH_NB; b++) {
    const int j0 = blk_first(b), j1 = blk_end(b);
    pp->bx0[b] = pp->bx1[b] = pp->x[j0];
    pp->by0[b] = pp->by1[b] = pp->y[j0];
    for (int j = j0 + 1; j <= j1; j++) { /* segment j - 1 ends at point j */
      pp->bx0[b] = fmin(pp->bx0[b], pp->x[j]);
      pp->bx1[b] = fmax(pp->bx1[b], pp->x[j]);
      pp->by0[b] = fmin(pp->by0[b], pp->y[j]);
      pp->by1[b] = fmax(pp->by1[b], pp->y[j]);
    }
  }
}

/* Squared distance from (x, y) to segment j (points j, j + 1). */
static double seg_d2(const path_poly *pp, int j, double x, double y)
{
  const double ax = pp->x[j], ay = pp->y[j], bx = pp->x[j + 1] - ax, by = pp->y[j + 1] - ay, l2 = bx * bx + by * by;
  double t = l2 > 0.0 ? ((x - ax) * bx + (y - ay) * by) / l2 : 0.0;
  t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
  const double dx = x - ax - t * bx, dy = y - ay - t * by;
  return dx * dx + dy * dy;
}

/* The nearest of block b's segments to (x, y) into *best, unless its box is no nearer;
 * returns the squared gap in y alone between the point and the box. */
static double path_block(const path_poly *pp, int b, double x, double y, double *best)
{
  const double gx = x < pp->bx0[b] ? pp->bx0[b] - x : x > pp->bx1[b] ? x - pp->bx1[b] : 0.0;
  const double gy = y < pp->by0[b] ? pp->by0[b] - y : y > pp->by1[b] ? y - pp->by1[b] : 0.0;
  if (gx * gx + gy * gy < *best)
    for (int j = blk_first(b); j < blk_end(b); j++)
      *best = fmin(*best, seg_d2(pp, j, x, y));
  return gy * gy;
}

/* Distance from (x, y) to the path: the minimum over its segments (the blocks skipped
 * hold none nearer). */
static double path_dist(const path_poly *pp, double x, double y)
{
  double best = fmin(seg_d2(pp, 0, x, y), seg_d2(pp, PATH_NP - 2, x, y)); /* the elastic line, the tail */
  if (!pp->falls) {
    for (int b = 0; b < PATH_NB; b++)
      path_block(pp, b, x, y, &best);
    return sqrt(best);
  }
  int b0 = 0; /* the first block whose lowest y is at or below the point's */
  while (b0 < PATH_NB - 1 && pp->by0[b0] > y)
    b0++;
  for (int b = b0; b >= 0 && path_block(pp, b, x, y, &best) < best; b--) {
  }
  for (int b = b0 + 1; b < PATH_NB && path_block(pp, b, x, y, &best) < best; b++) {
  }
  return sqrt(best);
}

/* Points per row of the run's polyline at most: a longer row (an outlier) is sampled at
 * this many evenly spaced points, each weighing for the ds-spaced points it stands for,
 * so the work is linear in the rows whatever the values. */
#define PATH_MAX_PER_ROW 4096

double ver_curve_path(const ana_bar *b, const double *delta, const double *P, size_t n, double *d5)
{
  const double ds = 0.002;     /* spacing of the run's points along its polyline     */
  double dpk, Ppk;
  if (d5)
    *d5 = NAN;
  path_poly *pp = n > 0 && b->Pmax > 0.0 ? malloc(sizeof *pp) : NULL; /* 96 KiB: not on the stack */
  if (!pp)
    return NAN;
  ana_bar_softening_point(b, 1.0, &dpk, &Ppk);
  pp->x[0] = pp->y[0] = 0.0;
  for (int k = 0; k <= PATH_NS; k++) { /* sigma* from 1 to 0 */
    double d, p;
    ana_bar_softening_point(b, 1.0 - (double)k / PATH_NS, &d, &p);
    pp->x[k + 1] = d / dpk;
    pp->y[k + 1] = p / b->Pmax;
  }
  pp->x[PATH_NS + 2] = pp->x[PATH_NS + 1] + 1e3;
  pp->y[PATH_NS + 2] = 0.0;
  path_blocks(pp);
  size_t ipk = 0, end = n - 1;
  for (size_t i = 1; i < n; i++)
    if (P[i] > P[ipk])
      ipk = i;
  for (size_t i = ipk; i < n; i++)
    if (P[i] <= 0.01 * b->Pmax) {
      end = i;
      break;
    }
  double s = 0.0, m = 0.0, x0 = 0.0, y0 = 0.0;
  for (size_t i = 0; i <= end; i++) {
    const double x1 = delta[i] / dpk, y1 = P[i] / b->Pmax, len = hypot(x1 - x0, y1 - y0);
    if (!isfinite(len)) {
      free(pp);
      return DBL_MAX; /* a row beyond the doubles once scaled: as far as can be, and finite */
    }
    const double kt = ceil(len / ds), k = fmin(kt, PATH_MAX_PER_ROW), w = k > 0.0 ? kt / k : 0.0;
    for (double j = 1; j <= k; j++) {
      const double t = j / k, e = path_dist(pp, x0 + t * (x1 - x0), y0 + t * (y1 - y0));
      s += w * e * e;
    }
    m += kt;
    if (d5 && i > ipk && isnan(*d5) && P[i] <= 0.05 * b->Pmax && P[i - 1] > 0.05 * b->Pmax) {
      const double f = (P[i - 1] - 0.05 * b->Pmax) / (P[i - 1] - P[i]);
      double da, pa;
      ana_bar_softening_point(b, 0.05 * b->Pmax / Ppk, &da, &pa);
      *d5 = (delta[i - 1] + f * (delta[i] - delta[i - 1]) - da) / dpk;
    }
    x0 = x1;
    y0 = y1;
  }
  free(pp);
  if (!(m > 0.0))
    return NAN;
  return isfinite(s) && isfinite(m) ? sqrt(s / m) : DBL_MAX;
}
