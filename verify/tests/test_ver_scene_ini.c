/*
 * test_ver_scene_ini.c - provenance of a scene (scene.h): the effective scene written
 * as INI reads back as the same scene, field for field, for every scene file with and
 * without overrides; case ids tell apart runs that differ in any override; and
 * docs/scene-keys.md holds the key table as the parser has it.
 * argv[1]: the source tree.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "io.h"
#include "scene.h"

static const char *src = ".";

static void load(const char *scene, const char *const *sets, ver_scene *vs)
{
  char path[1024], err[1024];
  snprintf(path, sizeof path, "%s/data/scenes/%s.ini", src, scene);
  if (ver_scene_parse(path, vs, err, sizeof err))
    fail_msg("%s", err);
  for (int i = 0; sets && sets[i]; i++)
    if (ver_scene_set(vs, sets[i], err, sizeof err))
      fail_msg("%s", err);
  if (ver_scene_validate(vs, err, sizeof err))
    fail_msg("%s", err);
}

/* The effective INI of a, read back, is a's scene; the text is returned (caller frees). */
static char *round_trip(const ver_scene *a)
{
  char *ini = NULL, err[1024];
  size_t len = 0;
  FILE *f = open_memstream(&ini, &len);
  assert_non_null(f);
  assert_int_equal(ver_scene_write_ini(a, f), 0);
  fclose(f);
  ver_scene b;
  if (ver_scene_parse_string(ini, "scene.ini", &b, err, sizeof err) || ver_scene_validate(&b, err, sizeof err))
    fail_msg("the effective scene of %s does not read back: %s\n%s", a->name, err, ini);
  /* every field of the kernel's scene, and the run control, bit for bit */
  if (memcmp(&a->sc, &b.sc, sizeof a->sc))
    fail_msg("%s: the kernel scene read back from its INI differs\n%s", a->name, ini);
  assert_true(a->nsnap == b.nsnap && !memcmp(a->snap, b.snap, sizeof a->snap));
  assert_true(a->interval == b.interval && a->stop_margin == b.stop_margin && a->sep_load_frac == b.sep_load_frac);
  return ini;
}

static void test_ver_scene_ini_round_trip(void **state)
{
  (void)state;
  const char *scenes[] = {"fig6", "fig7", "fig8", "a30", "a45", "iface90", "vibration"};
  /* values that do not print exactly in a few digits, and every kind of key */
  const char *sets[] = {"material.E=1000.1", "time.dt=0.0123456789012345", "decohesion.Le=particle",
                        "grid.ppc=4", "imperfection.x=33.3", "run.stop_margin=0", NULL};
  for (size_t i = 0; i < sizeof scenes / sizeof scenes[0]; i++) {
    ver_scene a;
    load(scenes[i], NULL, &a);
    free(round_trip(&a));
    load(scenes[i], sets, &a);
    char *ini = round_trip(&a);
    /* the overrides are named in the header */
    assert_non_null(strstr(ini, "material.E=1000.1"));
    free(ini);
  }
  /* a scene without decohesion: its unused keys stay out and it still reads back */
  ver_scene a;
  const char *none[] = {"decohesion.model=0", NULL};
  load("fig6", none, &a);
  free(round_trip(&a));
}

/* time.damping = critical is the bar's rate, 2 pi sqrt(E / rho) / L, set after every
 * override (so a changed bar changes it), and a number given later replaces it. */
static void test_ver_scene_damping_critical(void **state)
{
  (void)state;
  const double pi = 3.14159265358979323846;
  ver_scene a;
  const char *crit[] = {"time.damping=critical", NULL};
  load("fig8", crit, &a);
  assert_true(fabs(a.sc.damping - 2.0 * pi * 32.0 / 192.0) < 1e-14); /* E 1024, rho 1, L 192 */
  const char *softer[] = {"time.damping=critical", "material.E=256", "bar.L=128", NULL};
  load("fig8", softer, &a);
  assert_true(fabs(a.sc.damping - 2.0 * pi * 16.0 / 128.0) < 1e-14); /* c 16, L 128: 3 / 4 of the rate */
  const char *later[] = {"time.damping=critical", "time.damping=0.2", NULL};
  load("fig8", later, &a);
  assert_true(a.sc.damping == 0.2);
  load("fig8", crit, &a);
  free(round_trip(&a)); /* the effective INI holds the number, and reads back to it */
}

