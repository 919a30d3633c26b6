/* cli/accuracy.c: `gallop accuracy SCENE [-o DIR] [--set s.k=v]... [--tolerance E] [--study NAME]...
 * [--budget S] [--seeds N] [--levels N]`
 * (issue 7): what accuracy costs in time for the user's own span: accuracy.csv, summary.json and
 * a table on stdout (DESIGN.md "Command line"). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "gallop.h"
#include "gallop/analysis/accuracy.h"
#include "gallop/output/accreport.h"
#include "gallop/scene/scene.h"

static int bad(const char *what, const char *arg)
{
    fprintf(stderr, "gallop accuracy: %s%s%s\n", what, arg ? " " : "", arg ? arg : "");
    gal_cli_usage(stderr, gal_cli_command_find("accuracy"));
    return 2;
}

/* NAME or a comma list of names into the study mask */
static int add_studies(const char *list, unsigned *mask)
{
    char buf[256];
    if (strlen(list) >= sizeof buf) return bad("--study: too long:", list);
    strcpy(buf, list);
    for (char *save = NULL, *t = strtok_r(buf, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        int k = -1;
        if (!strcmp(t, "tolerance"))
            return bad("--study tolerance: no longer a study: it swept simulation.tolerance, which no integrator "
                       "reads since both models take fixed steps (the key is refused too); what replaced it: "
                       "the front study (the default) and --study time_step measure the error of the step, and --study "
                       "newton_tolerance (and the front's newton_tolerance rows) that of simulation.newton_tolerance, "
                       "the implicit step's Newton tolerance", NULL);
        for (int s = 0; s < GAL_ACC_NSTUDY; s++)
            if (!strcmp(t, gal_acc_study_names[s])) k = s;
        if (k < 0) return bad("--study: unknown study", t);
        *mask |= 1u << k;
    }
    return 0;
}

/* a number option in [lo, hi] into *v (untouched when absent) */
static int num_option(const gal_cli_command *c, const gal_cli_args *a, const char *name, double lo, double hi,
                      double *v)
{
    const char *s = gal_cli_value(c, a, name);
    if (!s) return 0;
    char *end, msg[128];
    double x = strtod(s, &end);
    if (end == s || *end || !(x >= lo && x <= hi)) {
        snprintf(msg, sizeof msg, "--%s: want a number in [%g, %g], got", name, lo, hi);
        return bad(msg, s);
    }
    *v = x;
    return 0;
}

/* --study NAME..., --tolerance E, --budget S, --seeds N, --levels N into the options */
static int own_options(const gal_cli_command *c, const gal_cli_args *a, gal_acc_opts *o)
{
    unsigned mask = 0;
    const char *const *st;
    int n = gal_cli_values(c, a, "study", &st);
    for (int i = 0; i < n; i++) {
        int rc = add_studies(st[i], &mask);
        if (rc) return rc;
    }
    if (mask) o->studies = mask;
    const char *v = gal_cli_value(c, a, "tolerance");
    if (v) {
        char *end;
        o->tolerance = strtod(v, &end);
        if (end == v || *end || !(o->tolerance > 0 && o->tolerance < 1))
            return bad("--tolerance: want a relative error in (0, 1), got", v);
    }
    double seeds = o->seeds, levels = o->max_levels;
    int rc = num_option(c, a, "budget", 0, 1e7, &o->budget_s);
    if (!rc) rc = num_option(c, a, "seeds", 1, 64, &seeds);
    if (!rc) rc = num_option(c, a, "levels", 1, 8, &levels);
    if (!rc && (seeds != (int)seeds || levels != (int)levels)) rc = bad("--seeds and --levels want whole numbers", NULL);
    o->seeds = (int)seeds, o->max_levels = (int)levels;
    return rc;
}

int gal_cli_accuracy(int argc, char **argv)
{
    gal_acc_opts o;
    gal_accuracy_default_opts(&o);
    const gal_cli_command *c = gal_cli_command_find("accuracy");
    gal_cli_args args;
    int rc = gal_cli_parse(c, argc, argv, &args);
    if (!rc) rc = own_options(c, &args, &o);
    if (rc) return rc;
    o.progress = isatty(2) || o.budget_s > 0; /* a long study says where it is */
    gal_scene sc;
    const char *outdir = NULL;
    rc = gal_cli_scene(c, &args, &sc, &outdir);
    if (rc) return rc;
    gal_acc_result r;
    int st = gal_accuracy_run(&sc, &o, &r);
    if (!st) {
        gal_accuracy_print(stdout, &r);
        st = gal_accuracy_write(outdir, &sc, &r);
        if (!st) printf("files: %s/{accuracy.csv,%ssummary.json}\n", outdir,
                        r.study[GAL_ACC_FRONT].ran ? "front.csv," : "");
    }
    if (st) fprintf(stderr, "gallop accuracy: %s\n", gal_error_message());
    gal_accuracy_clear(&r);
    return gal_exit_code(st);
}
