/*
 * mpm_control.c - what the grip follows (loading.control).
 *
 * GRIP: the paper's loading, the rigid head pulled at loading.speed throughout.
 * DISSIPATION: for a bar whose curve snaps back (g below its limit, eq. 36), the run's
 * dissipation D (eq. 10 summed over the particles, never decreasing) is held from the
 * first step with D > 0 until the cut to D0 + speed Ppeak (t - t0), Ppeak the largest grip
 * load so far, as a test machine follows a snapback by a crack opening.  On the analytic
 * bar (q = 1) that gives d delta / dt = speed (g - 1) / g, negative on a snapback.  A PI
 * loop with the time constant of two wave transits, 2 L / c, sets the grip's speed,
 * bounded by MPM_CONTROL_VMAX times loading.speed; after the cut the grip pulls at
 * loading.speed again.  The grip's work stays in W_ext.
 */
#include <math.h>

#include "mpm.h"
#include "mpm_kernel.h"

#define MPM_CONTROL_VMAX 10.0 /* the grip's speed stays within this many loading.speed */

void mpm_control_step(mpm_sim *s)
{
  const mpm_scene *sc = &s->sc;
  const double v0 = sc->speed;
  double v = v0;
  if (sc->control == MPM_CONTROL_DISSIPATION && !s->cut && s->D_run > 0.0) {
    const mpm_material *m = &s->mat[MPM_MAT_BAR];
    const double tau = 2.0 * sc->L / sqrt(m->E1 / m->rho), dt = sc->dt;
    const double rate = v0 * s->P_peak; /* the dissipation rate held to */
    /* the target never runs ahead of D by more than a step's rate: the loop only holds D
     * back (ctl_D0 is the target, infinite until the first softening, so that it starts
     * at D) and never pulls to make it catch up */
    s->ctl_D0 = fmin(s->ctl_D0, s->D_run) + rate * dt;
    const double e = (s->ctl_D0 - s->D_run) / s->P_peak; /* a length, < 0 when D runs ahead */
    const double i1 = fmin(s->ctl_int + e * dt / (tau * tau), 0.0);
    v = v0 + e / tau + i1;
    const double vmax = MPM_CONTROL_VMAX * v0;
    if (v > vmax || v < -vmax)
      v = v > 0.0 ? vmax : -vmax; /* saturated: the integral holds (no wind-up) */
    else
      s->ctl_int = i1;
  }
  s->dvgrip = v - s->vgrip;
  s->vgrip = v;
}
