/* main.c: the gallop command: dispatches to the sub-commands of src/cli/<command>.c (DESIGN.md
 * "Command line"). */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "gallop.h"

static const struct {
    const char *name;
    gal_cli_fn fn;
    const char *usage;
} commands[] = {
    {"modes", gal_cli_modes, "gallop modes SCENE [-o DIR] [--set s.k=v ...]\n"
              "                                         sagged equilibrium and natural modes"},
    {"simulate", gal_cli_simulate, "gallop simulate SCENE [--model reduced|full] [-o DIR] [--set s.k=v ...]\n"
                                   "                                         a galloping run: trace.csv, summary.json"},
    {"compare", gal_cli_compare, "gallop compare SCENE [-o DIR] [--set s.k=v ...]\n"
                                 "                                         full against reduced, same wind"},
    {"stability", gal_cli_stability, "gallop stability SCENE [-o DIR] [--set s.k=v ...]\n                                         Den Hartog criterion and onset wind speeds"}, {"wind", gal_cli_wind, "gallop wind SCENE [--points N] [-o DIR] [--set s.k=v ...]\n                                         the scene's turbulent wind field"},
    {"accuracy", gal_cli_accuracy, "gallop accuracy SCENE [-o DIR] [--set s.k=v ...] [--tolerance E] [--study NAME ...]\n"
                                   "                                         what accuracy costs in time: accuracy.csv, summary.json"},
    {"version", gal_cli_version, "gallop version                         print the version"},
    {"check", gal_cli_check, "gallop check SCENE [--set s.k=v ...]   parse and print the resolved scene"},
    {"spectrum", gal_cli_spectrum, "gallop spectrum TRACE.csv [--column NAME]... [--pair Y,Z]... [--from T] [--segment N] [-o DIR]\n"
                                   "                                         spectral analysis of any trace (DIR: TRACE's directory/spectrum)"},
};

static void usage(FILE *fp)
{
    fprintf(fp, "usage: gallop COMMAND [ARGS]\n\ncommands:\n");
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        fprintf(fp, "  %s\n", commands[i].usage);
    fprintf(fp, "\nexit status: 0 success, 1 the computation failed, 2 bad input\n");
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    if (!strcmp(argv[1], "-h") || !strcmp(argv[1], "--help") || !strcmp(argv[1], "help")) {
        usage(stdout);
        return 0;
    }
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        if (!strcmp(argv[1], commands[i].name)) return commands[i].fn(argc - 1, argv + 1);
    fprintf(stderr, "gallop: unknown command '%s'\n", argv[1]);
    usage(stderr);
    return 2;
}
