/* test_wind_vertical.c: the vertical turbulence component (gallop/loads/wind.h, windfield.h,
 * src/loads/turbulence.c): its target spectra (IEC 61400-1 Kaimal w, von Karman w) integrate to
 * sigma_w^2 with the stated length scales; the generated w's variance, Welch spectrum in octave
 * bands and co-coherence against the targets within sampling error; the scene's field (w
 * independent of u, on the same grid; off: no field, no term); w in the relative wind turns the
 * angle of attack by atan(w / U); the scene keys. */
#define _POSIX_C_SOURCE 200809L
#include "check.h"
#include "gallop.h"
#include "gallop/loads/windfield.h"

#include <unistd.h>

#include "welch.h"

static gal_wind_params wparams(gal_wind_spectrum s)
{
    gal_wind_params p;
    gal_wind_params_default(&p);
    p.speed = 10;
    p.intensity = 0.08;          /* sigma_w / U */
    p.spectrum = s;
    p.component = GAL_WIND_VERTICAL;
    return p;
}

/* integral of S(f) df = f S(f) d ln f from f0 to f1 (Hz) */
static double band(const gal_wind_params *p, double f0, double f1)
{
    double sum = 0, a = log(f0), b = log(f1);
    int n = 200000;
    double h = (b - a) / n;
    for (int i = 0; i < n; i++) {
        double f = exp(a + (i + 0.5) * h);
        sum += f * gal_wind_psd(p, f) * h;
    }
    return sum;
}

static double integral(const gal_wind_params *p) { return band(p, 1e-7, 1e4); }

/* the variance the discrete spectrum can carry: from 1 / T to the Nyquist frequency */
static double discrete_target(const gal_wind_params *p)
{
    return band(p, 1.0 / p->duration, 0.5 / p->time_step);
}

static void test_targets(void)
{
    gal_wind_spectrum kinds[] = {GAL_WIND_KAIMAL, GAL_WIND_DAVENPORT, GAL_WIND_VON_KARMAN,
                                 GAL_WIND_EN1991};
    for (int k = 0; k < 4; k++) {
        gal_wind_params p = wparams(kinds[k]);
        CHECK_REL(integral(&p), pow(p.intensity * p.speed, 2), 2e-3);
    }
    /* IEC 61400-1 Table C.1: L_w = 0.66 Lambda, Lambda = 0.7 z (z = 10 m: 4.62 m); von Karman:
     * L_u / 2 = 3.5 Lambda / 2 = 12.25 m */
    gal_wind_params p = wparams(GAL_WIND_KAIMAL);
    CHECK_NEAR(gal_wind_length_scale(&p), 4.62, 1e-12);
    CHECK_REL(gal_wind_psd(&p, 1e-9), 4 * 0.64 * 4.62 / 10, 1e-6);   /* f -> 0: 4 sigma^2 L / U */
    p.spectrum = GAL_WIND_VON_KARMAN;
    CHECK_NEAR(gal_wind_length_scale(&p), 12.25, 1e-12);
    CHECK_REL(gal_wind_psd(&p, 1e-9), 4 * 0.64 * 12.25 / 10, 1e-6);
    /* isotropy in the inertial range: with L_w = L_u / 2, f S_w / sigma^2 tends to (4/3) of the
     * along-wind form's 4 n_u / (1 + 70.8 n_u^2)^(5/6) at the same frequency */
    double f = 1e4, nu = f * 10 / 10, fu = 4 * nu / pow(1 + 70.8 * nu * nu, 5.0 / 6);
    p.length_scale = 5, p.speed = 10;                                /* L_u = 10 m, L_w = 5 m */
    double fw = f * gal_wind_psd(&p, f) / 0.64;
    CHECK_REL(fw / fu, 4.0 / 3.0, 1e-3);
    p.length_scale = 7;                                              /* the override */
    CHECK_NEAR(gal_wind_length_scale(&p), 7, 0);
    p.component = (gal_wind_component)5;
    CHECK(gal_wind_params_check(&p) == GAL_EINPUT && strstr(gal_error_message(), "component"),
          "bad component: %s", gal_error_message());
}

