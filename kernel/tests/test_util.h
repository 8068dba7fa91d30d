/*
 * test_util.h - helpers shared by the kernel's cmocka tests: tolerance asserts with a
 * readable failure, and a small deterministic generator (splitmix64) so that a
 * failure can be replayed.  Include after <cmocka.h>.
 */
#ifndef DELAM_TEST_UTIL_H
#define DELAM_TEST_UTIL_H

#include <math.h>
#include <stdint.h>
#include <string.h>

/* |got - want| <= tol |want| (or <= tol when want == 0). */
static inline void assert_rel(double got, double want, double tol, const char *what)
{
  const double err = want == 0.0 ? fabs(got) : fabs(got - want) / fabs(want);
  if (!(err <= tol))
    fail_msg("%s: got %.17g, want %.17g (rel err %.3g > %.3g)", what, got, want, err, tol);
}

static inline void assert_abs(double got, double want, double tol, const char *what)
{
  if (!(fabs(got - want) <= tol))
    fail_msg("%s: got %.17g, want %.17g (abs err %.3g > %.3g)", what, got, want, fabs(got - want), tol);
}

/* Uniform in [0, 1). */
static inline double urand(uint64_t *s)
{
  uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return (double)(z >> 11) * 0x1.0p-53;
}

#ifdef DELAM_MPM_H
/* The bar's material with a decohesion law: E 1024, nu 0.25, rho 1, U0 0.375, the
 * explicit default separation 0.98; the rest of the scene zero. */
static inline mpm_scene tu_scene(int model, double alpha, double snf, double stf, double s0, double q)
{
  mpm_scene sc;
  memset(&sc, 0, sizeof sc);
  sc.le_factor = 1.0;
  sc.E = 1024.0;
  sc.nu = 0.25;
  sc.rho = 1.0;
  sc.model = model;
  sc.alpha_deg = alpha;
  sc.snf = snf;
  sc.stf = stf;
  sc.U0 = 0.375;
  sc.s0 = s0;
  sc.q = q;
  sc.sep_threshold = 0.98;
  return sc;
}

/* Fails unless runs a and b (one thread and two) hold the same bits: particle positions,
 * velocities, stresses and lambda, and every energy and ledger term. */
static inline void tu_assert_same_bits(const mpm_sim *a, const mpm_sim *b, const char *what)
{
  const size_t nb = a->p->n * sizeof(double);
  if (memcmp(a->p->x, b->p->x, nb) || memcmp(a->p->vx, b->p->vx, nb) || memcmp(a->p->sxx, b->p->sxx, nb) ||
      memcmp(a->p->lam, b->p->lam, nb))
    fail_msg("%s: particle state differs between 1 and 2 threads", what);
  mpm_energy ea, eb;
  mpm_sim_energy(a, &ea);
  mpm_sim_energy(b, &eb);
  if (memcmp(&ea, &eb, sizeof ea))
    fail_msg("%s: energies or ledger differ between 1 and 2 threads", what);
}

/* mpm_sim_alloc, failing the test with the kernel's message if it refuses. */
static inline mpm_sim *tu_make_sim(const mpm_scene *sc, int nthreads)
{
  mpm_sim *s = NULL;
  char err[256] = "";
  const mpm_status st = mpm_sim_alloc(sc, nthreads, &s, err, sizeof err);
  if (st != MPM_OK || !s)
    fail_msg("mpm_sim_alloc: %s: %s", mpm_strerror(st), err);
  return s;
}

/* Every term the step books in its ledger (docs/findings.md): the losses it can name. */
static inline double tu_booked(const mpm_energy *e)
{
  return e->L_bc + e->L_flip + e->L_scheme + e->W_head + e->L_contact + e->L_debris + e->L_damp;
}

/* What the ledger leaves unexplained from e0 to e: W_ext + KE(0) + SE(0) - (KE + SE +
 * W_coh + the booked terms); 0 up to rounding when it closes. */
static inline double tu_ledger_gap(const mpm_energy *e0, const mpm_energy *e)
{
  return e->W_ext + e0->KE + e0->SE - (e->KE + e->SE + e->W_coh + tu_booked(e));
}

/* n steps, failing the test with the kernel's message at the first that fails. */
static inline void tu_run_steps(mpm_sim *s, long n)
{
  char err[256] = "";
  for (long k = 0; k < n; k++) {
    const mpm_status st = mpm_sim_step(s, err, sizeof err);
    if (st != MPM_OK)
      fail_msg("step %ld: %s: %s", s->step, mpm_strerror(st), err);
  }
}

/* The bar of data/scenes/vibration.ini at spacing h (elastic, held in x at both ends, no
 * head, first axial mode), for the kernel tests that need it (include mpm.h first). */
static inline mpm_scene tu_vib_scene(double h, int scheme, int bc)
{
  mpm_scene sc = mpm_mms_scene(h, scheme, bc); /* the same bar, grid and dt (mpm_mms.c) */
  sc.nu = 0.25;
  sc.vib_amp = 0.03;
  sc.body_amp = sc.body_omega = 0.0; /* free: no manufactured body force */
  return sc;
}
#endif

#endif
