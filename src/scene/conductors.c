/* conductors.c: the conductor table (data/conductors.csv): the row that [conductor] name asks
 * for fills the conductor keys the scene does not give; every row is checked. */
#include "scene_impl.h"
#include "gallop/base/datadir.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

/* ---- the conductor table ---- */

static const char *const csv_cols[] = {
    "name", "diameter_m", "mass_per_length_kg_m", "axial_stiffness_n", "bending_stiffness_n_m2",
    "torsional_stiffness_n_m2_rad", "polar_inertia_kg_m2_m", "rated_strength_n",
    "thermal_expansion_1_k", "final_modulus_pa", "source"};
#define NCOL 11  /* columns; the source is the rest of the line */
#define NCOL_OLD 8 /* the table before rated strength, expansion and modulus: still read */
#define NNUM 10  /* columns 1..9 are numbers */
static const int csv_keys[NNUM] = {-1, K_DIAM, K_MASS, K_EA, K_EI, K_GJ, K_CPOLAR,
                                   K_CRTS, K_CALPHA, K_CMOD};
#define FIRST_OPTIONAL 7 /* rated strength, expansion, modulus: empty where not published */

/* Where the reading of the table is. */
typedef struct {
    const char *csv;   /* its path */
    int line;          /* the line read last */
    int header;        /* the header was read */
    int ncol;          /* its columns: NCOL, or NCOL_OLD (no optional columns) */
    int found;         /* line of the row asked for, 0 none yet */
    double row[NNUM];  /* that row's numbers (row[0] unused; 0: an empty optional column) */
    char list[512];    /* the names seen, for the message when the name is not found */
    size_t listn;
} ctab;

