/* conductors.c: the conductor table (data/conductors.csv): the row that [conductor] name asks
 * for fills the conductor keys the scene does not give; every row is checked. */
#include "scene_impl.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

/* ---- the conductor table ---- */

static const char *const csv_cols[] = {
    "name", "diameter_m", "mass_per_length_kg_m", "axial_stiffness_n", "bending_stiffness_n_m2",
    "torsional_stiffness_n_m2_rad", "polar_inertia_kg_m2_m", "source"};
static const int csv_keys[7] = {-1, K_DIAM, K_MASS, K_EA, K_EI, K_GJ, K_CPOLAR};

/* Find `want` in the CSV table `csv` and fill the conductor keys the scene did not give. Every
 * row is checked, so that a broken table is found whichever row is asked for. */
int scn_load_conductor(pstate *ps, const char *csv)
{
    gal_scene *sc = ps->sc;
    int nl = ps->given[K_CNAME];
    char sv[128], sc_[128], list[512] = "";
    size_t len, listn = 0;
    char *buf = scn_slurp(csv, &len);
    scn_show(sc->conductor.name, sv, sizeof sv);
    scn_show(csv, sc_, sizeof sc_);
    if (!buf)
        return scn_fail(ps, errno == ENOMEM ? GAL_ENOMEM : GAL_EIO, nl,
                    "[conductor] name = %s: cannot read the conductor table %s: %s; allowed: a "
                    "readable CSV file (GALLOP_DATA names its directory)",
                    sv, sc_, strerror(errno));
    if (memchr(buf, '\0', len)) {
        free(buf);
        ps->file = csv;
        return scn_fail(ps, GAL_EINPUT, 0, "contains a NUL byte; allowed: a text CSV file");
    }
    int line = 0, header = 0, found = 0;
    double row[7] = {0};
    char *start = len >= 3 && !memcmp(buf, "\xEF\xBB\xBF", 3) ? buf + 3 : buf; /* UTF-8 BOM */
    for (char *l = start, *next; l; l = next) {
        next = strchr(l, '\n');
        if (next) *next++ = '\0';
        line++;
        char *t = scn_trim(l);
        if (!*t || *t == '#') continue;
        /* split into 8 fields: the 7 first commas, the source is the rest */
        char *f[8];
        int nf = 0;
        f[nf++] = t;
        for (char *p = t; *p && nf < 8; p++)
            if (*p == ',') *p = '\0', f[nf++] = p + 1;
        for (int i = 0; i < nf; i++) f[i] = scn_trim(f[i]);
        if (!header) {
            int ok = nf == 8;
            for (int i = 0; ok && i < 8; i++) ok = !strcmp(f[i], csv_cols[i]);
            if (!ok) {
                free(buf);
                ps->file = csv;
                return scn_fail(ps, GAL_EINPUT, line,
                            "not the conductor table header; allowed: name,diameter_m,"
                            "mass_per_length_kg_m,axial_stiffness_n,bending_stiffness_n_m2,"
                            "torsional_stiffness_n_m2_rad,polar_inertia_kg_m2_m,source");
            }
            header = 1;
            continue;
        }
        char sn[128], sf[128], rt[160];
        scn_show(f[0], sn, sizeof sn);
        if (nf != 8 || !*f[0]) {
            free(buf);
            ps->file = csv;
            return scn_fail(ps, GAL_EINPUT, line,
                        "row %s: %d fields; allowed: 8 fields, the first a non-empty name", sn, nf);
        }
        double v[7];
        for (int i = 1; i < 7; i++) {
            int k = csv_keys[i];
            int isnum = scn_parse_num(f[i], &v[i]);
            if (!isnum || !scn_in_range(&scn_keys[k], v[i])) {
                scn_show(f[i], sf, sizeof sf);
                free(buf);
                ps->file = csv;
                return scn_fail(ps, GAL_EINPUT, line, "row %s: %s = %s: %s; allowed: %s", sn,
                            csv_cols[i], sf, isnum ? "out of range" : "not a number",
                            scn_range_text(k, rt, sizeof rt));
            }
        }
        int w = snprintf(list + listn, sizeof list - listn, "%s%s", listn ? ", " : "", sn);
        if (w > 0 && (size_t)w < sizeof list - listn) listn += (size_t)w;
        if (!strcasecmp(f[0], sc->conductor.name)) {
            if (found) {
                free(buf);
                ps->file = csv;
                return scn_fail(ps, GAL_EINPUT, line, "row %s: a second row of this name (first at "
                            "line %d); allowed: one row per name", sn, found);
            }
            found = line;
            memcpy(row, v, sizeof v);
            if (scn_text_ok(f[0]) && strlen(f[0]) < sizeof sc->conductor.name)
                strcpy(sc->conductor.name, f[0]); /* the table's spelling */
        }
    }
    free(buf);
    if (!header) {
        ps->file = csv;
        return scn_fail(ps, GAL_EINPUT, line, "no header line; allowed: a CSV table with the header "
                    "name,diameter_m,...,source");
    }
    if (!found)
        return scn_fail(ps, GAL_EINPUT, nl, "[conductor] name = %s: not in %s; allowed: %s", sv, sc_,
                    listn ? list : "(the table has no rows)");
    for (int i = 1; i < 7; i++) {
        int k = csv_keys[i];
        if (!ps->given[k]) *(double *)((char *)sc + scn_keys[k].off) = row[i];
    }
    return 1;
}

/* The table conductor.name refers to: given, $GALLOP_DATA/conductors.csv,
 * ./data/conductors.csv, or <scene dir>/../conductors.csv. */
void scn_conductor_table(const pstate *ps, const char *given, char *out, size_t n)
{
    const char *env = getenv("GALLOP_DATA");
    if (given) snprintf(out, n, "%s", given);
    else if (env && *env) snprintf(out, n, "%s/conductors.csv", env);
    else if (access("data/conductors.csv", R_OK) == 0) snprintf(out, n, "data/conductors.csv");
    else snprintf(out, n, "%s/../conductors.csv", ps->dir);
}
