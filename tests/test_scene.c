/* test_scene.c: scene files (src/scene/): defaults, conductor table, units, --set, one test per
 * class of error (status, file, line and key in the message), print/load round trip, junk input. */
#include "check.h"
#include "gallop.h"
#include "gallop/scene/scene.h"

#include <stdint.h>
#include <unistd.h>

#define PI 3.14159265358979323846

static char dir[64];
static char csv[256];

/* Write `text` to dir/name; returns a malloc'ed path. */
static char *put(const char *name, const char *text)
{
    char *p = gal_path_join(dir, name);
    FILE *fp = fopen(p, "wb");
    if (fp) {
        fputs(text, fp);
        fclose(fp);
    }
    return p;
}

/* The 1-based line of the first line of `text` that contains `marker`. */
static int line_of(const char *text, const char *marker)
{
    const char *m = strstr(text, marker);
    int line = 1;
    if (!m) return -1;
    for (const char *p = text; p < m; p++) line += *p == '\n';
    return line;
}

static const char *BASE = "[span]\n"
                          "length = 200\n"
                          "horizontal_tension = 20000\n"
                          "[conductor]\n"
                          "diameter = 0.03\n"
                          "mass_per_length = 1.5\n"
                          "axial_stiffness = 3e7\n"
                          "bending_stiffness = 40\n"
                          "torsional_stiffness = 200\n";

static int load_text(gal_scene *sc, const char *name, const char *text, const char *const *sets,
                     int n)
{
    char *p = put(name, text);
    int st = gal_scene_load(sc, p, sets, n, csv);
    free(p);
    return st;
}

/* Load BASE + extra; expect GAL_EINPUT naming the file, the line of `marker` (0: none) and `key`. */
static void expect_error(const char *extra, const char *marker, const char *key)
{
    char text[4096];
    snprintf(text, sizeof text, "%s%s", BASE, extra);
    gal_scene sc;
    char *p = put("err.ini", text);
    int st = gal_scene_load(&sc, p, NULL, 0, csv);
    const char *msg = gal_error_message();
    CHECK(st == GAL_EINPUT, "status %d for [%s], message %s", st, extra, msg);
    CHECK(strstr(msg, p) == msg, "message names the file first: %s", msg);
    if (marker) {
        char at[64];
        snprintf(at, sizeof at, "%s:%d: ", p, line_of(text, marker));
        CHECK(strstr(msg, at) == msg, "message starts with '%s': %s", at, msg);
    }
    CHECK(strstr(msg, key) != NULL, "message names '%s': %s", key, msg);
    CHECK(strstr(msg, "allowed") != NULL, "message says what is allowed: %s", msg);
    free(p);
}

static void test_defaults(void)
{
    gal_scene sc;
    int st = load_text(&sc, "base.ini", BASE, NULL, 0);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    CHECK(!strcmp(sc.name, "base"), "name %s", sc.name);
    CHECK(!strcmp(sc.output.directory, "out/base"), "directory %s", sc.output.directory);
    CHECK_NEAR(sc.span.length, 200, 0);
    CHECK_NEAR(sc.span.height_difference, 0, 0);
    CHECK(sc.span.spec == GAL_SPEC_TENSION, "spec");
    CHECK_NEAR(sc.span.horizontal_tension, 20000, 0);
    CHECK(sc.span.end_twist == GAL_TWIST_CLAMPED, "end twist");
    CHECK(sc.conductor.name[0] == '\0', "no name");
    CHECK_REL(sc.conductor.polar_inertia, 1.5 * 0.03 * 0.03 / 8, 1e-15);
    CHECK_NEAR(sc.conductor.damping_ratio, 0, 0);
    CHECK(!sc.ice.present, "no ice");
    CHECK_NEAR(sc.wind.speed, 0, 0);
    CHECK_NEAR(sc.wind.yaw, PI / 2, 1e-15);
    CHECK_NEAR(sc.wind.air_density, 1.225, 0);
    CHECK(sc.wind.turbulence == GAL_TURB_NONE, "turbulence");
    CHECK_NEAR(sc.wind.intensity, 0.1, 0);
    CHECK_NEAR(sc.wind.coherence_decay, 10, 0);
    CHECK(sc.wind.seed == 1, "seed");
    int want[GAL_FX_COUNT] = {1, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0};
    for (int i = 0; i < GAL_FX_COUNT; i++)
        CHECK(sc.effect[i] == want[i], "effect %s = %d", gal_effect_names[i], sc.effect[i]);
    CHECK(sc.model.elements == 100, "elements");
    CHECK(sc.model.modes_vertical == 3 && sc.model.modes_horizontal == 2 &&
              sc.model.modes_torsional == 2, "modes");
    CHECK_NEAR(sc.simulation.duration, 60, 0);
    CHECK_NEAR(sc.simulation.time_step, 0, 0);
    CHECK(sc.simulation.nprobes == 1 && sc.simulation.probes[0] == 0.5, "probes");
}

