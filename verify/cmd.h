/*
 * cmd.h - the subcommands of the `delam` program.  Each returns the process exit
 * status: 0 success, 1 a check or run failed, 2 bad usage or bad input.
 */
#ifndef DELAM_CMD_H
#define DELAM_CMD_H

int ver_cmd_analytic(int argc, char **argv);
int ver_cmd_analytic_specimen(int argc, char **argv); /* `delam analytic --specimen` */
int ver_cmd_run(int argc, char **argv);
int ver_cmd_verify(int argc, char **argv);
int ver_cmd_report(int argc, char **argv);
int ver_cmd_bench(int argc, char **argv);
int ver_cmd_check(int argc, char **argv);
int ver_cmd_plot(int argc, char **argv);

#endif
