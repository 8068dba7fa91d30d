/* cmd_verify.c - `delam verify` (placeholder until its issue lands). */
#include <stdio.h>

#include "cmd.h"

int ver_cmd_verify(int argc, char **argv)
{
  (void)argc;
  (void)argv;
  fprintf(stderr, "delam verify: not implemented yet\n");
  return 2;
}