static void test_syntax_variants(void)
{
    /* comments, inline comments, indentation, ':' separator, CRLF, BOM, no final newline */
    const char *text = "\xEF\xBB\xBF# a comment\r\n"
                       "; another\r\n"
                       "  [span]   ; section comment\r\n"
                       "    length = 250 ; m\r\n"
                       "\thorizontal_tension: 30000\r\n"
                       "[conductor]\n"
                       "diameter = 0.03\n"
                       "mass_per_length = 1.5\n"
                       "axial_stiffness = 3e7\n"
                       "bending_stiffness = 40\n"
                       "[effects]\n"
                       "bending = NO\n"
                       "torsion = true\n"
                       "[conductor]\n"
                       "torsional_stiffness = 200";
    gal_scene sc;
    int st = load_text(&sc, "variants.ini", text, NULL, 0);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    CHECK_NEAR(sc.span.length, 250, 0);
    CHECK_NEAR(sc.span.horizontal_tension, 30000, 0);
    CHECK(sc.effect[GAL_FX_BENDING] == 0 && sc.effect[GAL_FX_TORSION] == 1, "effects");
}

static void test_conductor_by_name(void)
{
    /* the override comes before the name: order does not matter; names match in any case */
    const char *text = "[conductor]\n"
                       "diameter = 0.031\n"
                       "name = testcond\n"
                       "[span]\n"
                       "length = 300\n"
                       "sag = 6\n";
    gal_scene sc;
    int st = load_text(&sc, "named.ini", text, NULL, 0);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    CHECK(!strcmp(sc.conductor.name, "TestCond"), "canonical name %s", sc.conductor.name);
    CHECK_NEAR(sc.conductor.diameter, 0.031, 0);
    CHECK_NEAR(sc.conductor.mass_per_length, 1.3, 0);
    CHECK_NEAR(sc.conductor.axial_stiffness, 3e7, 0);
    CHECK_NEAR(sc.conductor.bending_stiffness, 30, 0);
    CHECK_NEAR(sc.conductor.torsional_stiffness, 150, 0);
    CHECK_NEAR(sc.conductor.polar_inertia, 1e-4, 0);
    CHECK(sc.span.spec == GAL_SPEC_SAG && sc.span.sag == 6, "sag spec");
}

static void test_shipped_table(void)
{
    /* every row of data/conductors.csv loads; Drake is the ACSR 795 kcmil 26/7 of the tables */
    const char *names[] = {"Drake", "Condor", "Grosbeak", "Bersimis", "Falcon", "Cardinal"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        char text[256];
        snprintf(text, sizeof text, "[span]\nlength = 300\nhorizontal_tension = 28000\n"
                 "[conductor]\nname = %s\n", names[i]);
        char *p = put("shipped.ini", text);
        gal_scene sc;
        int st = gal_scene_load(&sc, p, NULL, 0, "data/conductors.csv");
        free(p);
        CHECK(st == GAL_OK, "%s: %s", names[i], gal_error_message());
        if (st) continue;
        double m = sc.conductor.mass_per_length, d = sc.conductor.diameter;
        CHECK(d > 0.02 && d < 0.045 && m > 1 && m < 3.5, "%s: d %g m %g", names[i], d, m);
        CHECK_REL(sc.conductor.polar_inertia, m * d * d / 8, 1e-3);
    }
    /* the demo scene, with the table found through GALLOP_DATA */
    setenv("GALLOP_DATA", "data", 1);
    gal_scene sc;
    int st = gal_scene_load(&sc, "data/scenes/drake_300m.ini", NULL, 0, NULL);
    unsetenv("GALLOP_DATA");
    CHECK(st == GAL_OK, "%s", gal_error_message());
    CHECK_NEAR(sc.conductor.diameter, 0.02814, 0);
    CHECK_NEAR(sc.conductor.mass_per_length, 1.628, 0);
    CHECK_NEAR(sc.span.horizontal_tension, 28000, 0);
    CHECK(sc.model.elements == 100, "elements");
    CHECK(!strcmp(sc.output.directory, "out/drake_300m"), "%s", sc.output.directory);
    /* the table beside the scene directory (data/scenes/../conductors.csv) */
    st = gal_scene_load(&sc, "data/scenes/drake_300m.ini", NULL, 0, NULL);
    CHECK(st == GAL_OK, "%s", gal_error_message());
}

