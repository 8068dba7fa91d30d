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

/* The band method as fig7.ini and fig8.ini ran it before the interface: the band held to its
 * line with the paper's flaw on snf (fig8: on stf too, shear governs), and fig7 on the grid
 * that follows the bar's stretch; the files' band keys (Le, path_reach, reversed_shear)
 * stay as written. */
int ver_band_sets(const char *scene, const char *const **sets)
{
  static const char *const fig7[VER_BAND_NSETS] = {"decohesion.path=line", "imperfection.snf_factor=0.9",
                                                   "grid.motion=stretch"};
  static const char *const fig8[VER_BAND_NSETS] = {"decohesion.path=line", "imperfection.snf_factor=0.9",
                                                   "imperfection.stf_factor=0.9"};
  *sets = !strcmp(scene, "fig7") ? fig7 : !strcmp(scene, "fig8") ? fig8 : NULL;
  return *sets ? VER_BAND_NSETS : 0;
}
