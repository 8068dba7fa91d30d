/*
 * cmd_verify.c - `delam verify`: option parsing for the sweep of verify.h.
 * Options are parsed by hand (`--name value`), as in the other subcommands.
 */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cmd.h"
#include "datadir.h"
#include "scene.h"
#include "verify.h"

static void usage(FILE *f)
{
  fprintf(f,
    "usage: delam verify [--quick | --full | --angles] [options]\n"
    "Runs the scenes over grid spacings and particles per cell and checks every run\n"
    "against the closed-form bar (peak load, slopes, separation, energies, band width\n"
    "and angle, load-deflection error), then energy invariance and the order of\n"
    "convergence across runs.  Each check is pass, fail or known-limit (a deviation\n"
    "the paper itself reports; it carries its measured number and outer bounds).\n\n"
    "options:\n"
    "  --quick        a subset for `make check`: fig6 at h 8 (ppc 1, 4), h 4 (ppc 1, 4) and\n"
    "                 h 2 (ppc 4), its Le=particle and separation=0.8 variants at h 8 ppc 4,\n"
    "                 its whole run to end_delta at h 8 ppc 1, and at grip speeds 0.0005\n"
    "                 and 0.00025 (h 4, 2 ppc 1: the rate); fig7 at h 4 ppc 4 and at\n"
    "                 h 8, 4, 2 ppc 1 (an inclined GCI); iface90 at h 4 ppc 1 (against the\n"
    "                 exact solution at its grip speed) [default]\n"
    "  --full         every scene of the scene folder at h = 8, 4, 2, 1 and ppc = 1, 4, 9,\n"
    "                 explicit and static (the explicit interface at h 1 ppc 9 left out:\n"
    "                 implied by its neighbours), the split beams at h 4, 2, 1 ppc 4 and 1\n"
    "                 (the held bar ppc 4), and fig6's speed-refined cases\n"
    "                 (docs/sweeps.md)\n"
    "  --angles       every inclined scene file (alpha not 90) with its alpha replaced by\n"
    "                 30, 45, 60 and 75 deg (its own left out), and at all four with its\n"
    "                 snf and stf exchanged (the other mode; case ids end in -swap), at\n"
    "                 h = 4, 2 and ppc = 1, 4: the files' method on bands and modes they\n"
    "                 were not written for\n"
    "  --method NAME  every case with the method preset NAME (paper, band or interface)\n"
    "                 instead of its file's, as delam run --method; case ids end\n"
    "                 in -NAME (e.g. fig6-h8-ppc1-paper)\n"
    "  --jobs N       cases run in parallel (default: the number of cores)\n"
    "  --out DIR      per-case folders DIR/<case-id>/, DIR/verify.json, DIR/verify.csv\n"
    "                 (default out/verify-quick, out/verify-full or out/verify-angles)\n"
    "  --scenes DIR   scene folder (default: $DELAM_SCENES, ./data/scenes, or the\n"
    "                 installed or source tree's scenes)\n"
    "  --list         print one `delam run ...` line per case and stop (for GNU parallel\n"
    "                 or a cluster array; then `delam verify --merge DIR`)\n"
    "  --merge DIR    run nothing: check the case folders already in DIR (with --quick,\n"
    "                 --full or --angles: every case of that list, a missing one fails;\n"
    "                 alone: the cases of any list that DIR holds)\n"
    "  --help         this text\n"
    "SIGINT or SIGTERM stops the running cases, waits for them and writes verify.json\n"
    "with what there is (exit status 130).\n"
    "exit status: 0 no check failed, 1 a pass-class check failed (or a case crashed, or\n"
    "verify.json could not be written), 2 bad usage or input (or DIR is another\n"
    "sweep's, being written), 130 stopped by a signal\n");
}

int ver_cmd_verify(int argc, char **argv)
{
  const char *scenes = ver_scene_dir();
  ver_verify_opts o = {0, 0, 0, NULL, scenes ? scenes : "data/scenes", "delam", 0, 0, NULL, 0};
  int quick = 0;
  for (int i = 1; i < argc; i++) {
    const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
    if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
      usage(stdout);
      return 0;
    } else if (!strcmp(a, "--quick"))
      quick = 1;
    else if (!strcmp(a, "--full"))
      o.full = 1;
    else if (!strcmp(a, "--angles"))
      o.angles = 1;
    else if (!strcmp(a, "--list"))
      o.list = 1;
    else if (!strcmp(a, "--jobs")) {
      char *end;
      const long j = v ? strtol(v, &end, 10) : 0;
      if (!v || end == v || *end || j < 1 || j > 1024) {
        fprintf(stderr, "delam verify: --jobs: '%s' is not an integer in [1, 1024]\n", v ? v : "");
        return 2;
      }
      o.jobs = (int)j;
      i++;
    } else if (!strcmp(a, "--method")) {
      if (!v || ver_method_find(v) < 0) {
        char all[64];
        ver_method_list(all, sizeof all);
        fprintf(stderr, "delam verify: --method: '%s' is not a preset (allowed: %s)\n", v ? v : "", all);
        return 2;
      }
      o.method = v;
      i++;
    } else if (!strcmp(a, "--out") || !strcmp(a, "--merge") || !strcmp(a, "--scenes")) {
      if (!v || !v[0]) {
        fprintf(stderr, "delam verify: %s needs a folder\n", a);
        return 2;
      }
      if (!strcmp(a, "--scenes"))
        o.scenes = v;
      else {
        if (o.outdir && strcmp(o.outdir, v)) {
          fprintf(stderr, "delam verify: --out and --merge name different folders ('%s', '%s')\n", o.outdir, v);
          return 2;
        }
        o.outdir = v;
        if (!strcmp(a, "--merge"))
          o.merge = 1;
      }
      i++;
    } else {
      fprintf(stderr, "delam verify: unknown option '%s' (see delam verify --help)\n", a);
      return 2;
    }
  }
  if (quick + o.full + o.angles > 1) {
    fprintf(stderr, "delam verify: --quick, --full and --angles exclude each other\n");
    return 2;
  }
  if (o.list && o.merge) {
    fprintf(stderr, "delam verify: --list and --merge exclude each other\n");
    return 2;
  }
  if (!o.outdir)
    o.outdir = o.full ? "out/verify-full" : o.angles ? "out/verify-angles" : "out/verify-quick";
  o.merge_found = o.merge && !quick && !o.full && !o.angles;
  if (o.jobs == 0) {
    const long n = sysconf(_SC_NPROCESSORS_ONLN);
    o.jobs = n > 0 ? (int)n : 1;
  }
  /* the program itself, for --list lines that run as printed */
  static char self[PATH_MAX];
  const ssize_t l = readlink("/proc/self/exe", self, sizeof self - 1);
  if (l > 0) {
    self[l] = '\0';
    o.self = self;
  }
  return ver_verify(&o);
}
