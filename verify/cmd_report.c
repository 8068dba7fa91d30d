/* cmd_report.c - `delam report` (placeholder until its issue lands). */
#include <stdio.h>

#include "cmd.h"

int ver_cmd_report(int argc, char **argv)
{
  (void)argc;
  (void)argv;
  fprintf(stderr, "delam report: not implemented yet\n");
  return 2;
}