static void test_degrees_and_wind(void)
{
    char text[2048];
    snprintf(text, sizeof text, "%s[wind]\nspeed = 12\nyaw = 45\nturbulence = kaimal\n"
             "seed = 42\n[ice]\nmass_per_length = 0.5\neccentricity = 0.01\n", BASE);
    gal_scene sc;
    int st = load_text(&sc, "wind.ini", text, NULL, 0);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    CHECK_NEAR(sc.wind.yaw, PI / 4, 1e-15);
    CHECK(sc.wind.turbulence == GAL_TURB_KAIMAL && sc.wind.seed == 42, "turbulence, seed");
    for (int i = GAL_FX_ICE_ECCENTRICITY; i <= GAL_FX_TURBULENCE; i++)
        CHECK(sc.effect[i] == 1, "%s on with its data", gal_effect_names[i]);
    CHECK(sc.effect[GAL_FX_DAMPING] == 0, "no damping ratio, no damping");
    CHECK(sc.ice.present, "ice");
    CHECK_REL(sc.ice.polar_inertia, 0.5 * (0.015 * 0.015 + 0.01 * 0.01), 1e-12);
}

static void test_set_overrides(void)
{
    gal_scene sc;
    const char *sets[] = {"span.length = 250", "wind.yaw=30", "model.elements=40",
                          "span.sag=5", "effects.gravity=off"};
    int st = load_text(&sc, "set.ini", BASE, sets, 5);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    CHECK_NEAR(sc.span.length, 250, 0);
    CHECK_NEAR(sc.wind.yaw, PI / 6, 1e-15);
    CHECK(sc.model.elements == 40, "elements");
    CHECK(sc.span.spec == GAL_SPEC_SAG && sc.span.sag == 5, "a --set sag replaces the tension");
    CHECK(sc.effect[GAL_FX_GRAVITY] == 0, "gravity off");

    /* a --set that fixes a bad value of the file */
    char text[2048];
    snprintf(text, sizeof text, "%s[model]\nelements = 3\n", BASE);
    st = load_text(&sc, "fixed.ini", text, NULL, 0);
    CHECK(st == GAL_EINPUT, "elements = 3 is out of range");
    const char *fix[] = {"model.elements=8"};
    st = load_text(&sc, "fixed.ini", text, fix, 1);
    CHECK(st == GAL_OK && sc.model.elements == 8, "fixed by --set: %s", gal_error_message());

    /* bad --set: value, key, syntax; two specs on the command line */
    const char *bad[][2] = {{"model.elements=abc", "elements"}, {"span.lenght=3", "lenght"},
                            {"spanlength", "spanlength"}, {"nosuch.key=1", "nosuch"},
                            {"wind.yaw=181", "yaw"}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        st = load_text(&sc, "set.ini", BASE, bad[i], 1);
        const char *msg = gal_error_message();
        CHECK(st == GAL_EINPUT, "%s: status %d", bad[i][0], st);
        CHECK(strstr(msg, "--set: ") == msg && strstr(msg, bad[i][1]), "%s: %s", bad[i][0], msg);
    }
    const char *two[] = {"span.sag=5", "span.horizontal_tension=1000"};
    st = load_text(&sc, "set.ini", BASE, two, 2);
    CHECK(st == GAL_EINPUT && strstr(gal_error_message(), "--set") &&
              strstr(gal_error_message(), "sag"), "%s", gal_error_message());
}

