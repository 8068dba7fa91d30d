/* cmd_bench.c - `delam bench` (placeholder until its issue lands). */
#include <stdio.h>

#include "cmd.h"

int ver_cmd_bench(int argc, char **argv)
{
  (void)argc;
  (void)argv;
  fprintf(stderr, "delam bench: not implemented yet\n");
  return 2;
}
