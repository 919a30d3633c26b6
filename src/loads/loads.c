/* loads.c: quasi-steady aerodynamic loads in a ramped, turbulent, possibly reversing wind: the
 * lists of the terms that are on (loads.h), the point load as their sum (the relative wind, then
 * the section load, or an equivalent bundle's: bundle_section.c), the full model's generalized
 * forces and the statics under the mean wind. */
#include "gallop/loads/loads.h"
#include "gallop/base/core.h"
#include "loads_impl.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gallop/statics/statics.h"

void gal_loads_list_make(const gal_loads *L, gal_loads_list *list)
{
    int n = 0;
    if (L->speed != 0) list->wind[n++] = &gal_loads_term_mean_wind;
    if (L->u && L->nt > 1 && L->nx > 0) list->wind[n++] = &gal_loads_term_turbulence;
    if (L->w && L->nt > 1 && L->nx > 0) list->wind[n++] = &gal_loads_term_vertical_turbulence;
    if (L->aero_damping) list->wind[n++] = &gal_loads_term_aero_damping;
    list->nwind = n;
    list->nsection = gal_aero_terms(L->flags, list->section);
}

/* The wind at (t, x): the along-wind speed (mean wind, turbulence), reversed, along dir, plus
 * the vertical turbulence along +z. */
static void wind_at(const gal_loads *L, const gal_loads_list *ls, double t, double x, double w[3])
{
    double ramp = gal_loads_ramp(L, t), U = 0, W = 0;
    for (int k = 0; k < ls->nwind; k++) {
        if (ls->wind[k]->speed) U += ls->wind[k]->speed(L, t, x, ramp);
        if (ls->wind[k]->vertical) W += ls->wind[k]->vertical(L, t, x, ramp);
    }
    if (L->reverse_time > 0 && t >= L->reverse_time) U = -U;
    for (int k = 0; k < 3; k++) w[k] = U * L->dir[k];
    w[2] += W;                                     /* z is up */
}

/* The point load: the relative wind (the wind, then aerodynamic damping), the section's turned
 * reference direction, the section terms; an equivalent bundle's summed over its sub-conductors,
 * each moving with the twist rate spin (rad/s). */
static int point(const gal_loads *L, const gal_loads_list *ls, double t, double x, const double rdot[3],
                 double spin, const double tan[3], const double d1[3], double f[3], double *m)
{
    double w[3], d[3];
    const double *da = d1;
    wind_at(L, ls, t, x, w);
    if (L->attack_angle != 0) {
        /* the section's reference direction turned by -attack_angle about the tangent: the
         * angle of attack, measured from it, grows by attack_angle */
        double c = cos(L->attack_angle), s = sin(L->attack_angle), b[3];
        b[0] = tan[1] * d1[2] - tan[2] * d1[1];
        b[1] = tan[2] * d1[0] - tan[0] * d1[2];
        b[2] = tan[0] * d1[1] - tan[1] * d1[0];
        for (int k = 0; k < 3; k++) d[k] = c * d1[k] - s * b[k];
        da = d;
    }
    if (L->bundle.n > 1) return gal_loads_bundle_section(L, ls, w, rdot, spin, tan, d1, da, f, m);
    for (int k = 0; k < ls->nwind; k++)
        if (ls->wind[k]->relative) ls->wind[k]->relative(L, rdot, w);
    return gal_aero_load_terms(L->table, tan, da, w, L->rho, L->diam, ls->section, ls->nsection, f, m,
                               NULL, NULL);
}

void gal_loads_wind(const gal_loads *L, double t, double x, double w[3])
{
    gal_loads_list ls;
    gal_loads_list_make(L, &ls);
    wind_at(L, &ls, t, x, w);
}

int gal_loads_point(void *ctx, double t, double x, const double r[3], const double rdot[3],
                    const double tan[3], const double d1[3], double f[3], double *m)
{
    const gal_loads *L = ctx;
    gal_loads_list ls;
    (void)r;
    gal_loads_list_make(L, &ls);
    return point(L, &ls, t, x, rdot, 0.0, tan, d1, f, m);
}

/* The load of element j at its centre: force fe (N/m) and moment *me (N m/m); ta: the edge's frame
 * (gal_rod_eval_frames') or NULL (computed here). */
