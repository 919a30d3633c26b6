/* test_rom_spans.c: the short spans of tests/rom/ (those whose header says "short: make check")
 * through the recomputed reduced model against the full model on the same set-up, wind and steady
 * window (the full run's, at most its last half), measured as `gallop compare` measures (each family
 * at the probe where the full model moves most: gal_compare_reference), with issue 13's figures: dominant frequency
 * within 1%, vertical and horizontal peak-to-peak within 5% (horizontal: or 2% of the vertical
 * where it is small), twist within 5% or 3 deg, largest support tension over the window within 5%,
 * and the self-check valid. The long spans are measured by tests/bench/bench_rom.c (make bench). */
#include <glob.h>

#include "check.h"
#include "gallop.h"
#include "gallop/reduced/rom_sim.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"

/* 1 when the scene's header comment says "short: make check" */
static int is_short(const char *path)
{
    FILE *fp = fopen(path, "r");
    char line[256];
    int yes = 0;
    while (fp && fgets(line, sizeof line, fp) && line[0] == ';')
        if (strstr(line, "short: make check")) yes = 1;
    if (fp) fclose(fp);
    return yes;
}

/* The figures on one span; the full model's window must be a steady one (it settled in
 * the first three quarters of the run). */
static void one_span(const char *path, const char **ov, int nov, int growths_min)
{
    gal_scene sc;
    if (gal_scene_load(&sc, path, ov, nov, "data/conductors.csv")) {
        CHECK(0, "%s: %s", path, gal_error_message());
        return;
    }
    gal_sim_setup s;
    if (gal_sim_setup_init(&s, &sc, 1)) {
        CHECK(0, "%s: %s", path, gal_error_message());
        return;
    }
    gal_sim_result rf, rr;
    gal_rom_sim_info info;
    int sf = gal_sim_run(&s, GAL_MODEL_FULL, &rf);
    CHECK(sf == GAL_OK, "%s: full: %s", path, gal_error_message());
    int sr = sf ? 1 : gal_rom_sim_run(&s, NULL, &rr, &info);
    CHECK(sr == GAL_OK, "%s: reduced: %s", path, gal_error_message());
    if (!sf && !sr) {
        /* measured as `gallop compare` measures (compare.h): each family at the probe where the full
         * model moves most, over its window */
        gal_compare_ref h;
        gal_sim_measures mf, mr;
        CHECK(gal_compare_reference(&rf, -1, &h) == GAL_OK, "%s", gal_error_message());
        double dur = rf.time[rf.nsamples - 1], settled = h.from;
        if (settled < 0.5 * dur) h.from = 0.5 * dur; /* at most the last half */
        CHECK(gal_compare_measure(&rf, &h, &mf) == GAL_OK && gal_compare_measure(&rr, &h, &mr) == GAL_OK, "%s",
              gal_error_message());
        printf("    %s: steady from %.0f s, probes %g/%g/%g; reduced/full: f %.4f/%.4f Hz, vertical %.3f/%.3f m, "
               "horizontal %.3f/%.3f m, twist %.1f/%.1f deg, T %.0f/%.0f N; residual %.3f, basis %d\n",
               path, mf.steady_from_s, h.position[0], h.position[1], h.position[2], mr.frequency_hz[1],
               mf.frequency_hz[1], mr.peak_to_peak[1], mf.peak_to_peak[1],
               mr.peak_to_peak[0], mf.peak_to_peak[0], mr.peak_to_peak[3], mf.peak_to_peak[3], mr.tension_max_steady,
               mf.tension_max_steady, info.residual_max, info.basis);
        CHECK(settled > 0 && settled <= 0.75 * dur, "%s: the full model is not steady (from %g of %g s)", path, settled, dur);
        CHECK(mf.peak_to_peak[1] > 0.1, "%s: no galloping (vertical p-p %g m)", path, mf.peak_to_peak[1]);
        CHECK_REL(mr.frequency_hz[1], mf.frequency_hz[1], 1e-2);
        CHECK_REL(mr.peak_to_peak[1], mf.peak_to_peak[1], 5e-2);
        CHECK_NEAR(mr.peak_to_peak[0], mf.peak_to_peak[0], fmax(5e-2 * mf.peak_to_peak[0], 2e-2 * mf.peak_to_peak[1]));
        CHECK_NEAR(mr.peak_to_peak[3], mf.peak_to_peak[3], fmax(5e-2 * mf.peak_to_peak[3], 3.0));
        CHECK_REL(mr.tension_max_steady, mf.tension_max_steady, 5e-2);
        CHECK(info.valid && info.residual_max <= sc.model.residual_tolerance, "%s: residual %g, valid %d", path,
              info.residual_max, info.valid);
        CHECK(info.nevents >= growths_min, "%s: %d growths, at least %d", path, info.nevents, growths_min);
    }
    if (!sf) gal_sim_result_clear(&rf);
    if (!sr) gal_sim_result_clear(&rr);
    gal_sim_setup_clear(&s);
}

static int nargs;
static char **args;

/* the short spans of tests/rom/, or the scenes on the command line (test_rom_spans SCENE...) */
static void test_short_spans(void)
{
    glob_t g = {0};
    int n = 0;
    if (nargs)
        for (int k = 0; k < nargs; k++) one_span(args[k], NULL, 0, 0), n++;
    else if (glob("tests/rom/*.ini", 0, NULL, &g) == 0)
        for (size_t k = 0; k < g.gl_pathc; k++)
            if (is_short(g.gl_pathv[k])) one_span(g.gl_pathv[k], NULL, 0, 0), n++;
    globfree(&g);
    CHECK(n >= (nargs ? 1 : 2), "%d short spans in tests/rom/", n);
}

/* The known miss of the check before the twist had its own norm (BENCHMARKS.md): the shipped
 * scene at 40 elements with one torsional mode, whose twist is a 5:1 resonance with the galloping
 * (26.8 deg against 19.1, 40% off, at residual 0.084 under 0.1, valid). Now caught, grown, in
 * agreement. */
static void test_known_miss(void)
{
    if (nargs) return;
    const char *ov[] = {"model.elements=40", "model.modes_torsional=1", "simulation.duration=600"};
    one_span("data/scenes/iced_gallop.ini", ov, 3, 1);
}

int main(int argc, char **argv)
{
    nargs = argc - 1, args = argv + 1;
    RUN(test_short_spans);
    RUN(test_known_miss);
    return CHECK_SUMMARY();
}