static void test_errors(void)
{
    expect_error("[span]\nlenght = 3\n", "lenght", "lenght");
    expect_error("[spam]\n", "[spam]", "spam");
    expect_error("[span]\nlength = 100\n", "length = 100", "length");
    expect_error("[model]\nelements = 1OO\n", "elements", "elements");
    expect_error("[model]\nmodes_vertical = 2.5\n", "modes_vertical", "modes_vertical");
    expect_error("[conductor]\ndamping_ratio = 1\n", "damping_ratio", "damping_ratio");
    expect_error("[span]\nsag = 5\n", "sag", "horizontal_tension");
    expect_error("[effects]\ngravity = maybe\n", "gravity", "gravity");
    expect_error("[effects]\nturbulence = on\n", "turbulence", "turbulence");
    expect_error("[effects]\nice_eccentricity = on\n", "ice_eccentricity", "ice");
    expect_error("[simulation]\nprobes = 0.5, 1.2\n", "probes", "probes");
    expect_error("[simulation]\nprobes = 0.5,,0.2\n", "probes", "probes");
    expect_error("[simulation]\nprobes = .1,.1,.1,.1,.1,.1,.1,.1,.1,.1,.1,.1,.1,.1,.1,.1,.1\n",
                 "probes", "probes");
    expect_error("[simulation]\ntime_step = 100\nduration = 10\n", "time_step", "time_step");
    expect_error("[conductor]\nname = NoSuchWire\n", "NoSuchWire", "NoSuchWire");
    expect_error("[wind]\nspeed = nan\n", "speed", "speed");
    expect_error("[wind]\nspeed = 1e999\n", "speed", "speed");
    expect_error("[wind]\nturbulence = kaimal\n", "turbulence", "turbulence");
    expect_error("[wind]\nturbulence = gusty\n", "turbulence", "gusty");
    expect_error("[ice]\neccentricity = 0.01\n", "eccentricity", "mass_per_length");
    expect_error("[ice]\nmass_per_length = 1\naero_table = nosuch.csv\n", "aero_table",
                 "nosuch.csv");
    expect_error("[span]\nheight_difference = 250\n", "height_difference", "height_difference");
    expect_error("this line is not ini\n", "this line", "malformed");
    expect_error("[span\n", "[span\n", "malformed");
    expect_error("[span] junk\n", "[span] junk", "span");
    char longline[1200];
    memset(longline, 'x', 1000);
    strcpy(longline + 1000, " = 1\n");
    expect_error(longline, "xxx", "malformed");

    /* errors without a line: missing keys */
    gal_scene sc;
    int st = load_text(&sc, "nospec.ini", "[span]\nlength = 100\n[conductor]\nname = Other\n",
                       NULL, 0);
    CHECK(st == GAL_EINPUT && strstr(gal_error_message(), "nospec.ini: ") &&
              strstr(gal_error_message(), "horizontal_tension"), "%s", gal_error_message());
    st = load_text(&sc, "nodiam.ini", "[span]\nlength = 100\nsag = 3\n", NULL, 0);
    CHECK(st == GAL_EINPUT && strstr(gal_error_message(), "diameter"), "%s", gal_error_message());
    /* a key before any section */
    st = load_text(&sc, "nosec.ini", "length = 100\n", NULL, 0);
    CHECK(st == GAL_EINPUT && strstr(gal_error_message(), "nosec.ini:1: "), "%s",
          gal_error_message());
}

static void test_csv_errors(void)
{
    char *bad = put("bad.csv",
                    "# comment\n"
                    "name,diameter_m,mass_per_length_kg_m,axial_stiffness_n,bending_stiffness_n_m2,"
                    "torsional_stiffness_n_m2_rad,polar_inertia_kg_m2_m,source\n"
                    "Good,0.02,1,2e7,20,100,1e-4,ok\n"
                    "Bad,0.02,one,2e7,20,100,1e-4,broken\n");
    char *p = put("usebad.ini", "[span]\nlength = 100\nsag = 2\n[conductor]\nname = Good\n");
    gal_scene sc;
    int st = gal_scene_load(&sc, p, NULL, 0, bad);
    char at[300];
    snprintf(at, sizeof at, "%s:4: ", bad);
    CHECK(st == GAL_EINPUT, "status %d", st);
    CHECK(strstr(gal_error_message(), at) == gal_error_message() &&
              strstr(gal_error_message(), "mass_per_length"), "%s", gal_error_message());
    free(bad);
    bad = put("short.csv", "name,diameter_m,mass_per_length_kg_m,axial_stiffness_n,"
              "bending_stiffness_n_m2,torsional_stiffness_n_m2_rad,polar_inertia_kg_m2_m,source\n"
              "Good,0.02,1,2e7\n");
    st = gal_scene_load(&sc, p, NULL, 0, bad);
    snprintf(at, sizeof at, "%s:2: ", bad);
    CHECK(st == GAL_EINPUT && strstr(gal_error_message(), at) == gal_error_message(), "%s",
          gal_error_message());
    free(bad);
    bad = put("nohead.csv", "Good,0.02,1,2e7,20,100,1e-4,ok\n");
    st = gal_scene_load(&sc, p, NULL, 0, bad);
    snprintf(at, sizeof at, "%s:1: ", bad);
    CHECK(st == GAL_EINPUT && strstr(gal_error_message(), at) == gal_error_message(), "%s",
          gal_error_message());
    free(bad);
    st = gal_scene_load(&sc, p, NULL, 0, "/nonexistent/conductors.csv");
    CHECK(st == GAL_EIO && strstr(gal_error_message(), "/nonexistent/conductors.csv") &&
              strstr(gal_error_message(), "usebad.ini:5: "), "%s", gal_error_message());
    free(p);
}

