/* test_aero.c: coefficient tables (parsing, periodic splines, derivatives), the quasi-steady load
 * and its derivative (paper Eq. 10), the Den Hartog coefficient, bad and junk tables. */
#define _POSIX_C_SOURCE 200809L
#include "check.h"
#include "gallop.h"

#include <gsl/gsl_interp.h>
#include <math.h>
#include <unistd.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif
#define DEG (M_PI / 180.0)

static char tmpdir[64];

/* A small irregular table made from arrays (angles in degrees, span < 360). */
static gal_aero_table *irregular_table(void)
{
    double a[] = {-170, -100, -45, -10, 0, 15, 40, 90, 130, 175};
    double cd[10], cl[10], cm[10];
    for (int k = 0; k < 10; k++) {
        cd[k] = 1.1 + 0.3 * sin(a[k] * DEG) + 0.1 * cos(3 * a[k] * DEG);
        cl[k] = 0.7 * sin(2 * a[k] * DEG) - 0.2 * cos(a[k] * DEG);
        cm[k] = 0.05 * sin(a[k] * DEG + 0.3);
    }
    return gal_aero_table_make("irregular", "test", 10, a, cd, cl, cm);
}

static void test_nodes_exact(void)
{
    gal_aero_table *t = irregular_table();
    CHECK(t != NULL, "%s", gal_error_message());
    if (!t) return;
    CHECK(t->n == 11, "10 angles + closure, got %d", t->n);
    for (int k = 0; k < t->n; k++) {
        double c[3];
        gal_aero_eval(t, t->alpha[k], c, NULL);
        for (int i = 0; i < 3; i++) CHECK_NEAR(c[i], t->c[i][k], 1e-12);
    }
    gal_aero_table_free(t);
}

static void test_periodic_wrap(void)
{
    gal_aero_table *t = irregular_table();
    if (!t) return;
    for (double a = -7.0; a < 7.0; a += 0.37) {
        double c0[3], d0[3], c1[3], d1[3], c2[3], d2[3];
        gal_aero_eval(t, a, c0, d0);
        gal_aero_eval(t, a + 2 * M_PI, c1, d1);
        gal_aero_eval(t, a - 4 * M_PI, c2, d2);
        for (int i = 0; i < 3; i++) {
            CHECK_NEAR(c1[i], c0[i], 1e-12);
            CHECK_NEAR(c2[i], c0[i], 1e-12);
            CHECK_NEAR(d1[i], d0[i], 1e-10);
        }
    }
    /* value and slope continuous across the seam alpha_first (= alpha_last - 2 pi) */
    double a0 = t->alpha[0], e = 1e-7, cm[3], dm[3], cp[3], dp[3];
    gal_aero_eval(t, a0 - e, cm, dm);
    gal_aero_eval(t, a0 + e, cp, dp);
    for (int i = 0; i < 3; i++) {
        CHECK_NEAR(cm[i], cp[i], 1e-5);
        CHECK_NEAR(dm[i], dp[i], 1e-5);
    }
    gal_aero_table_free(t);
}

static void test_derivative_fd(void)
{
    gal_aero_table *t = irregular_table();
    if (!t) return;
    const double h = 1e-6;
    for (double a = -3.2; a < 3.2; a += 0.113) {
        double c[3], dc[3], cp[3], cm[3];
        gal_aero_eval(t, a, c, dc);
        gal_aero_eval(t, a + h, cp, NULL);
        gal_aero_eval(t, a - h, cm, NULL);
        for (int i = 0; i < 3; i++) CHECK_NEAR(dc[i], (cp[i] - cm[i]) / (2 * h), 1e-6);
    }
    gal_aero_table_free(t);
}

/* Constant coefficients C_D = 1, C_L = 0.5, C_M = 0.2. */
static gal_aero_table *constant_table(void)
{
    double a[] = {0, 90, 180, 270}, cd[] = {1, 1, 1, 1}, cl[] = {.5, .5, .5, .5},
           cm[] = {.2, .2, .2, .2};
    return gal_aero_table_make("constant", "test", 4, a, cd, cl, cm);
}

