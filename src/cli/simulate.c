/* cli/simulate.c: `gallop simulate SCENE [--model reduced|full] [-o DIR] [--set s.k=v]...` and
 * `gallop compare SCENE [-o DIR]` (issues 5, 6): the pipeline to the start of a run, then a run by
 * either integrator: trace.csv and summary.json; both integrators on the same model and data (the
 * same equilibrium, loads and wind), compare.csv and summary.json. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "gallop.h"
#include "gallop/bundle/bundle.h"
#include "gallop/model/model.h"
#include "gallop/run/forward.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"
#include "gallop/output/simreport.h"

static int fail(const char *cmd, int st)
{
    fprintf(stderr, "gallop %s: %s\n", cmd, gal_error_message());
    return gal_exit_code(st);
}

static void print_run(const char *label, const gal_sim_result *r, const gal_sim_measures *m)
{
    printf("%-8s wall %8.3f s (%.4f s per simulated s)  vertical p-p %.4g m at %.4g Hz, horizontal p-p %.4g m, "
           "twist p-p %.3g deg, steady after %.1f s\n", label, r->wall_time_s,
           r->wall_time_s / r->time[r->nsamples - 1], m->peak_to_peak[1], m->frequency_hz[1],
           m->peak_to_peak[0], m->peak_to_peak[3], m->time_to_steady_s);
}

/* A reduced run that finished past its residual tolerance (model.on_invalid = warn) says so. */
static void warn_invalid(const char *cmd, const gal_scene *sc, const gal_sim_result *r)
{
    if (r->checked && !r->valid && r->invalid_why[0])
        fprintf(stderr, "gallop %s: warning: %s: its results are not checked (summary.json: valid: false)\n", cmd,
                r->invalid_why);
    else if (r->checked && !r->valid)
        fprintf(stderr, "gallop %s: warning: the reduced model's residual reached %.3g, past model.residual_tolerance "
                "= %.3g: its results are not checked (summary.json: valid: false)\n", cmd, r->residual_max,
                sc->model.residual_tolerance);
}

/* A reduced run whose basis grew says so: how far, when last and in what family; a basis twice its
 * start or more costs several times as much a step (BENCHMARKS.md: the third-order set 17-21x), which
 * the engineer should weigh against the full model's time. */
static void note_growth(const char *cmd, const gal_sim_result *r)
{
    if (!r->checked || r->growths <= 0) return;
    const gal_rom_event *e = &r->growth[r->growths - 1];
    fprintf(stderr, "gallop %s: note: the reduced basis grew from %d to %d vectors in %d growth%s (the last at %.4g s, "
            "%s family; summary.json: basis_growths)%s\n", cmd, r->basis_start, r->basis, r->growths,
            r->growths > 1 ? "s" : "", e->t_s, gal_family_names[e->family],
            r->basis >= 2 * r->basis_start ? "; a step of a basis this large costs several times the initial one's: "
                                             "weigh the run's time against the full model's (--model full)" : "");
}

/* The full model's results alone, when the reduced model of `compare` failed; exit 1. */
static int compare_full_only(const char *outdir, const gal_scene *sc, const gal_sim_result *full)
{
    char why[1024];
    snprintf(why, sizeof why, "%s", gal_error_message());
    int st = gal_sim_write(outdir, sc, full);
    if (st) return fail("compare", st);
    fprintf(stderr, "gallop compare: the reduced model failed: %s\ngallop compare: the full model's results are "
            "written alone: %s/{trace.csv,summary.json}\n", why, outdir);
    return 1;
}

/* An equivalent bundle galloping at f Hz outside its measured domain says so
 * (gal_bundle_equivalent_outside). */
static void warn_domain(const char *cmd, const gal_scene *sc, const gal_data *d, double f)
{
    char msg[640];
    if (gal_bundle_equivalent_outside(sc, &d->md, f, msg, sizeof msg))
        fprintf(stderr, "gallop %s: warning: %s\n", cmd, msg);
}

