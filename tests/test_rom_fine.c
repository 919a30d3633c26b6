/* test_rom_fine.c: the reduced model holds on a fine mesh: data/scenes/iced_gallop.ini at 600
 * elements, 300 s, gallops as at 80 (the full model gives 6.964 m vertical, 0.785 m horizontal,
 * 18.3 deg twist peak to peak at 200, 600, 900 and 1000 elements). Before Newton every step became
 * the default (o.one_pass = 0, rom.h) the 600-element run finished valid with the twist at
 * 54.6 deg, 3x, in bursts between the self-check's instants. Before a growth added the tripping
 * family's correction alone (rom.h gal_rom_residual_family) it grew twice and rang a 1.3-1.6 deg
 * twist line at 6.38 Hz, 19% off in twist, valid (BENCHMARKS.md, issue 13, helper line; the family
 * split itself: test_rom_line.c). */
#include "check.h"
#include "gallop.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"

/* |DFT| (Hann) of the twist at probe 0 over the samples from t0, its largest in [lo, hi] Hz */
static double twist_line(const gal_sim_result *r, double t0, double lo, double hi)
{
    long i0 = 0;
    while (i0 < r->nsamples && r->time[i0] < t0) i0++;
    long n = r->nsamples - i0;
    int st = 4 * r->nprobe;
    double mean = 0, best = 0;
    for (long i = 0; i < n; i++) mean += r->trace[(i0 + i) * st + 3] / n;
    for (double f = lo; f <= hi; f += 0.25 / (n * r->dt_out)) {
        double re = 0, im = 0, ws = 0;
        for (long i = 0; i < n; i++) {
            double w = 0.5 - 0.5 * cos(2 * GAL_PI * i / (n - 1)), a = 2 * GAL_PI * f * i * r->dt_out;
            double x = r->trace[(i0 + i) * st + 3] - mean;
            re += w * x * cos(a), im += w * x * sin(a), ws += w;
        }
        best = fmax(best, 2 * sqrt(re * re + im * im) / ws);
    }
    return best;
}

/* The reduced run of iced_gallop at `elements` for 300 s, measured over the last 60 s as `gallop
 * compare` measures against the reference *h (detect: this run is it, and sets *h), its twist line
 * in 5.5-7.5 Hz over 240-300 s (deg) and its growths; 0 on success. */
static int reduced_run(int elements, gal_compare_ref *h, int detect, gal_sim_measures *ms, int *valid, double *line,
                       int *growths)
{
    char e[64];
    snprintf(e, sizeof e, "model.elements=%d", elements);
    const char *ov[] = {e, "simulation.duration=300"};
    gal_scene sc;
    gal_sim_setup s;
    int st = gal_scene_load(&sc, "data/scenes/iced_gallop.ini", ov, 2, "data/conductors.csv");
    if (!st) st = gal_sim_setup_init(&s, &sc, 1);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    if (st) return st;
    gal_sim_result res;
    memset(&res, 0, sizeof res);
    st = gal_sim_run(&s, GAL_MODEL_REDUCED, &res);
    CHECK(st == GAL_OK, "%d elements: %s", elements, gal_error_message());
    if (!st) {
        *valid = res.checked && res.valid;
        *line = twist_line(&res, 240, 5.5, 7.5), *growths = res.growths;
        if (detect) st = gal_compare_reference(&res, 240.0, h);
        if (!st) st = gal_compare_measure(&res, h, ms);
        CHECK(st == GAL_OK, "%s", gal_error_message());
        gal_sim_result_clear(&res);
    }
    gal_sim_setup_clear(&s);
    return st;
}

/* 600 elements against 80: the same orbit (index 0 horizontal, 1 vertical, 3 twist), checked. */
static void test_fine_mesh_agrees(void)
{
    gal_sim_measures a, b;
    int va = 0, vb = 0, ga = 0, gb = 0;
    double la = 0, lb = 0;
    gal_compare_ref h;
    if (reduced_run(80, &h, 1, &a, &va, &la, &ga) || reduced_run(600, &h, 0, &b, &vb, &lb, &gb)) return;
    printf("    80/600 elements: vertical %.3f/%.3f m, horizontal %.4f/%.4f m, twist %.2f/%.2f deg, the 5.5-7.5 Hz "
           "twist line %.2g/%.2g deg, growths %d/%d\n", a.peak_to_peak[1], b.peak_to_peak[1], a.peak_to_peak[0],
           b.peak_to_peak[0], a.peak_to_peak[3], b.peak_to_peak[3], la, lb, ga, gb);
    CHECK(va && vb, "valid: %d at 80, %d at 600", va, vb);
    CHECK_REL(b.peak_to_peak[1], a.peak_to_peak[1], 2e-2);
    CHECK_REL(b.peak_to_peak[0], a.peak_to_peak[0], 5e-2);
    CHECK_REL(b.peak_to_peak[3], a.peak_to_peak[3], 0.05);
    CHECK(lb < 0.05, "600 elements: a twist line of %g deg at 5.5-7.5 Hz (the full model: 5e-5)", lb);
    CHECK(gb == 1, "600 elements: %d growths (the start-up's on the mean twist alone)", gb);
}

int main(void)
{
    RUN(test_fine_mesh_agrees);
    return CHECK_SUMMARY();
}