static void test_ver_scene_case_ids(void **state)
{
  (void)state;
  ver_scene a, b;
  char ia[600], ib[600];
  load("fig6", NULL, &a);
  ver_scene_case_id(&a, ia, sizeof ia);
  assert_string_equal(ia, "fig6-h8-ppc1");
  const char *e1[] = {"material.E=2048", NULL}, *e2[] = {"material.E=2048.5", NULL};
  load("fig6", e1, &b);
  ver_scene_case_id(&b, ib, sizeof ib);
  assert_string_equal(ib, "fig6-h8-ppc1-E2048");
  load("fig6", e2, &a);
  ver_scene_case_id(&a, ia, sizeof ia);
  assert_string_not_equal(ia, ib);
  /* h with the file's Courant number is in the id once; an own dt is named */
  const char *h4[] = {"grid.h=4", "time.dt=0.05", NULL}, *h4dt[] = {"grid.h=4", "time.dt=0.04", NULL};
  load("fig6", h4, &a);
  ver_scene_case_id(&a, ia, sizeof ia);
  assert_string_equal(ia, "fig6-h4-ppc1");
  load("fig6", h4dt, &a);
  ver_scene_case_id(&a, ia, sizeof ia);
  assert_string_equal(ia, "fig6-h4-ppc1-dt0.04");
  /* --set grid.h scales dt as --h does (fig6: 0.1 at h 8): not refused for the CFL bound */
  const char *h4only[] = {"grid.h=4", NULL}, *dth4[] = {"time.dt=0.02", "grid.h=4", NULL};
  load("fig6", h4only, &a);
  assert_true(a.sc.dt == 0.05);
  ver_scene_case_id(&a, ia, sizeof ia);
  assert_string_equal(ia, "fig6-h4-ppc1");
  load("fig6", dth4, &a); /* a dt of the user's own stays */
  assert_true(a.sc.dt == 0.02);
  /* the last value of a key counts */
  const char *twice[] = {"material.E=1", "material.E=2048", NULL};
  load("fig6", twice, &a);
  ver_scene_case_id(&a, ia, sizeof ia);
  assert_string_equal(ia, ib);
}

/* The presets: each resolves to its rows, with every other method key at its default;
 * a key the file sets wins over its file's preset; --method (method.preset=NAME) gives
 * the same kernel scene as the paper's thirteen overrides on fig7; an unknown preset
 * is refused naming the file, the line and the presets. */
