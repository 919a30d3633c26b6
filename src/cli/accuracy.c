/* cli/accuracy.c: `gallop accuracy SCENE [-o DIR] [--set s.k=v]... [--tolerance E] [--study NAME]...`
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
        for (int s = 0; s < GAL_ACC_NSTUDY; s++)
            if (!strcmp(t, gal_acc_study_names[s])) k = s;
        if (k < 0) return bad("--study: unknown study", t);
        *mask |= 1u << k;
    }
    return 0;
}

/* --study NAME... and --tolerance E into the options */
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
    return 0;
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
    o.progress = isatty(2);
    gal_scene sc;
    const char *outdir = NULL;
    rc = gal_cli_scene(c, &args, &sc, &outdir);
    if (rc) return rc;
    gal_acc_result r;
    int st = gal_accuracy_run(&sc, &o, &r);
    if (!st) {
        gal_accuracy_print(stdout, &r);
        st = gal_accuracy_write(outdir, &sc, &r);
        if (!st) printf("files: %s/{accuracy.csv,summary.json}\n", outdir);
    }
    if (st) fprintf(stderr, "gallop accuracy: %s\n", gal_error_message());
    gal_accuracy_clear(&r);
    return gal_exit_code(st);
}
