/*
 * run_scene.c - a program of one's own on libdelam: load a scene (a file, or a name
 * such as fig6 from the installed scene folder), run it with the kernel to its end
 * displacement, and compare the peak load and the dissipation with the closed-form bar.
 *
 *   cc run_scene.c $(pkg-config --cflags --libs delam) -o run_scene
 *   ./run_scene fig6 [section.key=value ...]
 *
 * Exit status: 0 the peak is within 5 % of the bar's, 1 it is not or the run failed,
 * 2 bad input.
 */
#include <math.h>
#include <stdio.h>

#include <delam/build_info.h>
#include <delam/datadir.h>
#include <delam/scene.h>

int main(int argc, char **argv)
{
  if (argc < 2) {
    fprintf(stderr, "usage: %s SCENE [section.key=value ...]\n", argv[0]);
    return 2;
  }
  char path[4400], err[4800];
  ver_scene vs;
  if (ver_scene_resolve(argv[1], path, sizeof path, err, sizeof err) ||
      ver_scene_parse(path, &vs, err, sizeof err)) {
    fprintf(stderr, "%s\n", err);
    return 2;
  }
  for (int i = 2; i < argc; i++)
    if (ver_scene_set(&vs, argv[i], err, sizeof err)) {
      fprintf(stderr, "%s\n", err);
      return 2;
    }
  if (ver_scene_validate(&vs, err, sizeof err)) { /* fills the defaults */
    fprintf(stderr, "%s\n", err);
    return 2;
  }
  ana_bar bar;
  if (ver_scene_bar(&vs.sc, &bar, err, sizeof err)) {
    fprintf(stderr, "%s\n", err);
    return 2;
  }
  mpm_sim *s;
  if (mpm_sim_alloc(&vs.sc, 0, &s, err, sizeof err) != MPM_OK) {
    fprintf(stderr, "%s: %s\n", path, err);
    return 2;
  }
  /* to just past the bar's separation (or the scene's end) */
  const double end = fmin(vs.sc.end_delta, 1.5 * bar.delta_sep);
  double peak = 0.0;
  mpm_sim_info in; /* where the run is: step, time, loads, counters */
  while (mpm_sim_delta(s) < end) {
    const mpm_status st = mpm_sim_step(s, err, sizeof err);
    mpm_sim_info_get(s, &in);
    if (st != MPM_OK) {
      fprintf(stderr, "step %ld: %s: %s\n", in.step, mpm_strerror(st), err);
      mpm_sim_free(s);
      return 1;
    }
    peak = fmax(peak, in.P_grip);
  }
  mpm_energy e;
  mpm_sim_energy(s, &e);
  mpm_particle_view p; /* the particles' arrays, read-only */
  mpm_sim_particles(s, &p);
  printf("libdelam %s: %s, %zu particles, %ld steps to delta %.4g\n", ver_build_version(), vs.name, p.n,
         in.step, mpm_sim_delta(s));
  printf("peak load %.4g (closed form %.4g), dissipation %.4g (closed form at separation %.4g)\n", peak, bar.Pmax,
         e.D, bar.D_sep);
  mpm_sim_free(s);
  return fabs(peak / bar.Pmax - 1.0) < 0.05 ? 0 : 1;
}
