/* cli/common.c: what the sub-commands share: the option parser (getopt_long over the command's
 * table of usage.c), reading SCENE [--set section.key=value ...] [-o DIR] and loading the scene
 * and the tables it names. */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "gallop.h"
#include "gallop/model/tables.h"
#include "gallop/output/outset.h"
#include "gallop/scene/scene.h"

static int usage_error(const gal_cli_command *c, const char *what, const char *arg)
{
    fprintf(stderr, "gallop %s: %s%s%s\nusage: ", c->name, what, arg ? " " : "", arg ? arg : "");
    gal_cli_synopsis(stderr, c);
    fprintf(stderr, "(gallop %s --help for more)\n", c->name);
    return 2;
}

/* getopt_long's table: the command's options (val 256 + index) and --help */
static void long_options(const gal_cli_command *c, struct option *lo, char *shorts)
{
    int n = 0, ns = 0;
    shorts[ns++] = ':';   /* ':' for a missing value */
    shorts[ns++] = 'h';
    for (int i = 0; i < GAL_CLI_MAX_OPTS && c->opt[i].name; i++, n++) {
        lo[n] = (struct option){c->opt[i].name, c->opt[i].arg ? required_argument : no_argument, NULL, 256 + i};
        if (c->opt[i].shortopt) {
            shorts[ns++] = c->opt[i].shortopt;
            if (c->opt[i].arg) shorts[ns++] = ':';
        }
    }
    lo[n++] = (struct option){"help", no_argument, NULL, 'h'};
    lo[n] = (struct option){NULL, 0, NULL, 0};
    shorts[ns] = '\0';
}

static int short_index(const gal_cli_command *c, int ch)
{
    for (int i = 0; i < GAL_CLI_MAX_OPTS && c->opt[i].name; i++)
        if (c->opt[i].shortopt == ch) return i;
    return -1;
}

int gal_cli_parse(const gal_cli_command *c, int argc, char **argv, gal_cli_args *a)
{
    struct option lo[GAL_CLI_MAX_OPTS + 2];
    char shorts[2 * GAL_CLI_MAX_OPTS + 3];
    memset(a, 0, sizeof *a);
    long_options(c, lo, shorts);
    opterr = 0;
    optind = 0;   /* glibc: a full re-initialization (argv may be parsed more than once) */
    for (int ch; (ch = getopt_long(argc, argv, shorts, lo, NULL)) != -1;) {
        int i = ch >= 256 ? ch - 256 : short_index(c, ch);
        if (ch == 'h') {
            a->help = 1;
        } else if (ch == ':') {
            return usage_error(c, "missing value after", argv[optind - 1]);
        } else if (ch == '?' || i < 0) {
            char s[3] = {'-', (char)optopt, '\0'};
            return usage_error(c, "unknown option", optopt ? s : argv[optind - 1]);
        } else if (a->nval[i] == GAL_CLI_MAX_VALS) {
            return usage_error(c, "too many values of option", c->opt[i].name);
        } else {
            a->val[i][a->nval[i]++] = optarg;
        }
    }
    if (a->help) return 0;
    for (int k = optind; k < argc; k++) {
        if (!c->operand) return usage_error(c, "takes no argument:", argv[k]);
        if (a->operand) {
            char what[64];
            snprintf(what, sizeof what, "more than one %s:", c->what);
            return usage_error(c, what, argv[k]);
        }
        a->operand = argv[k];
    }
    if (c->operand && !a->operand) {
        char what[64];
        snprintf(what, sizeof what, "no %s given", c->what);
        return usage_error(c, what, NULL);
    }
    return 0;
}

int gal_cli_values(const gal_cli_command *c, const gal_cli_args *a, const char *name, const char *const **vals)
{
    for (int i = 0; i < GAL_CLI_MAX_OPTS && c->opt[i].name; i++)
        if (!strcmp(c->opt[i].name, name)) {
            *vals = a->val[i];
            return a->nval[i];
        }
    *vals = NULL;
    return 0;
}

const char *gal_cli_value(const gal_cli_command *c, const gal_cli_args *a, const char *name)
{
    const char *const *v;
    int n = gal_cli_values(c, a, name, &v);
    return n > 0 ? v[n - 1] : NULL;
}

