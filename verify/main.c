/*
 * main.c - `delam`: dispatch to the subcommands (analytic, run, verify, report, bench, check, plot).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "build_info.h"
#include "cmd.h"

/* Waiting OpenMP threads sleep instead of spinning unless the user says otherwise: on a
 * machine whose other cores are busy a spinning thread holds a core its partner needs
 * (docs/library.md).  libgomp reads the variable when it is loaded, before main, so it is
 * set from the executable's pre-initialisation array, which runs before any shared
 * library's constructors. */
static void wait_passive(void)
{
  setenv("OMP_WAIT_POLICY", "passive", 0);
}
__attribute__((section(".preinit_array"), used)) static void (*const ver_preinit)(void) = wait_passive;

static const struct {
  const char *name;
  int (*fn)(int, char **);
  const char *what;
} cmds[] = {
  {"analytic", ver_cmd_analytic, "closed-form uniaxial bar: r0, g, slopes, snapback, energies"},
  {"run", ver_cmd_run, "run one scene file with the MPM kernel"},
  {"verify", ver_cmd_verify, "sweeps over h and particles per cell, checked against the analytic bar"},
  {"report", ver_cmd_report, "figures and the report (reports/out/)"},
  {"bench", ver_cmd_bench, "kernel speed: particle-updates per second and time split"},
  {"check", ver_cmd_check, "judge a run folder written by any code against a scene's checks"},
  {"plot", ver_cmd_plot, "draw one run folder: load curve and reference, crack front, energy ledger"},
};

static void usage(FILE *f)
{
  fprintf(f, "usage: delam COMMAND [OPTIONS]   (delam COMMAND --help for its options)\n"
             "       delam --version\n\ncommands:\n");
  for (size_t i = 0; i < sizeof cmds / sizeof cmds[0]; i++)
    fprintf(f, "  %-9s %s\n", cmds[i].name, cmds[i].what);
  fprintf(f, "\nEvery option NAME with a value is written --NAME VALUE or --NAME=VALUE.\n");
}

/* --name=value becomes --name value, so that every subcommand takes both spellings.
 * Returns the new argument count; out holds at most 2 argc entries. */
static int split_assignments(int argc, char **argv, char **out)
{
  int n = 0;
  for (int i = 0; i < argc; i++) {
    char *a = argv[i], *eq = a[0] == '-' && a[1] == '-' ? strchr(a, '=') : NULL;
    int name_ok = eq && eq > a + 2;
    for (const char *c = a + 2; name_ok && c < eq; c++)
      name_ok = (*c >= 'a' && *c <= 'z') || (*c >= '0' && *c <= '9') || *c == '-';
    if (name_ok) {
      *eq = '\0'; /* argv's strings are ours to modify (C11 5.1.2.2.1) */
      out[n++] = a;
      out[n++] = eq + 1;
    } else
      out[n++] = a;
  }
  out[n] = NULL;
  return n;
}

int main(int argc, char **argv)
{
  /* GSL's default handler aborts; every GSL call here checks its status instead. */
  gsl_set_error_handler_off();
  if (argc < 2) {
    usage(stderr);
    return 2;
  }
  if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") || !strcmp(argv[1], "help")) {
    usage(stdout);
    return 0;
  }
  if (!strcmp(argv[1], "--version")) {
    printf("delam %s\ncompiler %s\nflags %s\n", ver_build_version(), ver_build_compiler(), ver_build_flags());
    return 0;
  }
  for (size_t i = 0; i < sizeof cmds / sizeof cmds[0]; i++)
    if (!strcmp(argv[1], cmds[i].name)) {
      char **args = malloc(sizeof(char *) * (2 * (size_t)argc + 1));
      if (!args) {
        fprintf(stderr, "delam: out of memory\n");
        return 1;
      }
      const int n = split_assignments(argc - 1, argv + 1, args);
      const int rc = cmds[i].fn(n, args);
      free(args);
      return rc;
    }
  fprintf(stderr, "delam: unknown command '%s' (allowed: analytic, run, verify, report, bench, check, plot)\n", argv[1]);
  return 2;
}
