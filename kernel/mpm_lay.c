/*
 * mpm_lay.c - where the step lays its background grid (grid.motion) and takes the
 * particles' weights (grid.weights): hooks at the step's start (mpm_phase.h).  The
 * paper's fixed grid at the particles' positions has no hook.
 */
#include "mpm_kernel.h"
#include "mpm_phase.h"

/* The stretch that carries the grid (and the laid places) this step. */
static double stretch_now(const mpm_sim *s)
{
  return 1.0 + mpm_sim_delta(s) / s->sc.L;
}

/* grid.motion = stretch: the grid along the bar's mean stretch, so that the gripped
 * column stays on the bar's left end, the fixed one on its right end.  Once the band has
 * cut the bar there is no mean stretch to follow: the grid stays. */
static void lay_stretch(mpm_sim *s)
{
  if (s->cut)
    return;
  mpm_grid *g = s->g;
  const double L = s->sc.L, stretch = stretch_now(s);
  g->hx = s->sc.h * stretch;
  g->ihx = 1.0 / g->hx;
  g->ox = L + (s->grid_ox0 - L) * stretch;
}

/* grid.weights = laid (after lay_stretch): each bar particle to its laid place carried
 * by the stretch (mpm.h, grid.weights); the rigid head keeps its own place (it follows
 * the grip, not the stretch).  mpm_sim_step adds the offsets back when the step ends.
 * Once the bar is cut the particles are taken where they are (they moved by their
 * offsets from the laid places: sort them again). */
static void lay_laid(mpm_sim *s)
{
  if (s->cut) {
    if (!s->laid_done) {
      s->laid_done = 1;
      s->resort = 1;
    }
    return;
  }
  const double L = s->sc.L, stretch = stretch_now(s);
  mpm_particles *p = s->p;
  for (size_t k = 0; k < p->n; k++) {
    if (p->mat[k] == MPM_MAT_HEAD)
      continue;
    const double xl = L + (p->x0[k] - L) * stretch;
    p->wdx[k] = p->x[k] - xl;
    p->wdy[k] = p->y[k] - p->y0[k];
    p->x[k] = xl;
    p->y[k] = p->y0[k];
  }
  s->laid = 1;
}

const mpm_hook mpm_hook_stretch = {"stretch", {[MPM_PH_LAY] = lay_stretch}};
const mpm_hook mpm_hook_laid = {"laid", {[MPM_PH_LAY] = lay_laid}};