static void test_load_directions(void)
{
    gal_aero_table *t = constant_table();
    CHECK(t != NULL, "%s", gal_error_message());
    if (!t) return;
    const double tx[3] = {1, 0, 0}, y[3] = {0, 1, 0};
    const double rho = 1.25, d = 0.03, V = 10, q = 0.5 * rho * d * V * V;
    double f[3], m;
    /* wind along +y, t = +x, d1 = +y: alpha = 0, drag along +y, lift along +z, moment about +x */
    double w[3] = {0, V, 0};
    CHECK(gal_aero_load(t, tx, y, w, rho, d, GAL_AERO_ALL, f, &m) == GAL_OK, "load");
    CHECK_NEAR(f[0], 0, 1e-12);
    CHECK_NEAR(f[1], q * 1.0, 1e-12);
    CHECK_NEAR(f[2], q * 0.5, 1e-12);
    CHECK_NEAR(m, q * d * 0.2, 1e-12);
    CHECK_NEAR(gal_aero_alpha(tx, y, w), 0.0, 1e-15);
    /* the axial part of the wind does not count */
    double wa[3] = {7, V, 0}, fa[3], ma;
    gal_aero_load(t, tx, y, wa, rho, d, GAL_AERO_ALL, fa, &ma);
    for (int i = 0; i < 3; i++) CHECK_NEAR(fa[i], f[i], 1e-12);
    /* wind from below (as when the conductor moves down): alpha > 0 */
    double wb[3] = {0, V, 1};
    CHECK_NEAR(gal_aero_alpha(tx, y, wb), atan(0.1), 1e-15);
    /* drag along w, lift along t x w: rotate both by atan(0.1) */
    gal_aero_load(t, tx, y, wb, rho, d, GAL_AERO_ALL, fa, &ma);
    double Vb = sqrt(V * V + 1), qb = 0.5 * rho * d * Vb * Vb;
    CHECK_NEAR(fa[1], qb * (1.0 * V / Vb - 0.5 * 1 / Vb), 1e-12);
    CHECK_NEAR(fa[2], qb * (1.0 * 1 / Vb + 0.5 * V / Vb), 1e-12);
    /* twist the section by +theta about t: alpha = -theta */
    double th = 0.3, d1[3] = {0, cos(th), sin(th)};
    CHECK_NEAR(gal_aero_alpha(tx, d1, w), -th, 1e-15);
    /* flags: drag only, lift only */
    gal_aero_load(t, tx, y, w, rho, d, GAL_AERO_DRAG, fa, &ma);
    CHECK(fa[2] == 0 && ma == 0 && fabs(fa[1] - q) < 1e-12, "drag only");
    gal_aero_load(t, tx, y, w, rho, d, GAL_AERO_LIFT, fa, NULL);
    CHECK(fa[1] == 0 && fabs(fa[2] - 0.5 * q) < 1e-12, "lift only");
    /* zero relative wind (or purely axial): zero load, no NaN, zero derivative */
    double w0[3] = {0, 0, 0}, wx[3] = {3, 0, 0}, df[9], dm[3];
    CHECK(gal_aero_load_deriv(t, tx, y, w0, rho, d, GAL_AERO_ALL, fa, &ma, df, dm) == GAL_OK, "0");
    CHECK(fa[0] == 0 && fa[1] == 0 && fa[2] == 0 && ma == 0, "zero wind, zero load");
    for (int i = 0; i < 9; i++) CHECK(df[i] == 0, "zero derivative");
    gal_aero_load(t, tx, y, wx, rho, d, GAL_AERO_ALL, fa, &ma);
    CHECK(fa[0] == 0 && fa[1] == 0 && fa[2] == 0 && ma == 0, "axial wind, zero load");
    /* bad frames */
    CHECK(gal_aero_load(t, w0, y, w, rho, d, GAL_AERO_ALL, fa, &ma) == GAL_EINPUT, "zero tangent");
    CHECK(gal_aero_load(t, tx, tx, w, rho, d, GAL_AERO_ALL, fa, &ma) == GAL_EINPUT, "d1 // t");
    gal_aero_table_free(t);
}

