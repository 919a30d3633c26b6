/* cli/usage.c: the commands of gallop and their options, one table (gal_cli_commands) from which
 * `gallop --help`, `gallop COMMAND --help` and the option parser (common.c) are made; doc/gallop.1
 * says the same in troff (tests/test_cli_help.sh checks that every option is in both). */
#include <stdio.h>
#include <string.h>

#include "cli.h"

#define SET {"set", 0, "SECTION.KEY=VALUE", 1, "set any scene key, after the file (repeatable)"}
#define OUT {"output", 'o', "DIR", 0, "output directory (default: [output] directory, out/<scene name>)"}
#define HELP "exit status: 0 success, 1 the computation failed, 2 bad input (the reason on stderr)\n"

const gal_cli_command gal_cli_commands[] = {
    {"modes", gal_cli_modes, "SCENE", "scene",
     "sagged equilibrium (Newton from the elastic catenary) and the natural modes asked for per family",
     "writes DIR/summary.json, modes.csv, shapes.csv, equilibrium.csv; a table on stdout\n",
     {OUT, SET}},
    {"simulate", gal_cli_simulate, "SCENE", "scene",
     "a galloping run under the scene's wind (reduced model by default)",
     "writes DIR/trace.csv and summary.json (per probe: measures, galloping ellipse, clearances)\n",
     {{"model", 0, "reduced|full", 0, "the model to integrate (default: reduced)"}, OUT, SET}},
    {"compare", gal_cli_compare, "SCENE", "scene",
     "the full and the reduced model on the same equilibrium, loads and wind",
     "writes DIR/compare.csv and summary.json; the errors and the speedup on stdout\n",
     {OUT, SET}},
    {"stability", gal_cli_stability, "SCENE", "scene",
     "Den Hartog's criterion over the angle of attack and the onset wind speed of each vertical mode",
     "writes DIR/stability.csv and summary.json; needs an [ice] aero_table\n",
     {OUT, SET}},
    {"wind", gal_cli_wind, "SCENE", "scene",
     "the scene's turbulent wind field as the simulations use it, and its statistics",
     "writes DIR/wind.csv and summary.json; needs [wind] turbulence\n",
     {{"points", 0, "N", 0, "write the wind at N evenly spaced points, 1 to 65 (default: 5)"}, OUT, SET}},
    {"accuracy", gal_cli_accuracy, "SCENE", "scene",
     "what accuracy costs in time: every choice against a converged reference, the Pareto front",
     "writes DIR/accuracy.csv, front.csv and summary.json; a table on stdout\n",
     {{"study", 0, "NAME[,NAME...]", 1,
       "run these studies: front (default), or the older one-at-a-time elements, modes, time_step, "
       "effects, newton_tolerance (repeatable)"},
      {"tolerance", 0, "E", 0, "relative error the chosen setting must meet, in (0, 1) (default: 0.01)"},
      {"budget", 0, "SECONDS", 0, "front: wall-time limit of the study, spent where the front is least known"},
      {"seeds", 0, "N", 0, "front, turbulent wind: seeds the statistics are averaged over, 1 to 64 (default: 3)"},
      {"levels", 0, "N", 0, "front: reference refinements at most, 1 to 8 (default: 3)"},
      OUT, SET}},
    {"spectrum", gal_cli_spectrum, "TRACE.csv", "trace",
     "Welch PSD, peaks, amplitudes, orbit ellipse and time to steady of any trace",
     "TRACE.csv: a header line of column names, then rows; the time column is `time`, `t` or `time_s`,\n"
     "else the first; uniform time step. Writes DIR/summary.json and DIR/psd.csv.\n",
     {{"column", 0, "NAME", 1, "analyse this column (repeatable; default: every column but time)"},
      {"pair", 0, "Y,Z", 1,
       "orbit ellipse of horizontal Y and vertical Z (repeatable; default: the columns named *_y/*_z "
       "or *_horizontal/*_vertical)"},
      {"from", 0, "T", 0,
       "the steady part starts at time T, s (default: the latest time to steady of the columns, but "
       "not after the middle of the record)"},
      {"segment", 0, "N", 0,
       "Welch segment, samples (default: the largest power of two giving >= 8 segments, at least 256)"},
      {"output", 'o', "DIR", 0, "output directory (default: the directory of TRACE.csv + /spectrum)"}}},
    {"sweep", gal_cli_sweep, "SCENE", "scene",
     "the scene over a grid of keys (galloping amplitude against wind speed...), alone or under mpirun",
     "LIST: v1,v2,... or start:stop:step; several --vary make the product grid. Writes DIR/sweep.csv (a row\n"
     "per case), summary.json, and DIR/cases/ (each finished case: a rerun skips it). `mpirun -n N gallop\n"
     "sweep ...` hands the cases out to N ranks; the results are the same whatever N\n",
     {{"vary", 0, "SECTION.KEY=LIST", 1, "vary this key over LIST (repeatable: the product grid)"},
      {"model", 0, "reduced|full", 0, "the model to integrate (default: reduced)"},
      {"continuation", 0, NULL, 0,
       "along the first key, start each case from the previous case's final state, up then down (hysteresis)"},
      OUT, SET}},
    {"check", gal_cli_check, "SCENE", "scene", "parse, validate and print the resolved scene (every key, its unit)",
     "prints INI that gallop reads back; nothing is computed or written\n", {SET}},
    {"version", gal_cli_version, NULL, NULL, "print the version", NULL, {{NULL, 0, NULL, 0, NULL}}},
};
const int gal_cli_ncommands = (int)(sizeof gal_cli_commands / sizeof gal_cli_commands[0]);

