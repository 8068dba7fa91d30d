/* cmd_analytic.c - `delam analytic` (placeholder until its issue lands). */
#include <stdio.h>

#include "cmd.h"

int ver_cmd_analytic(int argc, char **argv)
{
  (void)argc;
  (void)argv;
  fprintf(stderr, "delam analytic: not implemented yet\n");
  return 2;
}