static void test_load_derivative_fd(void)
{
    gal_aero_table *t = gal_aero_table_load("data/aero/iced_d_shape.csv");
    CHECK(t != NULL, "%s", gal_error_message());
    if (!t) return;
    srand(7);
    for (int trial = 0; trial < 50; trial++) {
        double tan[3], d1[3], w[3];
        for (int i = 0; i < 3; i++) {
            tan[i] = 2.0 * rand() / RAND_MAX - 1;
            d1[i] = 2.0 * rand() / RAND_MAX - 1;
            w[i] = 20.0 * rand() / RAND_MAX - 10;
        }
        tan[0] += 2; /* keep it away from zero */
        double f[3], m, df[9], dm[3];
        CHECK(gal_aero_load_deriv(t, tan, d1, w, 1.2, 0.04, GAL_AERO_ALL, f, &m, df, dm) == 0, "load");
        double scale = 0.5 * 1.2 * 0.04 * (1 + sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]));
        for (int j = 0; j < 3; j++) {
            double h = 1e-6, wp[3] = {w[0], w[1], w[2]}, wm[3] = {w[0], w[1], w[2]};
            wp[j] += h, wm[j] -= h;
            double fp[3], fm[3], mp, mm;
            gal_aero_load(t, tan, d1, wp, 1.2, 0.04, GAL_AERO_ALL, fp, &mp);
            gal_aero_load(t, tan, d1, wm, 1.2, 0.04, GAL_AERO_ALL, fm, &mm);
            for (int i = 0; i < 3; i++) CHECK_NEAR(df[3 * i + j], (fp[i] - fm[i]) / (2 * h), 1e-6 * scale);
            CHECK_NEAR(dm[j], (mp - mm) / (2 * h), 1e-6 * scale);
        }
    }
    gal_aero_table_free(t);
}

/* gal_aero_eval's one interval search for the three coefficients (a local accelerator) gives GSL's
 * own accelerator-free values, bit for bit, over several periods. */
static void test_eval_one_search(void)
{
    gal_aero_table *t = irregular_table();
    for (int k = 0; k <= 720; k++) {
        double al = -7.0 + 14.0 * k / 720, c[3], dc[3];
        gal_aero_eval(t, al, c, dc);
        double x = al - t->alpha[0];
        x -= 2 * M_PI * floor(x / (2 * M_PI));
        x += t->alpha[0];
        if (x > t->alpha[t->n - 1]) x = t->alpha[t->n - 1];
        for (int i = 0; i < 3; i++)
            CHECK(c[i] == gsl_interp_eval(t->spline[i], t->alpha, t->c[i], x, NULL) &&
                  dc[i] == gsl_interp_eval_deriv(t->spline[i], t->alpha, t->c[i], x, NULL),
                  "coefficient %d at %.4f rad: GSL's values", i, al);
    }
    gal_aero_table_free(t);
}

static void test_den_hartog(void)
{
    /* Parkinson & Smith (1964): C_Fy = A1 tan a - ..., C_Fy = -(C_L + C_D tan a) sec a, so
     * dC_Fy/da(0) = -(dC_L/da + C_D) = A1: H(0) = -A1 = -2.69 per rad. */
    gal_aero_table *sq = gal_aero_table_load("data/aero/square_parkinson_smith.csv");
    CHECK(sq != NULL, "%s", gal_error_message());
    if (sq) {
        CHECK_REL(gal_aero_den_hartog(sq, 0.0), -2.69, 0.01);
        printf("    square prism: H(0) = %.5f per rad (Parkinson & Smith: -A1 = -2.69)\n",
               gal_aero_den_hartog(sq, 0.0));
        double c[3], dc[3];
        gal_aero_eval(sq, 0.0, c, dc);
        CHECK_NEAR(c[0], 2.0, 1e-9);              /* C_D face-on */
        CHECK_REL(dc[1], -2.69 - 2.0, 0.01);       /* dC_L/dalpha = -A1 - C_D(0) */
        gal_aero_eval(sq, M_PI / 2, c, dc);        /* the square's 90-degree symmetry */
        CHECK_REL(gal_aero_den_hartog(sq, M_PI / 2), -2.69, 0.01);
        gal_aero_table_free(sq);
    }
    gal_aero_table *bare = gal_aero_table_load("data/aero/bare.csv");
    CHECK(bare != NULL, "%s", gal_error_message());
    if (bare) {
        for (double a = -3; a < 3; a += 0.5) CHECK_NEAR(gal_aero_den_hartog(bare, a), 1.1, 1e-12);
        gal_aero_table_free(bare);
    }
    gal_aero_table *ds = gal_aero_table_load("data/aero/iced_d_shape.csv");
    CHECK(ds != NULL, "%s", gal_error_message());
    if (ds) {
        for (double a = 0; a <= 40; a += 5)
            CHECK(gal_aero_den_hartog(ds, a * DEG) < 0, "D-shape H(%g deg) = %g", a,
                  gal_aero_den_hartog(ds, a * DEG));
        /* the linearised aerodynamic damping of a vertical motion in a horizontal wind is
         * c_zz = +df_zz = 1/2 rho U d H(alpha): negative where Den Hartog says galloping */
        const double tx[3] = {1, 0, 0};
        for (double a = -30; a <= 60; a += 15) {
            double d1[3] = {0, cos(-a * DEG), sin(-a * DEG)}, w[3] = {0, 12, 0}, df[9];
            gal_aero_load_deriv(ds, tx, d1, w, 1.25, 0.03, GAL_AERO_ALL, NULL, NULL, df, NULL);
            CHECK_NEAR(gal_aero_alpha(tx, d1, w), a * DEG, 1e-12);
            CHECK_REL(df[8], 0.5 * 1.25 * 12 * 0.03 * gal_aero_den_hartog(ds, a * DEG), 1e-9);
        }
        gal_aero_table_free(ds);
    }
    gal_aero_table *cr = gal_aero_table_load("data/aero/iced_crescent.csv");
    CHECK(cr != NULL, "%s", gal_error_message());
    cr = gal_aero_table_free(cr);
}