static int element_load(const gal_loads *L, const gal_loads_list *ls, double t, const double *q, const double *v,
                        int j, const double *ta, double fe[3], double *me)
{
    double r[3], rd[3], tg[3], d1[3];
    fe[0] = fe[1] = fe[2] = 0, *me = 0;
    for (int k = 0; k < 3; k++) {
        r[k] = 0.5 * (q[3 * j + k] + q[3 * (j + 1) + k]);
        rd[k] = 0.5 * (v[3 * j + k] + v[3 * (j + 1) + k]);
    }
    if (ta) gal_rod_material_frame_from(L->rod, q, j, ta, tg, d1);
    else gal_rod_material_frame(L->rod, q, j, tg, d1);
    double spin = L->rod->p.torsion ? v[3 * L->rod->nn + j] : 0.0; /* the twist rate */
    int st = point(L, ls, t, r[0], rd, spin, tg, d1, fe, me);
    if (st) return gal_error(GAL_EFAIL, "aerodynamic load of element %d at t = %.6g s: %s", j, t, gal_error_message());
    return GAL_OK;
}

/* gal_loads_full, with the edge frames given when frames != NULL */
static int full(const gal_loads *L, double t, const double *q, const double *v, const double *frames, double *f)
{
    gal_loads_list ls;
    gal_loads_list_make(L, &ls); /* once for all elements */
    const gal_rod *rod = L->rod;
    int nel = rod->p.elements, nn = rod->nn;
    for (int j = 0; j < nel; j++) {
        double fe[3], me;
        int st = element_load(L, &ls, t, q, v, j, frames ? frames + 6 * j : NULL, fe, &me);
        if (st) return st;
        double l0 = rod->l0[j];
        for (int k = 0; k < 3; k++) {
            f[3 * j + k] += 0.5 * l0 * fe[k];
            f[3 * (j + 1) + k] += 0.5 * l0 * fe[k];
        }
        if (rod->p.torsion) f[3 * nn + j] += l0 * me;
    }
    return GAL_OK;
}

int gal_loads_full(void *ctx, double t, const double *q, const double *v, double *f)
{
    return full(ctx, t, q, v, NULL, f);
}

int gal_loads_full_framed(void *ctx, double t, const double *q, const double *v, const double *frames, double *f)
{
    return full(ctx, t, q, v, frames, f);
}

int gal_loads_element(void *ctx, double t, const double *q, const double *v, int j, double f[7])
{
    const gal_loads *L = ctx;
    gal_loads_list ls;
    gal_loads_list_make(L, &ls);
    double fe[3], me, l0 = L->rod->l0[j];
    int st = element_load(L, &ls, t, q, v, j, NULL, fe, &me);
    if (st) return st;
    for (int k = 0; k < 3; k++) f[k] = f[3 + k] = 0.5 * l0 * fe[k];
    f[6] = L->rod->p.torsion ? l0 * me : 0;
    return GAL_OK;
}

int gal_loads_mean(const gal_loads *L, const double *q, double *f)
{
    int nq = L->rod->nq;
    double *v = calloc((size_t)nq, sizeof(double));
    if (!v) return gal_error(GAL_ENOMEM, "out of memory");
    gal_loads Ls = *L;
    Ls.u = Ls.w = NULL, Ls.nt = 0, Ls.ramp_time = 0, Ls.reverse_time = 0;
    int st = gal_loads_full(&Ls, 0.0, q, v, f);
    free(v);
    return st;
}

int gal_loads_static(const gal_rod *rod, double *q, const gal_loads *L, double force_tol, int max_iter, int *iterations)
{
    /* Picard on the follower load: solve grad U(q) = F(q) with F frozen, update F, repeat. The
     * load is evaluated with the full mean wind (after the ramp) and no turbulence or motion. */
    int nq = rod->nq, st = GAL_OK;
    double *f = malloc((size_t)nq * sizeof(double)), *qold = malloc((size_t)nq * sizeof(double));
    double *v = calloc((size_t)nq, sizeof(double));
    if (!f || !qold || !v) { free(f); free(qold); free(v); return gal_error(GAL_ENOMEM, "out of memory"); }
    gal_loads Ls = *L;
    Ls.u = Ls.w = NULL, Ls.nt = 0, Ls.ramp_time = 0, Ls.reverse_time = 0, Ls.rod = rod;
    double scale = fmax(rod->p.length, 1.0);
    int it;
    for (it = 0; it < max_iter; it++) {
        memset(f, 0, (size_t)nq * sizeof(double));
        if ((st = gal_loads_full(&Ls, 0.0, q, v, f))) break;
        memcpy(qold, q, (size_t)nq * sizeof(double));
        if ((st = gal_statics_solve_loaded(rod, q, f, force_tol, 60, iterations))) break;
        double dmax = 0;
        for (int k = 0; k < nq; k++) dmax = fmax(dmax, fabs(q[k] - qold[k]) / (k < 3 * rod->nn ? scale : 1.0));
        if (dmax < 1e-11) break;
    }
    if (!st && it >= max_iter)
        st = gal_error(GAL_EFAIL, "statics under the mean wind: the load iteration did not converge in %d iterations", max_iter);
    free(f); free(qold); free(v);
    return st;
}