/* the generated w: variance and octave-band spectrum against the target */
static void test_generated_spectrum(void)
{
    gal_wind_spectrum kinds[] = {GAL_WIND_KAIMAL, GAL_WIND_VON_KARMAN};
    const char *names[] = {"Kaimal w", "von Karman w"};
    for (int k = 0; k < 2; k++) {
        gal_wind_params p = wparams(kinds[k]);
        p.points = 32;
        p.spacing = 100;          /* nearly independent points: more averages */
        p.time_step = 0.1;
        p.duration = 32768 * 0.1;
        p.seed = 21 + k;
        gal_wind *w = gal_wind_alloc(&p);
        CHECK(w != NULL, "%s", gal_error_message());
        if (!w) continue;
        CHECK(gal_wind_generate(w) == GAL_OK, "generate");
        long M = gal_wind_samples(w);
        double s2 = 0;
        for (int j = 0; j < p.points; j++)
            for (long i = 0; i < M; i++) s2 += pow(gal_wind_history(w, j)[i], 2);
        double sd = sqrt(s2 / ((double)M * p.points)), target = p.intensity * p.speed;
        printf("    %-12s std %.4f m/s, sigma_w %.4f (%+.2f%%), discrete %.4f (%+.2f%%)\n", names[k],
               sd, target, 100 * (sd / target - 1), sqrt(gal_wind_variance(w)),
               100 * (sd / sqrt(gal_wind_variance(w)) - 1));
        CHECK_REL(sd, sqrt(gal_wind_variance(w)), 0.01);   /* 32 x 3277 s of a ~0.4 Hz process */
        /* the discrete spectrum's variance is the target's between 1 / T and Nyquist (the
         * part above Nyquist, 17% of sigma_w^2 for Kaimal w here, is not represented) */
        CHECK_REL(gal_wind_variance(w), discrete_target(&p), 2e-3);
        welch W;
        welch_init(&W, 2048, 1.0 / p.time_step);
        double *pxx = calloc(W.nb, sizeof(double));
        int cnt = 0;
        for (int j = 0; j < p.points; j++) cnt += welch_acc(&W, gal_wind_history(w, j), NULL, M, pxx, NULL, NULL);
        double dfw = W.fs / W.nseg, worst = 0;
        for (double f0 = 4 * dfw; 2 * f0 <= 4.0; f0 *= 2) {   /* octaves 0.02 .. 4 Hz */
            double est = 0, tgt = 0;
            for (int b = 1; b < W.nb; b++) {
                double f = b * dfw;
                if (f < f0 || f >= 2 * f0) continue;
                est += pxx[b] / cnt, tgt += gal_wind_psd(&p, f);
            }
            double e = est / tgt - 1;
            if (fabs(e) > fabs(worst)) worst = e;
            /* 32 points x 31 segments x >= 4 bins: a few per cent of sampling error */
            CHECK(fabs(e) < 0.05, "%s: octave from %g Hz: estimate/target - 1 = %g", names[k], f0, e);
        }
        printf("    %-12s worst octave-band error %+.1f%%\n", names[k], 100 * worst);
        free(pxx);
        welch_free(&W);
        gal_wind_free(w);
    }
}

/* co-coherence of w at two separations against exp(-C_w f dx / U), C_w = 6 */
static void test_generated_coherence(void)
{
    gal_wind_params p = wparams(GAL_WIND_KAIMAL);
    p.points = 64, p.spacing = 4, p.coherence_decay = 6, p.time_step = 0.1;
    p.duration = 16384 * 0.1, p.seed = 9;
    gal_wind *w = gal_wind_alloc(&p);
    CHECK(w != NULL, "%s", gal_error_message());
    if (!w) return;
    gal_wind_generate(w);
    welch W;
    welch_init(&W, 1024, 1.0 / p.time_step);
    for (int s = 1; s <= 3; s += 2) {
        double *pxx = calloc(W.nb, sizeof(double)), *pyy = calloc(W.nb, sizeof(double)),
               *pxy = calloc(W.nb, sizeof(double));
        for (int j = 0; j + s < p.points; j++)
            welch_acc(&W, gal_wind_history(w, j), gal_wind_history(w, j + s), gal_wind_samples(w), pxx, pyy, pxy);
        double dfw = W.fs / W.nseg, worst = 0, dx = s * p.spacing;
        for (double f0 = 4 * dfw; 2 * f0 <= 2.0; f0 *= 2) {
            double sxx = 0, syy = 0, sxy = 0, tgt = 0;
            int nb = 0;
            for (int b = 1; b < W.nb; b++) {
                double f = b * dfw;
                if (f < f0 || f >= 2 * f0) continue;
                sxx += pxx[b], syy += pyy[b], sxy += pxy[b], tgt += gal_wind_coherence(&p, f, dx), nb++;
            }
            double e = sxy / sqrt(sxx * syy) - tgt / nb;
            if (fabs(e) > fabs(worst)) worst = e;
            CHECK(fabs(e) < 0.05, "dx = %g m, octave from %g Hz: error %g", dx, f0, e);
        }
        printf("    w coherence at dx = %g m: worst band error %+.3f (absolute)\n", dx, worst);
        free(pxx), free(pyy), free(pxy);
    }
    welch_free(&W);
    gal_wind_free(w);
}