/* Each interval's cubic formed once (gal_aero_table.poly) is in use and gives GSL's spline values
 * and slopes bit for bit: at every node and at 20000 random angles over three periods, on the
 * irregular table, the shipped ones and one with a coefficient zero throughout. */
static void check_cubics(gal_aero_table *t, const char *name)
{
    CHECK(t && t->poly != NULL, "%s: the cubics are formed (GSL's numbers at the build's check points)", name);
    if (!t || !t->poly) return;
    unsigned long long s = 99;
    int bad = 0;
    for (int k = 0; k < 20000 + t->n; k++) {
        double al;
        if (k < t->n) al = t->alpha[k];
        else {
            s ^= s >> 12, s ^= s << 25, s ^= s >> 27;
            al = -3 * M_PI + 6 * M_PI * (((s * 2685821657736338717ULL) >> 11) * (1.0 / 9007199254740992.0));
        }
        double c[3], dc[3], c1[3];
        gal_aero_eval(t, al, c, dc);
        gal_aero_eval(t, al, c1, NULL);
        double x = al - t->alpha[0];
        x -= 2 * M_PI * floor(x / (2 * M_PI));
        x += t->alpha[0];
        if (x < t->alpha[0]) x = t->alpha[0];
        if (x > t->alpha[t->n - 1]) x = t->alpha[t->n - 1];
        for (int i = 0; i < 3; i++)
            bad += !(c[i] == gsl_interp_eval(t->spline[i], t->alpha, t->c[i], x, NULL) && c1[i] == c[i] &&
                     dc[i] == gsl_interp_eval_deriv(t->spline[i], t->alpha, t->c[i], x, NULL) &&
                     signbit(c[i]) == signbit(gsl_interp_eval(t->spline[i], t->alpha, t->c[i], x, NULL)));
    }
    CHECK(bad == 0, "%s: %d values or slopes differ from GSL's", name, bad);
}

static void test_eval_cubics(void)
{
    gal_aero_table *t = irregular_table();
    check_cubics(t, "irregular");
    gal_aero_table_free(t);
    const char *names[] = {"bare", "square_parkinson_smith", "iced_d_shape", "iced_crescent"};
    for (int k = 0; k < 4; k++) {
        char p[256];
        snprintf(p, sizeof p, "data/aero/%s.csv", names[k]);
        t = gal_aero_table_load(p);
        check_cubics(t, p);
        gal_aero_table_free(t);
    }
    double a[] = {-120, -30, 0, 45, 100}, cd[] = {1, 1.2, 1.1, 0.9, 1}, cl[] = {0.1, -0.2, 0, 0.3, 0.2}, cm[5] = {0};
    t = gal_aero_table_make("flat moment", "test", 5, a, cd, cl, cm);
    check_cubics(t, "flat moment");
    gal_aero_table_free(t);
}