static void test_unreadable_and_empty(void)
{
    gal_scene sc;
    int st = gal_scene_load(&sc, "/nonexistent/scene.ini", NULL, 0, csv);
    CHECK(st == GAL_EIO && strstr(gal_error_message(), "/nonexistent/scene.ini"), "%s",
          gal_error_message());
    st = gal_scene_load(&sc, dir, NULL, 0, csv); /* a directory */
    CHECK(st == GAL_EIO && strstr(gal_error_message(), dir), "%s", gal_error_message());
    st = load_text(&sc, "empty.ini", "", NULL, 0);
    CHECK(st == GAL_EINPUT && strstr(gal_error_message(), "empty.ini") &&
              strstr(gal_error_message(), "length"), "%s", gal_error_message());
    char *p = put("nul.ini", "[span]\n");
    FILE *fp = fopen(p, "ab");
    fwrite("length = 1\0x\n", 1, 13, fp);
    fclose(fp);
    st = gal_scene_load(&sc, p, NULL, 0, csv);
    CHECK(st == GAL_EINPUT && strstr(gal_error_message(), "nul.ini:2: "), "%s",
          gal_error_message());
    free(p);
}

/* Load, print, load the print: the same scene. */
static void round_trip(const char *text, const char *const *sets, int n)
{
    gal_scene a, b;
    int st = load_text(&a, "rt.ini", text, sets, n);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    if (st) return;
    char *p = gal_path_join(dir, "printed.ini");
    FILE *fp = fopen(p, "w");
    gal_scene_print(&a, fp);
    fclose(fp);
    st = gal_scene_load(&b, p, NULL, 0, csv);
    CHECK(st == GAL_OK, "reading the print back: %s", gal_error_message());
    free(p);
    if (st) return;
    memcpy(b.path, a.path, sizeof a.path);
    memcpy(b.name, a.name, sizeof a.name);
    /* where the table was given (for messages) differs between the two files; the path does not */
    b.ice.aero_table_line = a.ice.aero_table_line;
    memcpy(b.ice.aero_table_given, a.ice.aero_table_given, sizeof a.ice.aero_table_given);
    CHECK(b.span.spec == a.span.spec, "spec");
    CHECK(b.wind.yaw == a.wind.yaw, "yaw %.17g %.17g", a.wind.yaw, b.wind.yaw);
    CHECK(b.conductor.polar_inertia == a.conductor.polar_inertia, "polar inertia");
    CHECK(b.ice.polar_inertia == a.ice.polar_inertia, "ice polar inertia");
    CHECK(!strcmp(a.ice.aero_table, b.ice.aero_table), "%s %s", a.ice.aero_table,
          b.ice.aero_table);
    CHECK(memcmp(&a, &b, sizeof a) == 0, "the whole scene reads back the same");
}

static void test_round_trip(void)
{
    /* a valid table: the scene reads it when it names it */
    free(put("aero.csv", "# source: test_scene.c\nalpha_deg,cd,cl,cm\n-180,1,0,0\n-90,1,0.1,0\n0,1,0,0\n"
                         "90,1,-0.1,0\n180,1,0,0\n"));
    char text[4096];
    snprintf(text, sizeof text,
             "[span]\nlength = 412.5\nheight_difference = -31.7\nunstretched_length = 416\n"
             "end_twist = free\n[conductor]\nname = TestCond\nmass_per_length = 1.234567891\n"
             "damping_ratio = 0.003\n[ice]\nmass_per_length = 0.7\neccentricity = -0.012\n"
             "aero_table = aero.csv\n[wind]\nspeed = 14.2\nyaw = 33.3\nair_density = 1.3\n"
             "turbulence = von_karman\nintensity = 0.15\ncoherence_decay = 8\nseed = 99\n"
             "[effects]\naero_moment = off\n[model]\nelements = 321\nmodes_vertical = 0\n"
             "[simulation]\nduration = 120.5\ntime_step = 0.01\nprobes = 0.1, 0.5, 0.73\n"
             "[output]\ndirectory = results/run 1\n");
    round_trip(text, NULL, 0);
    round_trip(BASE, NULL, 0);
    const char *sets[] = {"span.sag=3.3", "wind.yaw=0.1", "wind.speed=0.5"};
    round_trip(BASE, sets, 3);
}