int gal_cli_scene(const gal_cli_command *c, const gal_cli_args *a, gal_scene *sc, const char **outdir)
{
    const char *const *sets;
    int nsets = gal_cli_values(c, a, "set", &sets);
    const char *dir = gal_cli_value(c, a, "output");
    int st = gal_scene_load(sc, a->operand, sets, nsets, NULL);
    if (st == GAL_OK && sc->ice.aero_table[0]) {
        /* the table is read now, whatever the command: a bad one is bad input before any output */
        gal_aero_table *t = NULL;
        st = gal_model_aero_table(sc, &t);
        gal_aero_table_free(t);
    }
    if (st != GAL_OK) {
        fprintf(stderr, "gallop %s: %s\n", c->name, gal_error_message());
        return gal_exit_code(st);
    }
    /* the explicit bundle model has statics, modes, the onset, both models' runs, compare and sweep (README "Bundles") */
    if (sc->bundle.subconductors > 1 && sc->bundle.explicit_model && strcmp(c->name, "modes") &&
        strcmp(c->name, "check") && strcmp(c->name, "wind") && strcmp(c->name, "stability") &&
        strcmp(c->name, "simulate") && strcmp(c->name, "compare") &&
        strcmp(c->name, "sweep")) { /* sweep: the explicit full model per case (run/sweep.h) */
        int ln = sc->bundle.model_line;
        char at[64] = "--set";
        if (ln > 0) snprintf(at, sizeof at, "%d", ln);
        fprintf(stderr, "gallop %s: %s%s%s: [bundle] model = explicit: `gallop %s` does not run the explicit "
                "bundle model (it has statics and modes, `gallop modes`, the coupled onset, `gallop stability`, "
                "the full and reduced models' runs, `gallop simulate`, `gallop compare`, and `gallop sweep` with the full model); allowed: model = equivalent, which runs every command\n", c->name, ln >= 0 ? a->operand : "", ln >= 0 ? ":" : "", at, c->name);
        return 2;
    }
    if (dir) {
        if (!*dir || strlen(dir) >= sizeof sc->output.directory)
            return usage_error(c, "-o: directory name empty or too long:", dir);
        strcpy(sc->output.directory, dir);
    }
    /* the output directory is checked now, before any computation (issue 14) */
    if ((st = gal_outset_check(sc->output.directory)) != GAL_OK) {
        fprintf(stderr, "gallop %s: %s\n", c->name, gal_error_message());
        return 2;
    }
    if (outdir) *outdir = sc->output.directory;
    return 0;
}

int gal_cli_load_scene_opts(int argc, char **argv, gal_scene *sc, const char **outdir,
                            const char *const *opts, const char **vals)
{
    const gal_cli_command *c = gal_cli_command_find(argc > 0 ? argv[0] : NULL);
    if (!c) {
        fprintf(stderr, "gallop: no such command '%s'\n", argc > 0 && argv[0] ? argv[0] : "?");
        return 2;
    }
    gal_cli_args a;
    int rc = gal_cli_parse(c, argc, argv, &a);
    if (rc) return rc;
    for (int j = 0; opts && opts[j]; j++)
        vals[j] = gal_cli_value(c, &a, opts[j] + (opts[j][0] == '-' && opts[j][1] == '-' ? 2 : 0));
    return gal_cli_scene(c, &a, sc, outdir);
}

int gal_cli_load_scene(int argc, char **argv, gal_scene *sc, const char **outdir)
{
    return gal_cli_load_scene_opts(argc, argv, sc, outdir, NULL, NULL);
}

/* a relative error as a percentage, or n/a where the full model does not move (compare.h) */
static const char *pct(char *buf, double e)
{
    if (isnan(e)) return "n/a";
    snprintf(buf, 32, "%.3g%%", 100 * e);
    return buf;
}

/* a vertical fundamental frequency, and the order of the larger line when it is a harmonic of it */
static const char *hz(char *buf, const gal_sim_measures *m)
{
    if (m->harmonic[1] > 1) snprintf(buf, 48, "%.4g Hz (harmonic %d larger)", m->frequency_hz[1], m->harmonic[1]);
    else snprintf(buf, 48, "%.4g Hz", m->frequency_hz[1]);
    return buf;
}

void gal_cli_print_compare(const gal_compare_figures *c, const char *twist, double setup_s)
{
    char f[2][48];
    char b[4][32];
    const gal_compare_probe *p = c->probe;
    const int *h = c->headline;
    printf("frequency error %s, amplitude errors: vertical %s, horizontal %s, %s %s; speedup %.2fx "
           "(reduced model's own set-up %.3f s)\n", pct(b[0], c->frequency_error), pct(b[1], c->err_vertical),
           pct(b[2], c->err_horizontal), twist, pct(b[3], c->err_twist), c->speedup, setup_s);
    static const char *const fam[GAL_CMP_FAMILIES] = {"vertical", "horizontal", "twist"};
    static const char *const unit[GAL_CMP_FAMILIES] = {"m", "m", "deg"};
    if (c->window_moved)
        fprintf(stderr, "gallop compare: note: the full model is not steady from %.4g s (still settling); the runs "
                "are compared over its steady part from %.4g s\n", c->window_first_from_s, c->full.steady_from_s);
    for (int f = 0; f < GAL_CMP_FAMILIES; f++)
        if (!c->family_steady[f])
            fprintf(stderr, "gallop compare: warning: the full model is not steady over the window (%s "
                    "peak-to-peak at %g of the span %.4g %s in its first half, %.4g %s in its second, %.3g%% apart: "
                    "still growing, decaying or bursting): the runs are compared in a transient; lengthen "
                    "simulation.duration (or check that the span gallops)\n", fam[f], p[h[f]].position,
                    c->family_first[f], unit[f], c->family_second[f], unit[f], 100 * c->family_drift[f]);
    if (c->nprobe < 2) return;
    printf("headline at the full model's largest peak-to-peak: vertical at %g, horizontal at %g, %s at %g of the "
           "span\n",
           p[h[0]].position, p[h[1]].position, twist, p[h[2]].position);
    for (int k = 0; k < c->nprobe; k++)
        printf("  probe %-5g full vertical p-p %.4g m at %s, reduced %.4g m at %s; errors: frequency %s, "
               "vertical %s, horizontal %s, %s %s\n", p[k].position, p[k].full.peak_to_peak[1],
               hz(f[0], &p[k].full), p[k].reduced.peak_to_peak[1], hz(f[1], &p[k].reduced),
               pct(b[0], p[k].frequency_error), pct(b[1], p[k].err[0]), pct(b[2], p[k].err[1]), twist,
               pct(b[3], p[k].err[2]));
}
