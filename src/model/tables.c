/* tables.c: the tables of a model read from the files its scene names: the section's aerodynamic
 * coefficients ([ice] aero_table), or the built-in table of a bare conductor. */
#include "gallop/model/tables.h"
#include "gallop/base/error.h"

#include <stddef.h>
#include <stdio.h>

/* A bare stranded conductor: a circular cylinder at subcritical Reynolds number. */
static gal_aero_table *bare_conductor(void)
{
    double a[4] = {-180, -90, 0, 90}, cd[4] = {1.0, 1.0, 1.0, 1.0}, z[4] = {0, 0, 0, 0};
    return gal_aero_table_make("bare conductor (built in)",
                               "circular cylinder, subcritical Reynolds number: C_D = 1.0, no lift or moment",
                               4, a, cd, z, z);
}

int gal_model_aero_table(const gal_scene *sc, gal_aero_table **out)
{
    *out = NULL;
    if (!sc->ice.present || !sc->ice.aero_table[0]) {
        *out = bare_conductor();
        return *out ? GAL_OK : GAL_EFAIL;
    }
    int st = gal_aero_table_read(sc->ice.aero_table, out);
    if (st == GAL_OK) return GAL_OK;
    /* where the scene gave it: "FILE:LINE: ", "--set: ", or "FILE: " (a scene built by hand) */
    char where[GAL_PATH_MAX + 32];
    int line = sc->ice.aero_table_line;
    if (line > 0) snprintf(where, sizeof where, "%s:%d: ", sc->path, line);
    else if (line < 0) snprintf(where, sizeof where, "--set: ");
    else snprintf(where, sizeof where, "%s: ", sc->path);
    const char *given = sc->ice.aero_table_given[0] ? sc->ice.aero_table_given : sc->ice.aero_table;
    return gal_error(st == GAL_ENOMEM ? GAL_ENOMEM : GAL_EINPUT,
                     "%s[ice] aero_table = %s: %s; allowed: a CSV table '# source: ...', "
                     "'alpha_deg,cd,cl,cm', rows of 4 finite numbers, angles increasing over one "
                     "period", where, given, gal_error_message());
}