/* The scene's model and its data forwarded to the start of a run. */
static int setup(const gal_scene *sc, gal_model **m, gal_data **d)
{
    int st;
    *d = NULL;
    if (!(*m = gal_model_alloc(sc, &st))) return st;
    if (!(*d = gal_data_alloc(*m))) return GAL_ENOMEM;
    return gal_forward(*m, *d, GAL_STAGE_START);
}

int gal_cli_simulate(int argc, char **argv)
{
    gal_scene sc;
    const char *outdir = NULL, *vals[1] = {NULL};
    static const char *const opts[] = {"--model", NULL};
    int rc = gal_cli_load_scene_opts(argc, argv, &sc, &outdir, opts, vals);
    if (rc) return rc;
    const gal_integrator_type *T = &gal_integrator_reduced; /* the default */
    if (vals[0]) {
        if (!strcmp(vals[0], "full")) T = &gal_integrator_full;
        else if (strcmp(vals[0], "reduced")) {
            fprintf(stderr, "gallop simulate: --model %s; allowed: reduced, full\n", vals[0]);
            return 2;
        }
    }
    if (sc.bundle.subconductors > 1 && sc.bundle.explicit_model)
        return gal_cli_simulate_bundle(&sc, outdir, T == &gal_integrator_reduced);
    gal_model *m;
    gal_data *d;
    gal_run_opts o;
    gal_run_opts_from_scene(&sc, &o);
    gal_sim_result r;
    memset(&r, 0, sizeof r);
    int st = setup(&sc, &m, &d);
    if (!st) st = gal_run_check_measurable(m, d, &o); /* before the run */
    if (!st) st = gal_run(m, d, T, &o, &r);
    gal_sim_measures ms;
    if (!st) st = gal_sim_write_measured(outdir, &sc, &r, &ms); /* and the mid-span measures */
    if (!st) {
        print_run(T->name, &r, &ms);
        printf("files: %s/{trace.csv,summary.json}\n", outdir);
        warn_invalid("simulate", &sc, &r);
        note_growth("simulate", &r);
        warn_domain("simulate", &sc, d, ms.frequency_hz[1]);
    }
    gal_sim_result_clear(&r);
    gal_data_free(d);
    gal_model_free(m);
    return st ? fail("simulate", st) : 0;
}

int gal_cli_compare(int argc, char **argv)
{
    gal_scene sc;
    const char *outdir = NULL;
    int rc = gal_cli_load_scene(argc, argv, &sc, &outdir);
    if (rc) return rc;
    if (sc.bundle.subconductors > 1 && sc.bundle.explicit_model) return gal_cli_compare_bundle(&sc, outdir);
    gal_model *m;
    gal_data *d;
    gal_run_opts o;
    gal_run_opts_from_scene(&sc, &o);
    gal_sim_result full, red;
    memset(&full, 0, sizeof full);
    memset(&red, 0, sizeof red);
    int st = setup(&sc, &m, &d);
    if (!st) st = gal_run_check_measurable(m, d, &o); /* before the runs */
    if (!st) st = gal_run(m, d, &gal_integrator_full, &o, &full);
    int red_failed = 0;
    if (!st && (red_failed = gal_run(m, d, &gal_integrator_reduced, &o, &red)) != GAL_OK) {
        rc = compare_full_only(outdir, &sc, &full);
        st = -1;
    }
    gal_compare_figures c;
    if (!st) st = gal_sim_write_compare(outdir, &sc, &full, &red, &c);
    if (!st) {
        print_run("full", &full, &c.full);
        print_run("reduced", &red, &c.reduced);
        gal_cli_print_compare(&c, "twist", red.build_time_s);
        printf("files: %s/{compare.csv,summary.json}\n", outdir);
        warn_invalid("compare", &sc, &red);
        note_growth("compare", &red);
        warn_domain("compare", &sc, d, c.full.frequency_hz[1]);
    }
    gal_sim_result_clear(&full);
    gal_sim_result_clear(&red);
    gal_data_free(d);
    gal_model_free(m);
    if (red_failed) return rc;
    return st ? fail("compare", st) : 0;
}