static void test_ver_scene_presets(void **state)
{
  (void)state;
  ver_scene a, b;
  char err[1024];
  for (int p = 0; p < 3; p++) {
    const char *const *rows;
    const int n = ver_method_rows(p, &rows);
    assert_true(n > 0);
    char text[512];
    snprintf(text, sizeof text, "[method]\npreset = %s\n[bar]\nL = 192\nH = 32\n", ver_method_name(p));
    assert_int_equal(ver_scene_parse_string(text, "p.ini", &a, err, sizeof err), 0);
    for (int i = 0; i < n; i++) { /* each row, set on a scene without a preset, changes nothing */
      assert_int_equal(ver_scene_parse_string("[bar]\nL = 192\nH = 32\n", "q.ini", &b, err, sizeof err), 0);
      for (int j = 0; j <= i; j++)
        assert_int_equal(ver_scene_set(&b, rows[j], err, sizeof err), 0);
      ver_scene c = a;
      assert_int_equal(ver_scene_set(&c, rows[i], err, sizeof err), 0);
      assert_memory_equal(&c.sc, &a.sc, sizeof a.sc);
      if (i == n - 1) /* all its rows on the defaults: the preset */
        assert_memory_equal(&b.sc, &a.sc, sizeof a.sc);
    }
  }
  assert_string_equal(ver_method_name(ver_method_find("paper")), "paper");
  /* the band preset: path line, Le zone, the flaw's cell at 0.9, the stretched grid, MUSL */
  assert_int_equal(ver_scene_parse_string("[method]\npreset = band\n[grid]\nfields = one\n", "b.ini", &a, err,
                                          sizeof err), 0);
  assert_int_equal(a.sc.path, MPM_PATH_LINE);
  assert_int_equal(a.sc.le_mode, MPM_LE_ZONE);
  assert_int_equal(a.sc.imp_size, MPM_IMP_CELL);
  assert_true(a.sc.imp_factor == 0.9 && a.sc.damping == 0.1);
  assert_int_equal(a.sc.grid_motion, MPM_GRID_STRETCH);
  assert_int_equal(a.sc.scheme, MPM_SCHEME_MUSL);
  assert_int_equal(a.sc.fields, MPM_FIELDS_ONE); /* the file's key over its preset's */
  assert_int_equal(a.sc.bc, MPM_BC_LAGRANGIAN); /* not in the preset: the default */
  /* the file's [method] may come after the keys it gives way to */
  assert_int_equal(ver_scene_parse_string("[grid]\nshape = linear\n[method]\npreset = interface\n", "i.ini", &b, err,
                                          sizeof err), 0);
  assert_int_equal(b.sc.shape, MPM_SHAPE_LINEAR);
  assert_int_equal(b.sc.path, MPM_PATH_IFACE);
  /* --method paper on fig7 is its thirteen overrides, and drops the file's other keys */
  const char *paper[] = {"method.preset=paper", NULL};
  load("fig7", paper, &a);
  const char *sets[VER_PAPER_NSETS + 1];
  for (int i = 0; i < VER_PAPER_NSETS; i++)
    sets[i] = ver_paper_sets[i];
  sets[VER_PAPER_NSETS] = NULL;
  load("fig7", sets, &b);
  /* besides: the file's damping_from = cut and damping_about = parts (its preset's) go
   * back to their defaults, which do nothing at damping 0 (check_method.sh: the same
   * load.csv byte for byte) */
  assert_true(b.sc.damping_from == MPM_DAMP_CUT && b.sc.damping_about == MPM_DAMP_PARTS);
  b.sc.damping_from = MPM_DAMP_START;
  b.sc.damping_about = MPM_DAMP_DRIFT;
  assert_memory_equal(&a.sc, &b.sc, sizeof a.sc);
  char id[600], diff[32][64];
  ver_scene_case_id(&a, id, sizeof id);
  assert_string_equal(id, "fig7-h2-ppc1-paper");
  assert_int_equal(ver_method_overrides(&a, diff, 32), 0);
  const char *then[] = {"time.scheme=musl", "method.preset=paper", "grid.bc=consistent", NULL};
  load("fig6", then, &a);
  assert_int_equal(a.sc.scheme, MPM_SCHEME_USL); /* an override before --method gives way */
  assert_int_equal(a.sc.bc, MPM_BC_CONSISTENT); /* one after it holds */
  assert_int_equal(ver_method_overrides(&a, diff, 32), 1);
  assert_string_equal(diff[0], "grid.bc=consistent");
  ver_scene_case_id(&a, id, sizeof id);
  assert_string_equal(id, "fig6-h8-ppc1-paper-bc_consistent");
  free(round_trip(&a));
  /* an unknown preset: file, line and the allowed names */
  assert_int_equal(ver_scene_parse_string("[bar]\nL = 1\n[method]\npreset = paperr\n", "u.ini", &a, err, sizeof err), 2);
  assert_non_null(strstr(err, "u.ini:4: method.preset: 'paperr' is not allowed"));
  assert_true(strstr(err, "paper") && strstr(err, "band") && strstr(err, "interface"));
  load("fig7", NULL, &a);
  assert_int_equal(ver_scene_set(&a, "method.preset=none", err, sizeof err), 2);
  assert_non_null(strstr(err, "fig7.ini: command line: method.preset: 'none' is not allowed"));
}

/* docs/scene-keys.md between its two marker lines is the parser's key table. */
static void test_ver_scene_keys_doc(void **state)
{
  (void)state;
  char path[1024];
  snprintf(path, sizeof path, "%s/docs/scene-keys.md", src);
  char *doc = ver_io_slurp(path, NULL, 0);
  assert_non_null(doc);
  const char *b = strstr(doc, "<!-- keys: begin -->\n"), *e = strstr(doc, "<!-- keys: end -->");
  assert_true(b && e && e > b);
  b += strlen("<!-- keys: begin -->\n");
  char *tab = NULL;
  size_t len = 0;
  FILE *f = open_memstream(&tab, &len);
  ver_scene_keys_markdown(f);
  fclose(f);
  if ((size_t)(e - b) != len || memcmp(b, tab, len))
    fail_msg("docs/scene-keys.md is not the key table of verify/scene_keys.c (`make docs-keys` rewrites it); it should read:\n%s", tab);
  free(tab);
  free(doc);
}

int main(int argc, char **argv)
{
  if (argc > 1)
    src = argv[1];
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_ver_scene_ini_round_trip),
      cmocka_unit_test(test_ver_scene_damping_critical),
      cmocka_unit_test(test_ver_scene_case_ids),
      cmocka_unit_test(test_ver_scene_keys_doc),
      cmocka_unit_test(test_ver_scene_presets),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
