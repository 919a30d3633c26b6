/* cli.h: the gallop sub-commands. Each returns the process exit status (0, 1 computation failed,
 * 2 bad input). */
#ifndef GALLOP_CLI_H
#define GALLOP_CLI_H

typedef int (*gal_cli_fn)(int argc, char **argv);

/* One entry per sub-command, in src/cli_<name>.c. */
int gal_cli_version(int argc, char **argv);
int gal_cli_spectrum(int argc, char **argv);

#endif
