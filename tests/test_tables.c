/* test_tables.c: the model's tables (src/model/tables.c): the built-in bare-conductor table, a
 * scene's [ice] aero_table read, and a bad table refused with the scene file, line and key; the
 * scene reader itself resolves the path but leaves the contents to the model. */
#define _XOPEN_SOURCE 700 /* realpath */
#include "check.h"
#include "gallop.h"
#include "gallop/model/tables.h"
#include "gallop/scene/scene.h"

#include <unistd.h>

static char dir[64];

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

static const char *SCENE = "[span]\n"
                           "length = 200\n"
                           "horizontal_tension = 20000\n"
                           "[conductor]\n"
                           "diameter = 0.03\n"
                           "mass_per_length = 1.5\n"
                           "axial_stiffness = 3e7\n"
                           "bending_stiffness = 40\n"
                           "torsional_stiffness = 200\n"
                           "[wind]\n"
                           "speed = 10\n";

static const char *GOOD = "# source: test_tables.c\nalpha_deg,cd,cl,cm\n-180,1.3,0.2,-0.01\n"
                          "-90,1.0,0.4,0.03\n0,1.2,0.1,0.01\n90,1.1,-0.3,0.02\n";
/* line 4 has three columns */
static const char *BAD = "# source: test_tables.c\nalpha_deg,cd,cl,cm\n-180,1.3,0.2,-0.01\n"
                         "-90,1.0,0.4\n0,1.2,0.1,0.01\n";

/* SCENE with an [ice] section naming `table` (the aero_table key on line 14), loaded. */
static int load(gal_scene *sc, const char *table, const char *const *sets, int n)
{
    char text[2048];
    snprintf(text, sizeof text, "%s[ice]\nmass_per_length = 0.6\naero_table = %s\n", SCENE, table);
    char *p = put("iced.ini", text);
    int st = gal_scene_load(sc, p, sets, n, NULL);
    free(p);
    return st;
}

static void test_bare_conductor(void)
{
    gal_scene sc;
    char *p = put("bare.ini", SCENE);
    int st = gal_scene_load(&sc, p, NULL, 0, NULL);
    free(p);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    gal_aero_table *t = NULL;
    st = gal_model_aero_table(&sc, &t);
    CHECK(st == GAL_OK && t, "%s", gal_error_message());
    if (!t) return;
    /* a circular cylinder: C_D = 1 at every angle, no lift, no moment */
    for (double a = -3.0; a <= 3.0; a += 0.37) {
        double c[3], dc[3];
        gal_aero_eval(t, a, c, dc);
        CHECK_NEAR(c[0], 1.0, 1e-12);
        CHECK_NEAR(c[1], 0.0, 1e-12);
        CHECK_NEAR(c[2], 0.0, 1e-12);
        CHECK_NEAR(gal_aero_den_hartog(t, a), 1.0, 1e-12);
    }
    CHECK(strstr(t->path, "bare conductor") != NULL, "%s", t->path);
    gal_aero_table_free(t);
}

static void test_scene_table(void)
{
    char *good = put("good.csv", GOOD);
    gal_scene sc;
    int st = load(&sc, "good.csv", NULL, 0);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    CHECK(sc.ice.aero_table_line == 14, "line %d", sc.ice.aero_table_line);
    CHECK(!strcmp(sc.ice.aero_table_given, "good.csv"), "%s", sc.ice.aero_table_given);
    char real[4096];
    CHECK(realpath(good, real) && !strcmp(sc.ice.aero_table, real), "%s", sc.ice.aero_table);
    gal_aero_table *t = NULL;
    st = gal_model_aero_table(&sc, &t);
    CHECK(st == GAL_OK && t, "%s", gal_error_message());
    if (t) {
        double c[3];
        gal_aero_eval(t, 0.0, c, NULL); /* a node of the table */
        CHECK_NEAR(c[0], 1.2, 1e-12);
        CHECK_NEAR(c[1], 0.1, 1e-12);
        CHECK_NEAR(c[2], 0.01, 1e-12);
    }
    gal_aero_table_free(t);
    free(good);
}

static void test_bad_table(void)
{
    char *bad = put("bad.csv", BAD);
    gal_scene sc;
    /* the scene reader does not read the table: the scene loads */
    int st = load(&sc, "bad.csv", NULL, 0);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    static gal_aero_table sentinel;
    gal_aero_table *t = &sentinel; /* must be reset to NULL */
    st = gal_model_aero_table(&sc, &t);
    const char *m = gal_error_message();
    char where[3 * GAL_PATH_MAX];
    snprintf(where, sizeof where, "%s/iced.ini:14: [ice] aero_table = bad.csv: ", dir);
    CHECK(st == GAL_EINPUT && t == NULL, "status %d", st);
    CHECK(strstr(m, where) == m, "%s", m);
    CHECK(strstr(m, "bad.csv:4") != NULL, "the table's line: %s", m);
    CHECK(strstr(m, "; allowed: a CSV table") != NULL, "%s", m);

    /* given by --set: "--set: " (a relative path is taken from the current directory) */
    char set[512];
    snprintf(set, sizeof set, "ice.aero_table=%s", bad);
    const char *sets[] = {set};
    st = load(&sc, "nosuch.csv", sets, 1); /* the file's value is replaced, not checked */
    CHECK(st == GAL_OK, "%s", gal_error_message());
    CHECK(sc.ice.aero_table_line == -1, "line %d", sc.ice.aero_table_line);
    st = gal_model_aero_table(&sc, &t);
    m = gal_error_message();
    CHECK(st == GAL_EINPUT && strstr(m, "--set: [ice] aero_table = ") == m, "%s", m);
    CHECK(strstr(m, "bad.csv:4") != NULL, "%s", m);

    /* a scene filled by hand names no line: "SCENE: [ice] aero_table = PATH: ..." */
    sc.ice.aero_table_line = 0;
    sc.ice.aero_table_given[0] = '\0';
    st = gal_model_aero_table(&sc, &t);
    m = gal_error_message();
    snprintf(where, sizeof where, "%s: [ice] aero_table = %s: ", sc.path, sc.ice.aero_table);
    CHECK(st == GAL_EINPUT && strstr(m, where) == m, "%s", m);
    free(bad);
}

int main(void)
{
    strcpy(dir, "/tmp/gallop_tables_XXXXXX");
    if (!mkdtemp(dir)) return 1;
    if (access("data/conductors.csv", R_OK) != 0) printf("    (run from the top directory)\n");
    RUN(test_bare_conductor);
    RUN(test_scene_table);
    RUN(test_bad_table);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0) printf("    could not remove %s\n", dir);
    return CHECK_SUMMARY();
}
