/*
 * scene_bar.c - what the paper fixes about a scene, in one place: the conversion to the
 * closed-form bar of analytic/ (ver_scene_bar; verify, report and bench all take their
 * analytic numbers from here) and the overrides that give the band method the
 * inclined files ran before the interface (ver_band_sets; the report's and the bench's).
 */
#include <stdio.h>
#include <string.h>

#include "scene.h"

int ver_scene_bar(const mpm_scene *sc, ana_bar *bar, char *err, size_t len)
{
  ana_params p;
  /* the bar's response depends on the plane's line only: alpha and 180 - alpha agree */
  p.alpha_deg = sc->alpha_deg > 90.0 ? 180.0 - sc->alpha_deg : sc->alpha_deg;
  p.snf = sc->snf;
  p.stf = sc->stf;
  p.U0 = sc->U0;
  p.s0 = sc->s0 > 0 ? sc->s0 : sc->snf; /* a parsed, not yet validated scene: the default */
  p.q = sc->q;
  p.E = sc->E;
  p.nu = sc->nu;
  p.L = sc->L;
  p.H = sc->H;
  p.model = sc->model;
  return ana_bar_init(&p, bar, err, (int)len) == ANA_OK ? 0 : 2;
}

int ver_static_refusal(const mpm_scene *sc, char *err, size_t len)
{
  if (sc->solver != MPM_SOLVER_STATIC)
    return 0;
  if (mpm_static_refusal(sc, err, len) != MPM_OK)
    return 2;
  /* measured on fig6's band at 4 ppc: g 0.67 (U0 0.125) curve_path 0.0067 at h 8, a stall
   * at h 4 after delta went to -0.018 and P to -15, 0.019 at h 2; g 0.5 (U0 0.09375)
   * stalls at h 8 and 4 (delta -0.030, -0.019), 0.031 at h 2: the band's particles
   * separate one by one, each a snapback of its own */
  ana_bar b;
  if (sc->specimen != MPM_SPEC_BAR || sc->model == MPM_DCOH_NONE || sc->path == MPM_PATH_IFACE ||
      ver_scene_bar(sc, &b, NULL, 0) != 0 || !(b.g < 1.0))
    return 0;
  snprintf(err, len, "solver.type = static: a softening band (decohesion.path = %s) on a bar whose closed form snaps "
           "back (g = %.3g, below 1) is not traced: its particles separate one by one, each a snapback of its own, "
           "and the path stalls or leaves the closed form by more than 0.01 (fig6's band at g 0.67 and 0.5, h 8, 4, 2; "
           "docs/static.md, \"Where it stops\"); the interface (--method interface) traces it to the solver's tolerance",
           sc->path == MPM_PATH_LINE ? "line" : "free", b.g);
  return 2;
}

/* The band method as fig7.ini and fig8.ini ran it before the interface: the band held to
 * its line with the paper's flaw on snf (fig8: on stf too, shear governs), Le measured
 * over the zone (fig8: the row), shear against the slip closing, and fig7 with the
 * flaw's whole cell on the grid that follows the bar's stretch; the rest is the file's
 * (its preset's MUSL, uGIMP, two fields and damping).  fig7's are the band preset's
 * keys that differ from its file's. */
int ver_band_sets(const char *scene, const char *const **sets)
{
  static const char *const fig7[] = {"decohesion.path=line", "imperfection.snf_factor=0.9", "grid.motion=stretch",
                                     "decohesion.Le=zone", "decohesion.reversed_shear=closing", "imperfection.size=cell"};
  static const char *const fig8[] = {"decohesion.path=line", "imperfection.snf_factor=0.9",
                                     "imperfection.stf_factor=0.9", "decohesion.Le=row",
                                     "decohesion.reversed_shear=closing"};
  _Static_assert(sizeof fig7 / sizeof fig7[0] <= VER_BAND_NSETS && sizeof fig8 / sizeof fig8[0] <= VER_BAND_NSETS,
                 "VER_BAND_NSETS too small");
  *sets = !strcmp(scene, "fig7") ? fig7 : !strcmp(scene, "fig8") ? fig8 : NULL;
  return !strcmp(scene, "fig7") ? (int)(sizeof fig7 / sizeof fig7[0])
         : !strcmp(scene, "fig8") ? (int)(sizeof fig8 / sizeof fig8[0]) : 0;
}
