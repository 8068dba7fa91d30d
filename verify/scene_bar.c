/*
 * scene_bar.c - the one conversion of a scene to the closed-form bar of analytic/
 * (scene.h: ver_scene_bar).  verify, report and bench all take their analytic
 * numbers from here.
 */
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
