/* main.c: the gallop command: `gallop --help`, `gallop --version`, `gallop help [COMMAND]`, then
 * the sub-commands of src/cli/<command>.c (their options in usage.c), each checked and its
 * `--help` answered here before it runs; the BLAS threads are set first (blas.c). */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "gallop.h"

static int help(int argc, char **argv)
{
    if (argc < 2) {
        gal_cli_usage_all(stdout);
        return 0;
    }
    const gal_cli_command *c = gal_cli_command_find(argv[1]);
    if (!c) {
        fprintf(stderr, "gallop help: no command '%s'\n", argv[1]);
        gal_cli_usage_all(stderr);
        return 2;
    }
    gal_cli_usage(stdout, c);
    return 0;
}

int main(int argc, char **argv)
{
    gal_cli_blas_threads(argv);
    if (gal_cli_blas_reserve()) return 1;
    if (argc < 2) {
        gal_cli_usage_all(stderr);
        return 2;
    }
    const char *a = argv[1];
    if (!strcmp(a, "-h") || !strcmp(a, "--help") || !strcmp(a, "help")) return help(argc - 1, argv + 1);
    if (!strcmp(a, "--version") || !strcmp(a, "-V")) return gal_cli_version(argc - 1, argv + 1);
    const gal_cli_command *c = gal_cli_command_find(a);
    if (!c) {
        fprintf(stderr, "gallop: unknown command '%s'\n", a);
        gal_cli_usage_all(stderr);
        return 2;
    }
    /* the arguments checked once against the command's table: --help answered, bad ones refused */
    gal_cli_args args;
    int rc = gal_cli_parse(c, argc - 1, argv + 1, &args);
    if (rc) return rc;
    if (args.help) {
        gal_cli_usage(stdout, c);
        return 0;
    }
    return c->fn(argc - 1, argv + 1);
}