const gal_cli_command *gal_cli_command_find(const char *name)
{
    for (int i = 0; name && i < gal_cli_ncommands; i++)
        if (!strcmp(name, gal_cli_commands[i].name)) return gal_cli_commands + i;
    return NULL;
}

/* "gallop simulate SCENE [--model reduced|full] [-o DIR] [--set SECTION.KEY=VALUE]..." */
void gal_cli_synopsis(FILE *fp, const gal_cli_command *c)
{
    fprintf(fp, "gallop %s", c->name);
    if (c->operand) fprintf(fp, " %s", c->operand);
    for (int i = 0; i < GAL_CLI_MAX_OPTS && c->opt[i].name; i++) {
        const gal_cli_optdoc *o = c->opt + i;
        if (o->shortopt) fprintf(fp, " [-%c %s]", o->shortopt, o->arg);
        else if (o->arg) fprintf(fp, " [--%s %s]%s", o->name, o->arg, o->repeat ? "..." : "");
        else fprintf(fp, " [--%s]", o->name);
    }
    fputc('\n', fp);
}

void gal_cli_usage(FILE *fp, const gal_cli_command *c)
{
    fputs("usage: ", fp);
    gal_cli_synopsis(fp, c);
    fprintf(fp, "\n%s\n\noptions:\n", c->summary);
    for (int i = 0; i < GAL_CLI_MAX_OPTS && c->opt[i].name; i++) {
        const gal_cli_optdoc *o = c->opt + i;
        char head[80];
        if (o->shortopt) snprintf(head, sizeof head, "-%c, --%s %s", o->shortopt, o->name, o->arg);
        else snprintf(head, sizeof head, "--%s%s%s", o->name, o->arg ? " " : "", o->arg ? o->arg : "");
        fprintf(fp, "  %-26s %s\n", head, o->help);
    }
    fprintf(fp, "  %-26s %s\n", "-h, --help", "print this help and exit");
    if (c->details) fprintf(fp, "\n%s", c->details);
    fputs(HELP, fp);
}

void gal_cli_usage_all(FILE *fp)
{
    fputs("usage: gallop COMMAND [ARGS]\n       gallop COMMAND --help\n       gallop --version\n\ncommands:\n", fp);
    for (int i = 0; i < gal_cli_ncommands; i++) {
        fputs("  ", fp);
        gal_cli_synopsis(fp, gal_cli_commands + i);
        fprintf(fp, "      %s\n", gal_cli_commands[i].summary);
    }
    fputs("\nenvironment: GALLOP_DATA (the directory of conductors.csv), GALLOP_BLAS_THREADS (BLAS threads, "
          "default 1)\nsee gallop(1)\n" HELP, fp);
}
