/*
 * scene_bar.c - what the paper fixes about a scene, in one place: the conversion to the
 * closed-form bar of analytic/ (ver_scene_bar; verify, report and bench all take their
 * analytic numbers from here) and the overrides that give the band method the
 * inclined files ran before the interface (ver_band_sets; the report's and the bench's).
 */
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