static void test_shipped_tables(void)
{
    const char *names[] = {"bare", "square_parkinson_smith", "iced_d_shape", "iced_crescent"};
    for (int k = 0; k < 4; k++) {
        char p[256];
        snprintf(p, sizeof p, "data/aero/%s.csv", names[k]);
        gal_aero_table *t = gal_aero_table_load(p);
        CHECK(t != NULL, "%s", gal_error_message());
        if (!t) continue;
        CHECK(t->source && strlen(t->source) > 20, "%s: source", p);
        for (double a = -M_PI; a < M_PI; a += 0.01) {
            double c[3];
            gal_aero_eval(t, a, c, NULL);
            CHECK(c[0] > 0, "%s: C_D(%g) = %g must be positive", p, a, c[0]);
        }
        gal_aero_table_free(t);
    }
}

/* ---- bad tables ---- */

static char *write_tmp(const char *name, const char *text, size_t len)
{
    char *p = gal_path_join(tmpdir, name);
    FILE *fp = fopen(p, "wb");
    if (!len) len = strlen(text);
    if (fp) {
        fwrite(text, 1, len, fp);
        fclose(fp);
    }
    return p;
}

#define SRC "# source: test\nalpha_deg,cd,cl,cm\n"

static void test_bad_tables(void)
{
    struct {
        const char *text;
        const char *line; /* ":<line>" expected in the message */
        const char *what; /* a word expected in the message */
    } bad[] = {
        {"alpha_deg,cd,cl,cm\n0,1,0,0\n90,1,0,0\n180,1,0,0\n270,1,0,0\n", ":1", "source"},
        {"# source: x\n0,1,0,0\n", ":2", "header"},
        {"# source: x\nalpha,cd,cl,cm\n0,1,0,0\n", ":2", "header"},
        {"# source:   \nalpha_deg,cd,cl,cm\n", ":1", "source"},
        {SRC "0,1,0,0\n90,1,0,0\n80,1,0,0\n270,1,0,0\n", ":5", "increasing"},
        {SRC "0,1,0,0\n90,1,0,0\n90,1,0,0\n270,1,0,0\n", ":5", "duplicates"},
        {SRC "0,1,0,0\n90,nan,0,0\n180,1,0,0\n270,1,0,0\n", ":4", "finite"},
        {SRC "0,1,0,0\n90,1,inf,0\n180,1,0,0\n270,1,0,0\n", ":4", "finite"},
        {SRC "0,1,0,0\n90,1,0\n180,1,0,0\n270,1,0,0\n", ":4", "column"},
        {SRC "0,1,0,0\n90,1,,0\n180,1,0,0\n270,1,0,0\n", ":4", "missing"},
        {SRC "0,1,0,0\n90,1,0,0,5\n180,1,0,0\n270,1,0,0\n", ":4", "extra"},
        {SRC "0,1,0,0\n90,1,0,0\n180,1,0,0\n", ":", "at least 4"},
        {SRC "0,1,0,0\n120,1,0,0\n240,1,0,0\n360,1,0,0\n", ":", "at least 4"},
        {SRC "0,1,0,0\n90,12,0,0\n180,1,0,0\n270,1,0,0\n", ":4", "range"},
        {SRC "0,1,0,0\n90,1,0,-10.5\n180,1,0,0\n270,1,0,0\n", ":4", "range"},
        {SRC "0,1,0,0\n90,1,0,0\n180,1,0,0\n270,1,0,0\n361,1,0,0\n", ":7", "360"},
        {SRC "0,1,0,0\n90,1,0,0\n180,1,0,0\n270,1,0,0\n360,1.1,0,0\n", ":7", "closure"},
        {SRC "0,1,0,0\n90,1x,0,0\n180,1,0,0\n270,1,0,0\n", ":4", "not a number"},
        {SRC "0,1,0,0\n1e5,1,0,0\n", ":4", "range"},
        {"", ":", "header"},
        {SRC, ":", "at least 4"},
    };
    int nbad = (int)(sizeof bad / sizeof bad[0]);
    for (int k = 0; k < nbad; k++) {
        char name[32];
        snprintf(name, sizeof name, "bad%02d.csv", k);
        char *p = write_tmp(name, bad[k].text, 0);
        gal_aero_table *t = (gal_aero_table *)1;
        int st = gal_aero_table_read(p, &t);
        const char *msg = gal_error_message();
        CHECK(st == GAL_EINPUT && t == NULL, "case %d: status %d", k, st);
        char want[600];
        snprintf(want, sizeof want, "%s%s", p, bad[k].line);
        CHECK(strstr(msg, want) != NULL, "case %d: message must name %s: %s", k, want, msg);
        CHECK(strstr(msg, bad[k].what) != NULL, "case %d: message must say '%s': %s", k,
              bad[k].what, msg);
        remove(p);
        free(p);
    }
    /* the column is named: file:line:column */
    char *p = write_tmp("col.csv", SRC "0,1,0,0\n90,  1,0.5,99\n180,1,0,0\n270,1,0,0\n", 0);
    gal_aero_table *t;
    gal_aero_table_read(p, &t);
    CHECK(strstr(gal_error_message(), ":4:12:") != NULL, "column: %s", gal_error_message());
    remove(p);
    free(p);
    /* a NUL byte */
    p = write_tmp("nul.csv", SRC "0,1,0,0\n9\0,1,0,0\n", sizeof(SRC "0,1,0,0\n9\0,1,0,0\n") - 1);
    CHECK(gal_aero_table_read(p, &t) == GAL_EINPUT, "NUL byte");
    remove(p);
    free(p);
    /* an unreadable file */
    CHECK(gal_aero_table_read("/nonexistent/x.csv", &t) == GAL_EIO && !t, "missing file");
    CHECK(strstr(gal_error_message(), "/nonexistent/x.csv") != NULL, "%s", gal_error_message());
    /* good variants: closure given, comments and blank lines anywhere, CRLF, spaces */
    p = write_tmp("good.csv", "# source: a\r\n# source: b\r\n\r\n alpha_deg , cd,cl ,cm\r\n"
                  "# c\r\n-90,1,0.1,0\r\n0,1.2,0,0\r\n\r\n90,1,-0.1,0\r\n180,0.9,0,0.01\r\n"
                  "270,1,0.1,0\r\n", 0);
    t = gal_aero_table_load(p);
    CHECK(t != NULL, "%s", gal_error_message());
    if (t) {
        CHECK(t->n == 5 && !strcmp(t->source, "a; b"), "n %d source '%s'", t->n, t->source);
        t = gal_aero_table_free(t);
    }
    remove(p);
    free(p);
}