static char dir[64];

static int load(gal_scene *sc, const char *text)
{
    char *p = gal_path_join(dir, "s.ini");
    FILE *fp = fopen(p, "wb");
    if (fp) fputs(text, fp), fclose(fp);
    int st = gal_scene_load(sc, p, NULL, 0, "data/conductors.csv");
    free(p);
    return st;
}

#define SCENE "[span]\nlength = 200\nhorizontal_tension = 20000\n[conductor]\nname = Drake\n" \
              "[simulation]\nduration = 60\n[wind]\nspeed = 12\nturbulence = kaimal\nintensity = 0.12\n"

/* the scene's field: w beside u on the same grid, independent of it, with the scene's sigma_w;
 * off: no w, no term */
static void test_scene_field(void)
{
    gal_scene sc;
    CHECK(load(&sc, SCENE) == GAL_OK, "%s", gal_error_message());
    gal_loads L = {.speed = 12, .dir = {0, 1, 0}};
    double *u = NULL;
    CHECK(gal_windfield_sample(&sc, &L, &u) == GAL_OK, "%s", gal_error_message());
    CHECK(L.u && !L.w, "vertical off: no w field");
    gal_loads_list ls;
    gal_loads_list_make(&L, &ls);
    for (int k = 0; k < ls.nwind; k++) CHECK(ls.wind[k]->vertical == NULL, "a vertical term when off");
    double *u_off = malloc((size_t)L.nx * L.nt * sizeof(double));
    memcpy(u_off, u, (size_t)L.nx * L.nt * sizeof(double));
    free(u);
    CHECK(load(&sc, SCENE "vertical_turbulence = on\n") == GAL_OK, "%s", gal_error_message());
    CHECK_NEAR(sc.wind.vertical_intensity, 0.06, 1e-15);       /* 0.5 sigma_u / U */
    CHECK_NEAR(sc.wind.vertical_coherence_decay, 10, 0);
    gal_loads Lv = {.speed = 12, .dir = {0, 1, 0}};
    CHECK(gal_windfield_sample(&sc, &Lv, &u) == GAL_OK, "%s", gal_error_message());
    CHECK(Lv.w != NULL && Lv.nx == L.nx && Lv.nt == L.nt, "w on the grid of u");
    if (!Lv.w) { free(u), free(u_off); return; }
    size_t n = (size_t)Lv.nx * Lv.nt;
    CHECK(!memcmp(u_off, Lv.u, n * sizeof(double)), "u unchanged by switching w on");
    double suw = 0, suu = 0, sww = 0;
    for (size_t i = 0; i < n; i++) suw += Lv.u[i] * Lv.w[i], suu += Lv.u[i] * Lv.u[i], sww += Lv.w[i] * Lv.w[i];
    double r = suw / sqrt(suu * sww), sdw = sqrt(sww / n);
    gal_wind_params p;
    CHECK(gal_windfield_params_vertical(&sc, &p) == GAL_OK, "%s", gal_error_message());
    double tgt = sqrt(discrete_target(&p));
    printf("    scene field: sigma_w %.4f m/s (target %.4f below Nyquist, 0.72 in all), corr(u, w) "
           "%+.3f\n", sdw, tgt, r);
    /* 85 points x 61 s, the points 2.4 m apart (U / (C 0.5 Hz)): a short record, ~10% sampling error; u and w
     * independent: |r| small */
    CHECK_REL(sdw, tgt, 0.1);
    CHECK(fabs(r) < 0.1, "u and w correlated: %g", r);
    gal_loads_list_make(&Lv, &ls);
    CHECK(ls.nwind == 3 && ls.wind[2] == &gal_loads_term_vertical_turbulence, "w term listed");
    free(u), free(u_off);
}

/* w in the relative wind: at rest the section sees U along y and w up, so alpha = atan2(w, U);
 * the load equals the section load at that relative wind */
