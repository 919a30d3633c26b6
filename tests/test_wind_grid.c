/* test_wind_grid.c: the scene's turbulent field as the loads see it (windfield.h, turbulence.c):
 * points a physical spacing apart, the same wind at the same point whatever the mesh (40, 80 and
 * 160 elements, bit for bit) and on the common part of two spans, the field's sigma at the grid,
 * the Catmull-Rom time interpolation exact at the samples, C1 between them and flat in gain up to
 * 1 Hz (linear interpolation loses 2.5% of the power there). */
#define _POSIX_C_SOURCE 200809L
#include "check.h"
#include "gallop.h"

#include <fftw3.h>
#include <unistd.h>

static char dir[64];

static int load(gal_scene *sc, const char *text, const char *const *ov, int nov)
{
    char *p = gal_path_join(dir, "s.ini");
    FILE *fp = fopen(p, "wb");
    if (fp) fputs(text, fp), fclose(fp);
    int st = gal_scene_load(sc, p, ov, nov, "data/conductors.csv");
    free(p);
    return st;
}

#define SCENE(len, dur)                                                                                  \
    "[span]\nlength = " len "\nhorizontal_tension = 20000\n[conductor]\nname = Drake\n[simulation]\n" \
    "duration = " dur "\n[wind]\nspeed = 12\nturbulence = kaimal\nintensity = 0.12\nseed = 5\n"

/* dx = U / (C f_c), clamped */
static void test_spacing_rule(void)
{
    gal_scene sc;
    CHECK(load(&sc, SCENE("200", "60"), NULL, 0) == GAL_OK, "%s", gal_error_message());
    CHECK_NEAR(gal_windfield_spacing(&sc), 12.0 / (10 * GAL_WINDFIELD_FREQUENCY), 1e-15);
    gal_wind_params p;
    CHECK(gal_windfield_params(&sc, &p) == GAL_OK, "%s", gal_error_message());
    CHECK(p.points == 85 && (p.points - 1) * p.spacing >= 200 && (p.points - 2) * p.spacing < 200,
          "85 points cover 200 m: %d x %g m", p.points, p.spacing);
    sc.wind.speed = 30;
    CHECK_NEAR(gal_windfield_spacing(&sc), GAL_WINDFIELD_SPACING_MAX, 0);
    sc.wind.speed = 2;
    CHECK_NEAR(gal_windfield_spacing(&sc), GAL_WINDFIELD_SPACING_MIN, 0);
    sc.wind.coherence_decay = 0; /* full coherence: any spacing is exact */
    CHECK_NEAR(gal_windfield_spacing(&sc), GAL_WINDFIELD_SPACING_MAX, 0);
}

/* the loads of the shipped turbulent scene at 40, 80 and 160 elements: the same wind at every
 * (t, x), bit for bit */
static void test_same_wind_any_mesh(void)
{
    const int ne[3] = {40, 80, 160};
    double ref[41 * 21][3];
    for (int i = 0; i < 3; i++) {
        char el[64];
        snprintf(el, sizeof el, "model.elements=%d", ne[i]);
        const char *ov[2] = {el, "simulation.duration=20"};
        gal_scene sc;
        int st = gal_scene_load(&sc, "data/scenes/iced_gallop_turbulent.ini", ov, 2, "data/conductors.csv");
        CHECK(st == GAL_OK, "%s", gal_error_message());
        gal_model *m = st ? NULL : gal_model_alloc(&sc, &st);
        gal_data *d = m ? gal_data_alloc(m) : NULL;
        CHECK(d && gal_forward(m, d, GAL_STAGE_WIND) == GAL_OK, "%s", gal_error_message());
        if (!d || !d->loads.u) { gal_data_free(d), gal_model_free(m); continue; }
        CHECK_NEAR(d->loads.dx, gal_windfield_spacing(&sc), 0);
        int same = 1, n = 0;
        for (int a = 0; a <= 40; a++)
            for (int b = 0; b <= 20; b++, n++) {
                double t = 0.37 * a, x = 10.0 * b - 0.3 * (b == 20), w[3];
                gal_loads_wind(&d->loads, t, x, w);
                if (i == 0) memcpy(ref[n], w, sizeof w);
                else same &= !memcmp(ref[n], w, sizeof w);
            }
        CHECK(same, "%d elements: another wind than at 40", ne[i]);
        gal_data_free(d);
        gal_model_free(m);
    }
}

/* a longer span: the same field on the common part (the phases drawn point by point from x = 0);
 * sigma of the field at its points against the discrete spectrum's */