/* ---- junk: ~1000 mutated and random files never crash; a table that loads evaluates finite ---- */
static void test_fuzz(void)
{
    const char *base = "# source: fuzz\nalpha_deg,cd,cl,cm\n-180,1.2,0.1,0.01\n-90,1.0,-0.3,0\n"
                       "-30,1.1,0.5,-0.02\n0,1.3,0.2,0\n45,0.9,-0.4,0.03\n120,1.0,0.0,0\n"
                       "180,1.2,0.1,0.01\n";
    const char *tokens[] = {",", "\n", "#", "nan", "inf", "-", "1e999", "1e-320", "0x1p3", " ",
                            "\r", "360", "9", "0", ".", "e", "alpha_deg,cd,cl,cm\n", "# source:"};
    int ntok = (int)(sizeof tokens / sizeof tokens[0]);
    char buf[4096];
    unsigned seed = 12345;
    int loaded = 0;
    char *p = gal_path_join(tmpdir, "fuzz.csv");
    for (int trial = 0; trial < 1000; trial++) {
        size_t len = strlen(base);
        memcpy(buf, base, len);
        int nmut = 1 + rand_r(&seed) % 6;
        for (int k = 0; k < nmut; k++) {
            int kind = rand_r(&seed) % 5;
            size_t pos = len ? (size_t)rand_r(&seed) % len : 0;
            if (kind == 0 && len) buf[pos] = (char)(rand_r(&seed) % 256);         /* flip */
            else if (kind == 1 && len) memmove(buf + pos, buf + pos + 1, len - pos - 1), len--;
            else if (kind == 2) {                                                 /* insert */
                const char *s = tokens[rand_r(&seed) % ntok];
                size_t n = strlen(s);
                if (len + n < sizeof buf) {
                    memmove(buf + pos + n, buf + pos, len - pos);
                    memcpy(buf + pos, s, n);
                    len += n;
                }
            } else if (kind == 3) len = pos;                                      /* truncate */
            else if (len + 64 < sizeof buf)                                       /* random junk */
                for (int i = 0; i < 64; i++) buf[len++] = (char)(rand_r(&seed) % 256);
        }
        FILE *fp = fopen(p, "wb");
        if (!fp) break;
        fwrite(buf, 1, len, fp);
        fclose(fp);
        gal_aero_table *t = NULL;
        int st = gal_aero_table_read(p, &t);
        CHECK((st == GAL_OK) == (t != NULL), "status %d", st);
        CHECK(st == GAL_OK || st == GAL_EINPUT, "status %d: %s", st, gal_error_message());
        if (t) {
            loaded++;
            for (double a = -10; a < 10; a += 0.7) {
                double c[3], dc[3];
                gal_aero_eval(t, a, c, dc);
                for (int i = 0; i < 3; i++) CHECK(isfinite(c[i]) && isfinite(dc[i]), "finite");
            }
            gal_aero_table_free(t);
        }
    }
    printf("    fuzz: %d of 1000 mutated tables loaded, the rest were rejected\n", loaded);
    remove(p);
    free(p);
}