/* An error in the table itself: "CSV:LINE: ..." (LINE 0: "CSV: ..."). Returns 0. */
static int csv_fail(pstate *ps, const ctab *t, int line, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;
static int csv_fail(pstate *ps, const ctab *t, int line, const char *fmt, ...)
{
    char what[2048];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    ps->file = t->csv;
    return scn_fail(ps, GAL_EINPUT, line, "%s", what);
}

/* One data row: 11 fields, numbers in the range of their scene keys (the optional ones may be
 * empty); the row asked for is kept. */
static int table_row(pstate *ps, ctab *t, char **f, int nf)
{
    gal_scene *sc = ps->sc;
    char sn[128], sf[128], rt[160];
    scn_show(f[0], sn, sizeof sn);
    if (nf != t->ncol || !*f[0])
        return csv_fail(ps, t, t->line, "row %s: %d fields; allowed: %d fields, the first a "
                        "non-empty name", sn, nf, t->ncol);
    double v[NNUM] = {0};
    for (int i = 1; i < NNUM; i++) {
        int k = csv_keys[i];
        if (i >= FIRST_OPTIONAL && (t->ncol == NCOL_OLD || !*f[i])) continue; /* not published */
        int isnum = scn_parse_num(f[i], &v[i]);
        if (!isnum || !scn_in_range(&scn_keys[k], v[i]))
            return csv_fail(ps, t, t->line, "row %s: %s = %s: %s; allowed: %s", sn, csv_cols[i],
                            scn_show(f[i], sf, sizeof sf), isnum ? "out of range" : "not a number",
                            scn_range_text(k, rt, sizeof rt));
    }
    int w = snprintf(t->list + t->listn, sizeof t->list - t->listn, "%s%s", t->listn ? ", " : "", sn);
    if (w > 0 && (size_t)w < sizeof t->list - t->listn) t->listn += (size_t)w;
    if (!strcasecmp(f[0], sc->conductor.name)) {
        if (t->found)
            return csv_fail(ps, t, t->line, "row %s: a second row of this name (first at line "
                            "%d); allowed: one row per name", sn, t->found);
        t->found = t->line;
        memcpy(t->row, v, sizeof v);
        if (scn_text_ok(f[0]) && strlen(f[0]) < sizeof sc->conductor.name)
            strcpy(sc->conductor.name, f[0]); /* the table's spelling */
    }
    return 1;
}

/* Every line of the table in buf (changed in place): comments, the header, the rows. */
static int table_lines(pstate *ps, ctab *t, char *buf, size_t len)
{
    if (memchr(buf, '\0', len))
        return csv_fail(ps, t, 0, "contains a NUL byte; allowed: a text CSV file");
    char *start = len >= 3 && !memcmp(buf, "\xEF\xBB\xBF", 3) ? buf + 3 : buf; /* UTF-8 BOM */
    for (char *l = start, *next; l; l = next) {
        next = strchr(l, '\n');
        if (next) *next++ = '\0';
        t->line++;
        char *s = scn_trim(l);
        if (!*s || *s == '#') continue;
        /* split into NCOL fields: the first NCOL - 1 commas, the source is the rest */
        char *f[NCOL];
        int nf = 0;
        f[nf++] = s;
        int maxf = t->header ? t->ncol : NCOL;
        for (char *p = s; *p && nf < maxf; p++)
            if (*p == ',') *p = '\0', f[nf++] = p + 1;
        for (int i = 0; i < nf; i++) f[i] = scn_trim(f[i]);
        if (t->header) {
            if (!table_row(ps, t, f, nf)) return 0;
            continue;
        }
        /* the header: all columns, or the old 8 (name ... polar_inertia_kg_m2_m, source) */
        int ok = nf == NCOL;
        for (int i = 0; ok && i < NCOL; i++) ok = !strcmp(f[i], csv_cols[i]);
        int old = nf == NCOL_OLD && !strcmp(f[NCOL_OLD - 1], "source");
        for (int i = 0; old && i < NCOL_OLD - 1; i++) old = !strcmp(f[i], csv_cols[i]);
        t->ncol = old ? NCOL_OLD : NCOL;
        ok = ok || old;
        if (!ok)
            return csv_fail(ps, t, t->line, "not the conductor table header; allowed: name,"
                            "diameter_m,mass_per_length_kg_m,axial_stiffness_n,"
                            "bending_stiffness_n_m2,torsional_stiffness_n_m2_rad,"
                            "polar_inertia_kg_m2_m,rated_strength_n,thermal_expansion_1_k,"
                            "final_modulus_pa,source");
        t->header = 1;
    }
    return 1;
}

/* Find conductor.name in the CSV table `csv` and fill the conductor keys the scene did not give.
 * Every row is checked, so that a broken table is found whichever row is asked for. */
int scn_load_conductor(pstate *ps, const char *csv)
{
    gal_scene *sc = ps->sc;
    int nl = ps->given[K_CNAME];
    char sv[128], sc_[128];
    size_t len;
    char *buf = scn_slurp(csv, &len);
    scn_show(sc->conductor.name, sv, sizeof sv);
    scn_show(csv, sc_, sizeof sc_);
    if (!buf)
        return scn_fail(ps, errno == ENOMEM ? GAL_ENOMEM : GAL_EIO, nl,
                        "[conductor] name = %s: cannot read the conductor table %s: %s; allowed: "
                        "a readable CSV file (GALLOP_DATA names its directory)",
                        sv, sc_, strerror(errno));
    ctab t = {.csv = csv};
    int ok = table_lines(ps, &t, buf, len);
    free(buf);
    if (!ok) return 0;
    if (!t.header)
        return csv_fail(ps, &t, t.line, "no header line; allowed: a CSV table with the header "
                        "name,diameter_m,...,source");
    if (!t.found)
        return scn_fail(ps, GAL_EINPUT, nl, "[conductor] name = %s: not in %s; allowed: %s", sv,
                        sc_, t.listn ? t.list : "(the table has no rows)");
    for (int i = 1; i < NNUM; i++) {
        int k = csv_keys[i];
        if (!ps->given[k]) *(double *)((char *)sc + scn_keys[k].off) = t.row[i];
    }
    return 1;
}

/* The table conductor.name refers to: given, $GALLOP_DATA/conductors.csv, the installed data
 * directory's (base/datadir.h), ./data/conductors.csv, or <scene dir>/../conductors.csv. */
void scn_conductor_table(const pstate *ps, const char *given, char *out, size_t n)
{
    const char *env = getenv("GALLOP_DATA"), *inst = gal_datadir_installed();
    if (given) snprintf(out, n, "%s", given);
    else if (env && *env) snprintf(out, n, "%s/conductors.csv", env);
    else if (*inst && (snprintf(out, n, "%s/conductors.csv", inst), access(out, R_OK) == 0)) return;
    else if (access("data/conductors.csv", R_OK) == 0) snprintf(out, n, "data/conductors.csv");
    else snprintf(out, n, "%s/../conductors.csv", ps->dir);
}