static void test_common_part_and_sigma(void)
{
    gal_scene s1, s2;
    CHECK(load(&s1, SCENE("200", "300"), NULL, 0) == GAL_OK, "%s", gal_error_message());
    CHECK(load(&s2, SCENE("260", "300"), NULL, 0) == GAL_OK, "%s", gal_error_message());
    gal_loads L1 = {.speed = 12, .dir = {0, 1, 0}}, L2 = L1;
    double *u1 = NULL, *u2 = NULL;
    CHECK(gal_windfield_sample(&s1, &L1, &u1) == GAL_OK, "%s", gal_error_message());
    CHECK(gal_windfield_sample(&s2, &L2, &u2) == GAL_OK, "%s", gal_error_message());
    if (!u1 || !u2) { free(u1), free(u2); return; }
    CHECK(L1.nt == L2.nt && L2.nx > L1.nx && L1.dx == L2.dx, "grids %d/%d x %d", L1.nx, L2.nx, L1.nt);
    int same = 1;
    for (int k = 0; k < L1.nt; k++)
        same &= !memcmp(u1 + (size_t)k * L1.nx, u2 + (size_t)k * L2.nx, (size_t)L1.nx * sizeof(double));
    CHECK(same, "the 200 m span's field differs from the first 200 m of the 260 m span's");
    gal_wind_params p;
    gal_windfield_params(&s1, &p);
    gal_wind *w = gal_wind_alloc(&p);
    double s = 0;
    size_t n = (size_t)L1.nx * L1.nt;
    for (size_t i = 0; i < n; i++) s += u1[i] * u1[i];
    double sd = sqrt(s / n), tgt = sqrt(gal_wind_variance(w));
    printf("    sigma_u at the %d points: %.4f m/s, discrete target %.4f\n", L1.nx, sd, tgt);
    CHECK_REL(sd, tgt, 0.1); /* 301 s: the sampling error of the low frequencies, ~5% */
    gal_wind_free(w);
    free(u1), free(u2);
}

/* Catmull-Rom in time: the samples exactly, the derivative continuous across a sample, the
 * midpoints' spectrum equal to the samples' within 0.5% up to 1 Hz */
static void test_time_interpolation(void)
{
    gal_scene sc;
    CHECK(load(&sc, SCENE("200", "200"), NULL, 0) == GAL_OK, "%s", gal_error_message());
    gal_loads L = {.speed = 12, .dir = {0, 1, 0}};
    double *u = NULL;
    CHECK(gal_windfield_sample(&sc, &L, &u) == GAL_OK, "%s", gal_error_message());
    if (!u) return;
    int j = 40, nt = L.nt;
    double x = j * L.dx, w[3], worst = 0, jump = 0, slope = 0;
    for (int k = 0; k < nt; k++) {
        gal_loads_wind(&L, k * L.dt, x, w);
        worst = fmax(worst, fabs(w[1] - 12 - u[(size_t)k * L.nx + j]));
    }
    CHECK(worst < 1e-12, "not the sample at the samples: %g", worst);
    for (int k = 1; k < nt - 1; k++) { /* one-sided slopes at each sample, h = 1e-4 dt */
        double h = 1e-4 * L.dt, wl[3], wr[3], w0[3];
        gal_loads_wind(&L, k * L.dt - h, x, wl);
        gal_loads_wind(&L, k * L.dt, x, w0);
        gal_loads_wind(&L, k * L.dt + h, x, wr);
        double sl = (w0[1] - wl[1]) / h, sr = (wr[1] - w0[1]) / h;
        jump = fmax(jump, fabs(sr - sl)), slope = fmax(slope, fabs(sl));
    }
    printf("    largest slope jump at a sample %.3g of slopes up to %.3g m/s^2\n", jump, slope);
    CHECK(jump < 1e-3 * slope, "a kink at a sample: %g", jump);
    double *a = fftw_malloc(sizeof(double) * nt), *b = fftw_malloc(sizeof(double) * nt);
    fftw_complex *A = fftw_malloc(sizeof(fftw_complex) * (nt / 2 + 1)), *B = fftw_malloc(sizeof(fftw_complex) * (nt / 2 + 1));
    for (int k = 0; k < nt; k++) {
        a[k] = u[(size_t)k * L.nx + j];
        gal_loads_wind(&L, (k + 0.5) * L.dt, x, w);
        b[k] = w[1] - 12;
    }
    fftw_plan pa = fftw_plan_dft_r2c_1d(nt, a, A, FFTW_ESTIMATE), pb = fftw_plan_dft_r2c_1d(nt, b, B, FFTW_ESTIMATE);
    fftw_execute(pa), fftw_execute(pb);
    double df = 1.0 / (nt * L.dt), gain_worst = 0;
    for (double f0 = 0.0625; f0 < 1.0; f0 *= 2) { /* octave bands to 1 Hz */
        double pa_ = 0, pb_ = 0;
        for (int m = (int)ceil(f0 / df); m * df < 2 * f0 && m <= nt / 2; m++) {
            pa_ += A[m][0] * A[m][0] + A[m][1] * A[m][1];
            pb_ += B[m][0] * B[m][0] + B[m][1] * B[m][1];
        }
        gain_worst = fmax(gain_worst, fabs(pb_ / pa_ - 1));
    }
    printf("    midpoints' power against the samples' to 1 Hz: worst band %+.4f\n", gain_worst);
    CHECK(gain_worst < 0.005, "the interpolation filters the field below 1 Hz: %g", gain_worst);
    fftw_destroy_plan(pa), fftw_destroy_plan(pb);
    fftw_free(a), fftw_free(b), fftw_free(A), fftw_free(B);
    free(u);
}

int main(void)
{
    strcpy(dir, "/tmp/gallop_wgrid_XXXXXX");
    if (!mkdtemp(dir)) return 1;
    RUN(test_spacing_rule);
    RUN(test_same_wind_any_mesh);
    RUN(test_common_part_and_sigma);
    RUN(test_time_interpolation);
    char *p = gal_path_join(dir, "s.ini");
    unlink(p), free(p), rmdir(dir);
    return CHECK_SUMMARY();
}