static void test_angle_of_attack(void)
{
    gal_aero_table *t = gal_aero_table_load("data/aero/iced_d_shape.csv");
    CHECK(t != NULL, "%s", gal_error_message());
    if (!t) return;
    double u[2 * 2] = {0.5, 0.5, 0.5, 0.5}, w[2 * 2] = {1.0, 2.0, 3.0, 4.0};
    gal_loads L = {.table = t, .flags = GAL_AERO_ALL, .rho = 1.25, .diam = 0.03, .speed = 10,
                   .dir = {0, 1, 0}, .nx = 2, .nt = 2, .dx = 100, .dt = 1, .u = u, .w = w};
    double wind[3];
    /* linear in x (1.5, 3.5 at x = 50), Catmull-Rom in t through the periodic record
     * 3.5, 1.5 | 3.5, 1.5 at a = 0.25: weights (-0.0703125, 0.8671875, 0.2265625, -0.0234375) */
    gal_loads_wind(&L, 0.25, 50, wind);
    double wz = -0.0703125 * 3.5 + 0.8671875 * 1.5 + 0.2265625 * 3.5 - 0.0234375 * 1.5;
    CHECK_NEAR(wz, 1.8125, 1e-15);
    CHECK_NEAR(wind[2], wz, 1e-12);
    CHECK_NEAR(wind[1], 10.5, 1e-12);
    double tan[3] = {1, 0, 0}, d1[3] = {0, 1, 0}, r[3] = {0}, rd[3] = {0}, f[3], m, fr[3], mr;
    CHECK_NEAR(gal_aero_alpha(tan, d1, wind), atan2(wz, 10.5), 1e-12);
    CHECK(gal_loads_point(&L, 0.25, 50, r, rd, tan, d1, f, &m) == GAL_OK, "point");
    CHECK(gal_aero_load(t, tan, d1, wind, 1.25, 0.03, GAL_AERO_ALL, fr, &mr) == GAL_OK, "load");
    for (int k = 0; k < 3; k++) CHECK_NEAR(f[k], fr[k], 1e-12 * (1 + fabs(fr[k])));
    CHECK_NEAR(m, mr, 1e-15);
    /* the reversed wind keeps w up */
    L.reverse_time = 0.1;
    gal_loads_wind(&L, 0.25, 50, wind);
    CHECK(wind[1] < 0 && wind[2] > 0, "reversal: %g, %g", wind[1], wind[2]);
    gal_aero_table_free(t);
}

static void test_scene_keys(void)
{
    gal_scene sc;
    const char *noturb = "[span]\nlength = 200\nhorizontal_tension = 20000\n[conductor]\nname = Drake\n"
                         "[wind]\nspeed = 12\nvertical_turbulence = on\n";
    CHECK(load(&sc, noturb) == GAL_EINPUT && strstr(gal_error_message(), "turbulence"),
          "on without a field: %s", gal_error_message());
    CHECK(load(&sc, SCENE "vertical_intensity = 0.05\n") == GAL_EINPUT &&
          strstr(gal_error_message(), "vertical_intensity"), "a w key while off: %s", gal_error_message());
    CHECK(load(&sc, SCENE "vertical_turbulence = on\nvertical_intensity = 0.05\nvertical_length_scale = 3\n"
                    "vertical_coherence_decay = 7\n") == GAL_OK, "%s", gal_error_message());
    gal_wind_params p;
    CHECK(gal_windfield_params_vertical(&sc, &p) == GAL_OK, "%s", gal_error_message());
    CHECK(p.component == GAL_WIND_VERTICAL && p.intensity == 0.05 && p.length_scale == 3 &&
          p.coherence_decay == 7 && p.seed != 1, "w parameters from the scene");
    CHECK(load(&sc, SCENE "vertical_turbulence = on\nvertical_intensity = 1.5\n") == GAL_EINPUT,
          "out of range");
}

int main(void)
{
    strcpy(dir, "/tmp/gallop_wvert_XXXXXX");
    if (!mkdtemp(dir)) return 1;
    RUN(test_targets);
    RUN(test_generated_spectrum);
    RUN(test_generated_coherence);
    RUN(test_scene_field);
    RUN(test_angle_of_attack);
    RUN(test_scene_keys);
    char *p = gal_path_join(dir, "s.ini");
    unlink(p), free(p), rmdir(dir);
    return CHECK_SUMMARY();
}
