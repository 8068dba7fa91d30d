/* cmd_run.c - `delam run` (placeholder until its issue lands). */
#include <stdio.h>

#include "cmd.h"

int ver_cmd_run(int argc, char **argv)
{
  (void)argc;
  (void)argv;
  fprintf(stderr, "delam run: not implemented yet\n");
  return 2;
}