/* ---- junk must give a status, never a crash ---- */

static uint64_t rng = 88172645463325252ull;
static unsigned rnd(unsigned n)
{
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17; /* xorshift64 */
    return (unsigned)(rng % n);
}

static void test_fuzz(void)
{
    static const char *const pieces[] = {"[", "]", "=", ":", ";", "#", "\n", " ", "\t", "\r",
                                         ",", ".", "e", "-", "1e308", "nan", "[span]",
                                         "[effects]", "length", "on", "\xEF\xBB\xBF", "\xff"};
    char valid[4096];
    snprintf(valid, sizeof valid, "%s[wind]\nspeed = 10\nyaw = 80\n[simulation]\n"
             "probes = 0.2, 0.4\n[conductor]\nname = Other\n", BASE);
    char *p = gal_path_join(dir, "fuzz.ini");
    int ok = 0, bad = 0, other = 0;
    for (int it = 0; it < 2000; it++) {
        char buf[8192];
        size_t n = 0;
        if (it % 2 == 0) { /* random bytes */
            n = rnd(700);
            for (size_t i = 0; i < n; i++) buf[i] = (char)rnd(256);
        } else { /* a valid scene, mutated */
            n = strlen(valid);
            memcpy(buf, valid, n);
            int muts = 1 + (int)rnd(4);
            for (int m = 0; m < muts; m++) {
                size_t at = rnd((unsigned)n + 1);
                switch (rnd(4)) {
                case 0: if (n) buf[rnd((unsigned)n)] = (char)rnd(256); break;
                case 1: n = at; break; /* truncate */
                case 2: { /* insert a piece */
                    const char *s = pieces[rnd(sizeof pieces / sizeof pieces[0])];
                    size_t l = strlen(s);
                    if (n + l < sizeof buf) {
                        memmove(buf + at + l, buf + at, n - at);
                        memcpy(buf + at, s, l);
                        n += l;
                    }
                    break;
                }
                default: /* delete a stretch */
                    if (at < n) {
                        size_t l = rnd((unsigned)(n - at) + 1);
                        memmove(buf + at, buf + at + l, n - at - l);
                        n -= l;
                    }
                }
            }
        }
        FILE *fp = fopen(p, "wb");
        fwrite(buf, 1, n, fp);
        fclose(fp);
        gal_scene sc;
        const char *sets[] = {"wind.seed=7"};
        int st = gal_scene_load(&sc, p, sets, (int)rnd(2), csv);
        if (st == GAL_OK) ok++;
        else if (st == GAL_EINPUT && strstr(gal_error_message(), "allowed")) bad++;
        else other++, printf("    status %d: %s\n", st, gal_error_message());
    }
    free(p);
    CHECK(other == 0, "%d inputs gave another status or a message without 'allowed'", other);
    CHECK(ok > 0 && bad > 0, "both outcomes seen: %d ok, %d errors", ok, bad);
}

int main(void)
{
    strcpy(dir, "/tmp/gallop_scene_XXXXXX");
    if (!mkdtemp(dir)) return 1;
    char *c = put("conductors.csv",
                  "# test table\n"
                  "name,diameter_m,mass_per_length_kg_m,axial_stiffness_n,bending_stiffness_n_m2,"
                  "torsional_stiffness_n_m2_rad,polar_inertia_kg_m2_m,source\n"
                  "TestCond,0.025,1.3,3e7,30,150,1e-4,test row, with a comma\n"
                  "\n"
                  "Other , 0.03 , 1.8 , 4e7 , 40 , 250 , 2e-4 , test\n");
    snprintf(csv, sizeof csv, "%s", c);
    free(c);
    RUN(test_defaults);
    RUN(test_syntax_variants);
    RUN(test_conductor_by_name);
    RUN(test_shipped_table);
    RUN(test_degrees_and_wind);
    RUN(test_set_overrides);
    RUN(test_errors);
    RUN(test_csv_errors);
    RUN(test_unreadable_and_empty);
    RUN(test_round_trip);
    RUN(test_fuzz);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0) printf("    could not remove %s\n", dir);
    return CHECK_SUMMARY();
}