/* issue 14: the interpolant is checked between rows, not only at them: two close rows with
 * different values make the periodic spline overshoot (C_D of 1.5e4 here); a steep but smooth
 * table passes; a jump of 1 in C_L over 0.5 deg exceeds the slope bound. The message names the
 * two rows where the bound is exceeded most. */
static void test_interpolant_bounds(void)
{
    double a[5] = {-180, -90, 0, 0.001, 90}, cd[5] = {1, 1, 1, 2, 1}, z[5] = {0, 0, 0, 0, 0};
    gal_aero_table *t = gal_aero_table_make("close", "test", 5, a, cd, z, z);
    CHECK(t == NULL, "two rows 0.001 deg apart with C_D 1 and 2 accepted");
    const char *msg = gal_error_message();
    CHECK(strstr(msg, "close: row 4 and close: row 5") != NULL, "names the rows: %s", msg);
    CHECK(strstr(msg, "periodic spline of cd") != NULL, "names the coefficient: %s", msg);
    gal_aero_table_free(t);
    /* the same shape with the rows far enough apart stays within the bounds */
    double a2[5] = {-180, -90, 0, 45, 90};
    t = gal_aero_table_make("spread", "test", 5, a2, cd, z, z);
    CHECK(t != NULL, "%s", gal_error_message());
    gal_aero_table_free(t);
    /* a slope of 2 per degree (115 per rad) with values within |c| <= 10 */
    double a3[8] = {-180, -120, -60, 0, 0.5, 60, 120, 179}, cl[8] = {0, 0, 0, 0, 1, 1, 1, 0};
    double d3[8] = {1, 1, 1, 1, 1, 1, 1, 1}, z3[8] = {0};
    t = gal_aero_table_make("steep", "test", 8, a3, d3, cl, z3);
    CHECK(t == NULL, "a slope of 115 per rad accepted");
    msg = gal_error_message();
    CHECK(strstr(msg, "dcl/dalpha") != NULL || strstr(msg, "cl =") != NULL, "%s", msg);
    gal_aero_table_free(t);
    /* the shipped tables' splines stay far inside both bounds (checked when loaded) */
    for (int i = 0; i < 3; i++) {
        const char *f[3] = {"data/aero/iced_d_shape.csv", "data/aero/iced_crescent.csv",
                            "data/aero/square_parkinson_smith.csv"};
        t = gal_aero_table_load(f[i]);
        CHECK(t != NULL, "%s: %s", f[i], gal_error_message());
        gal_aero_table_free(t);
    }
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/gallop_aero_XXXXXX");
    if (!mkdtemp(tmpdir)) return 1;
    RUN(test_nodes_exact);
    RUN(test_periodic_wrap);
    RUN(test_derivative_fd);
    RUN(test_load_directions);
    RUN(test_load_derivative_fd);
    RUN(test_eval_one_search);
    RUN(test_eval_cubics);
    RUN(test_den_hartog);
    RUN(test_shipped_tables);
    RUN(test_interpolant_bounds);
    RUN(test_bad_tables);
    RUN(test_fuzz);
    rmdir(tmpdir);
    return CHECK_SUMMARY();
}
