/* diag_project.c: what the reduced basis lacks on a span. The full run's displacement fields over
 * its second half (every --every s) projected on the reduced model's initial basis V (modes and
 * modal derivatives, M-orthonormal: e = u - V V^T M u), the projection error per family and along
 * the span, the POD of the error (mass-weighted SVD) with each POD vector's family, place and
 * nearest computed modes, the share of the error that candidate vectors capture, and (--run) the
 * reduced run with vectors added to its initial basis (gal_rom_sim_run, the scene's adaptation unless
 * --tol 0), against the full run (compare's figures: gal_compare_runs). --run GROUP:
 *   base        nothing added
 *   modes       the computed modes outside the basis
 *   aero        K0^-1 dF/d eta_i and K0^-1 dF/d eta_i' (the static responses to the aerodynamic load's
 *               derivatives along each selected mode, at the mean-wind state q_start, after the ramp)
 *   third       the third-order modal derivatives -K0^-1 (d2K/d eta_j d eta_k) phi_i, i <= j <= k
 *               (second directional derivatives of the tangent by central differences)
 *   aero+third  both
 *   podN        the first N POD vectors of the projection error (an oracle: the full run's)
 *   tpodN       the first N POD vectors of the cubic part's content along the full trajectory (oracle)
 *   ttanN       ... of the cubic part's tangent d/d eta_i along the full trajectory (oracle)
 *   rtanN       ... of the cubic part's tangent at 48 training states at the scale of the motion, as
 *               the hyper-reduction's (no knowledge of the trajectory); N = 0: the shares >= 1e-5
 *   any of the last four +aero: with the aero vectors too;  match:GLOB,...: the candidates so named
 * Usage: diag_project SCENE [--set key=value]... [--every S] [--from S] [--pod N] [--tol T]
 *        [--detail] [--mass-weighted] [--run GROUP]...   (built like the bench programs, by hand:
 *        cc ... tests/bench/diag_project.c build/libgallop.a ... as tests/bench/run.sh does) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fnmatch.h>
#include <time.h>

#include <gsl/gsl_eigen.h>

#include "gallop.h"
#include "gallop/analysis/compare.h"
#include "gallop/base/core.h"
#include "gallop/reduced/rom.h"
#include "gallop/reduced/rom_sim.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"
#include "base/chol.h"
#include "diag_cubic.h"

#define NBIN 10
#define NCAND_MAX 600
#define NTR 48 /* training states */

/* ---- the full run, recorded through a wrapped integrator ---- */
static struct {
    double from, every, next;
    int ns, cap, n;
    double *U, *tU; /* n x cap, cap */
    const gal_rod *rod;
    const double *qeq;
    double *q, *v;
} rec;

static int w_alloc(const gal_model *m, const gal_data *d, const gal_run_opts *o, double dt_out, double fhi, void **s)
{
    return gal_integrator_full.alloc(m, d, o, dt_out, fhi, s);
}
static int w_advance(void *s, double t_out, double t_end)
{
    int st = gal_integrator_full.advance(s, t_out, t_end);
    if (!st && t_out >= rec.next - 1e-9 && rec.ns < rec.cap) {
        gal_integrator_full.state(s, rec.q, rec.v);
        double *u = rec.U + (size_t)rec.ns * rec.n;
        for (int k = 0; k < rec.n; k++) u[k] = rec.q[rec.rod->free_q[k]] - rec.qeq[rec.rod->free_q[k]];
        rec.tU[rec.ns++] = t_out;
        rec.next += rec.every;
    }
    return st;
}
static void w_observe(void *s, double *p, double t[2]) { gal_integrator_full.observe(s, p, t); }
static void w_counters(const void *s, gal_run_counters *c) { gal_integrator_full.counters(s, c); }
static void w_free(void *s) { gal_integrator_full.free(s); }
static void w_state(const void *s, double *q, double *v) { gal_integrator_full.state(s, q, v); }

/* Family (0 v, 1 h, 2 twist, 3 axial) and span bin of each free dof, the local directions at q_eq;
 * returns per dof the family weight split: fam[d*4+f] the share of dof d's value along family f is
 * taken node-wise in proj(). */
typedef struct { int node, bin; double dir[3][3]; } nodeinfo; /* dir: v, h, axial unit vectors */

static void node_dirs(const gal_rod *rod, const double *qeq, nodeinfo *ni)
{
    for (int i = 0; i < rod->nn; i++) {
        double t[3], ey[3], nv[3];
        gal_rod_node_directions(rod, qeq, i, t, ey, nv);
        memcpy(ni[i].dir[0], nv, sizeof nv), memcpy(ni[i].dir[1], ey, sizeof ey), memcpy(ni[i].dir[2], t, sizeof t);
        ni[i].bin = (int)fmin(NBIN - 1, floor(NBIN * (double)i / (rod->nn - 1)));
    }
}

/* mass-norm^2 of y per family and span bin: acc[f * NBIN + b] */
static void famspan(const gal_rod *rod, const nodeinfo *ni, const double *y, double *acc)
{
    memset(acc, 0, 4 * NBIN * sizeof(double));
    for (int i = 0; i < rod->nn; i++) {
        int d0 = rod->dof[3 * i];
        if (d0 < 0) continue;
        double w = rod->mdiag[d0], yv = gal_dot3(ni[i].dir[0], y + d0), yh = gal_dot3(ni[i].dir[1], y + d0),
               ya = gal_dot3(ni[i].dir[2], y + d0);
        acc[0 * NBIN + ni[i].bin] += w * yv * yv, acc[1 * NBIN + ni[i].bin] += w * yh * yh;
        acc[3 * NBIN + ni[i].bin] += w * ya * ya;
    }
    if (rod->p.torsion)
        for (int j = 0; j < rod->p.elements; j++) {
            int d = rod->dof[3 * rod->nn + j];
            int b = (int)fmin(NBIN - 1, floor(NBIN * (j + 0.5) / rod->p.elements));
            if (d >= 0) acc[2 * NBIN + b] += y[d] * y[d] * rod->mdiag[d];
        }
}

static void famsum(const double *acc, double f[4])
{
    for (int k = 0; k < 4; k++) {
        f[k] = 0;
        for (int b = 0; b < NBIN; b++) f[k] += acc[k * NBIN + b];
    }
}

static void print_famspan(const char *what, const double *acc, double tot)
{
    static const char *fn[4] = {"v", "h", "t", "a"};
    double f[4];
    famsum(acc, f);
    printf("%s family shares v %.3f h %.3f t %.3f a %.3f; along the span (tenths, the largest family):", what,
           f[0] / tot, f[1] / tot, f[2] / tot, f[3] / tot);
    int fm = 0;
    for (int k = 1; k < 4; k++)
        if (f[k] > f[fm]) fm = k;
    printf(" %s", fn[fm]);
    for (int b = 0; b < NBIN; b++) printf(" %.2f", acc[fm * NBIN + b] / fmax(f[fm], 1e-300));
    printf("\n");
}

/* The reduced run with nx extra vectors X, measured against the full run */
static void run_reduced(gal_sim_setup *s, const gal_sim_result *rf, const double *X, int nx, double tol,
                        const char *label)
{
    gal_sim_result rr;
    gal_rom_sim_info info;
    gal_rom_sim_opts o;
    gal_rom_sim_default_opts(&o);
    o.extra = nx ? X : NULL, o.nextra = nx, o.tolerance = tol;
    if (gal_rom_sim_run(s, &o, &rr, &info)) {
        printf("RUN %s: failed: %s\n", label, gal_error_message());
        gal_sim_result_clear(&rr);
        return;
    }
    gal_compare_figures c;
    gal_compare_runs(rf, &rr, -1, &c);
    double Tf = c.full.tension_max_steady, Tr = c.reduced.tension_max_steady;
    printf("RUN %s +%d basis %d->%d (%d growths) f %.2f%% v %.2f%% h %.2f%% twist %.2f%% (%.1f/%.1f deg) "
           "T %.2f%% res %.3f valid %d wall %.2f s (%.1f us/step, %ld steps, %.2f Newton, %.3f tangents a step)\n",
           label, nx, info.basis_start, info.basis, info.nevents, 100 * c.frequency_error, 100 * c.err_vertical,
           100 * c.err_horizontal, 100 * c.err_twist, c.reduced.peak_to_peak[3], c.full.peak_to_peak[3],
           100 * (Tr - Tf) / Tf, info.residual_max, info.valid, rr.wall_time_s, 1e6 * rr.wall_time_s / fmax(rr.steps, 1),
           rr.steps, (double)rr.newton_iterations / fmax(rr.steps, 1), (double)rr.factorizations / fmax(rr.steps, 1));
    printf("CUBIC %s: the cubic indicator's largest, per family: v %.4f h %.4f t %.4f a %.4f; residual v %.3f h %.3f "
           "t %.3f a %.3f\n", label, info.cubic_family[0], info.cubic_family[1], info.cubic_family[2],
           info.cubic_family[3], info.residual_family[0], info.residual_family[1], info.residual_family[2],
           info.residual_family[3]);
    gal_sim_result_clear(&rr);
}

/* everything main computes, for its parts */
typedef struct {
    gal_sim_setup s;
    gal_sim_result rf;
    gal_rom *m;
    nodeinfo *ni;
    double *E, *P, share[64];      /* the projection error (n x ns) and its POD */
    int npod, detail, massw, cost;
    double tol;
    cands c;
    int g0[4], g1[4];              /* the candidate groups: modes, aero, third, pod */
    double *Pt, sht[16], *Ptan, shtan[16], *Prt, shrt[32], *Pst; /* tpod, ttan, rtan, stan */
} diag;

static int setup(diag *g, const gal_scene *sc)
{
    gal_data *d = g->s.data;
    const gal_modes *md = &d->md;
    gal_rom_opts ro;
    gal_rom_default_opts(&ro);
    ro.damping = d->damping, ro.hyper = 0;
    int sel[64], nsel = 0;
    for (int k = 0; k < md->n && nsel < 64; k++)
        if (md->mode[k].selected) sel[nsel++] = k;
    if (!(g->m = gal_rom_alloc(d->eq.rod, d->eq.q, md, sel, nsel, &ro, NULL))) return 1;
    printf("selected modes (basis columns 0..%d):", nsel - 1);
    for (int k = 0; k < nsel; k++)
        printf(" %d=%s %.3f Hz", k, gal_family_names[md->mode[sel[k]].family], md->mode[sel[k]].frequency_hz);
    printf("\n");
    int n = d->eq.rod->ndof, nq = d->eq.rod->nq;
    double T = sc->simulation.duration;
    rec.next = rec.from = rec.from >= 0 ? rec.from : T / 2, rec.n = n, rec.rod = d->eq.rod;
    rec.qeq = d->eq.q, rec.cap = (int)((T - rec.from) / rec.every) + 2;
    rec.U = malloc((size_t)n * rec.cap * sizeof(double)), rec.tU = malloc(rec.cap * sizeof(double));
    rec.q = malloc(nq * sizeof(double)), rec.v = malloc(nq * sizeof(double));
    gal_integrator_type W = gal_integrator_full;
    W.alloc = w_alloc, W.advance = w_advance, W.observe = w_observe, W.counters = w_counters, W.free = w_free,
    W.state = w_state;
    gal_run_opts go;
    gal_run_opts_from_scene(sc, &go);
    double t0 = gal_wall_time();
    if (gal_run_check_measurable(g->s.model, d, &go) || gal_run(g->s.model, d, &W, &go, &g->rf)) return 1;
    printf("full run %.1f s wall, %.0f us/step; %d snapshots from %.1f s every %.2f s; basis %d (%d modes)\n",
           gal_wall_time() - t0, 1e6 * g->rf.wall_time_s / fmax(g->rf.steps, 1), rec.ns, rec.from, rec.every,
           g->m->r, g->m->nmodes);
    return 0;
}

/* the projection error per family and along the span, and its POD */
static void projection(diag *g)
{
    const gal_rod *rod = g->m->rod;
    const gal_modes *md = &g->s.data->md;
    int n = rod->ndof, ns = rec.ns;
    double accE[4 * NBIN] = {0}, accU[4 * NBIN] = {0}, a[4 * NBIN], emax[4] = {0}, fE[4], fU[4];
    g->ni = malloc(rod->nn * sizeof *g->ni);
    node_dirs(rod, g->m->q_eq, g->ni);
    g->E = malloc((size_t)n * ns * sizeof(double));
    for (int j = 0; j < ns; j++) {
        double *e = g->E + (size_t)j * n, fe[4], fu[4];
        memcpy(e, rec.U + (size_t)j * n, n * sizeof(double));
        famspan(rod, g->ni, e, a), famsum(a, fu);
        for (int k = 0; k < 4 * NBIN; k++) accU[k] += a[k];
        orth(rod, g->m->V, g->m->r, e);
        famspan(rod, g->ni, e, a), famsum(a, fe);
        for (int k = 0; k < 4 * NBIN; k++) accE[k] += a[k];
        double tot = fu[0] + fu[1] + fu[2] + fu[3];
        for (int f = 0; f < 4; f++) emax[f] = fmax(emax[f], sqrt(fe[f] / fmax(fu[f], 4e-4 * tot)));
    }
    famsum(accE, fE), famsum(accU, fU);
    printf("projection error |e|_M/|u|_M per family over the window (rms; max over states):");
    for (int f = 0; f < 4; f++) printf(" %s %.4f (%.4f)", gal_family_names[f], sqrt(fE[f] / fU[f]), emax[f]);
    printf("\n");
    print_famspan("error:", accE, fE[0] + fE[1] + fE[2] + fE[3]);
    g->P = malloc((size_t)n * g->npod * sizeof(double));
    pod(rod, g->E, ns, g->npod, g->P, g->share);
    for (int k = 0; k < g->npod; k++) {
        const double *p = g->P + (size_t)k * n;
        char what[64];
        famspan(rod, g->ni, p, a);
        snprintf(what, sizeof what, "POD %d (%.3f of the error):", k, g->share[k]);
        print_famspan(what, a, 1.0);
        int best[3] = {-1, -1, -1};
        double bv[3] = {0};
        for (int i = 0; i < md->n; i++) {
            double c = mdot(rod, md->shape + (size_t)i * n, p), c2 = c * c;
            for (int b = 0; b < 3; b++)
                if (c2 > bv[b]) {
                    for (int b2 = 2; b2 > b; b2--) bv[b2] = bv[b2 - 1], best[b2] = best[b2 - 1];
                    bv[b] = c2, best[b] = i;
                    break;
                }
        }
        printf("   nearest computed modes:");
        for (int b = 0; b < 3; b++)
            if (best[b] >= 0)
                printf(" %d%s(%s %.3f Hz) %.3f", best[b], md->mode[best[b]].selected ? "*" : "",
                       gal_family_names[md->mode[best[b]].family], md->mode[best[b]].frequency_hz, bv[b]);
        printf("\n");
    }
}

/* the modal coordinates of the recorded states (every st-th: *nt of them) */
static double *trajectory_eta(const gal_rom *m, int st, int *nt)
{
    int n = m->ndof, nm = m->nmodes;
    double *eta = malloc((size_t)nm * (rec.ns / st + 1) * sizeof(double));
    *nt = 0;
    for (int t = 0; t < rec.ns; t += st, (*nt)++)
        for (int a = 0; a < nm; a++) eta[(size_t)*nt * nm + a] = mdot(m->rod, m->V + (size_t)a * n, rec.U + (size_t)t * n);
    return eta;
}

/* the candidate groups, and the POD of the cubic part (content and tangents) */
static void candidates(diag *g)
{
    gal_rom *m = g->m;
    const gal_modes *md = &g->s.data->md;
    int n = m->ndof, nm = m->nmodes, nt;
    cands c = {0, NCAND_MAX, n, malloc((size_t)n * NCAND_MAX * sizeof(double)), malloc(NCAND_MAX * 32)};
    g->g0[0] = 0;
    for (int i = 0; i < md->n; i++)
        if (!md->mode[i].selected && md->mode[i].frequency_hz > 0.01) {
            char nm2[32];
            snprintf(nm2, sizeof nm2, "mode%d_%c%.2f", i % 1000, gal_family_names[md->mode[i].family][0], md->mode[i].frequency_hz);
            cand_add(&c, md->shape + (size_t)i * n, nm2);
        }
    g->g1[0] = g->g0[1] = c.n;
    cand_aero(&c, m, g->s.data, g->s.sc->simulation.duration);
    g->g1[1] = g->g0[2] = c.n;
    cand_third(&c, m);
    g->g1[2] = g->g0[3] = c.n;
    for (int k = 0; k < g->npod; k++) cand_add(&c, g->P + (size_t)k * n, "pod");
    g->g1[3] = c.n;
    g->c = c;
    const double *th = c.X + (size_t)g->g0[2] * n;
    /* the cubic part's content along the trajectory, sum_{i<=j<=k} (multiplicity / 6) theta_ijk
     * eta_i eta_j eta_k, less its content in V */
    double *eta = trajectory_eta(m, 1, &nt), *Wt = calloc((size_t)n * nt, sizeof(double));
    for (int t = 0; t < nt; t++) {
        const double *e = eta + (size_t)t * nm;
        int id = 0;
        for (int j = 0; j < nm; j++)
            for (int k = j; k < nm; k++)
                for (int i = 0; i <= j; i++, id++) {
                    double mult = (i == j && j == k) ? 1 : (i == j || j == k) ? 3 : 6, w = mult / 6 * e[i] * e[j] * e[k];
                    for (int d = 0; d < n; d++) Wt[(size_t)t * n + d] += w * th[(size_t)id * n + d];
                }
        orth(m->rod, m->V, m->r, Wt + (size_t)t * n);
    }
    { /* the cubic part outside V against the motion, per family (an a-priori error indicator) */
        double a[4 * NBIN], fc[4], fu[4], cmax[4] = {0}, sc[4] = {0}, su[4] = {0};
        for (int t = 0; t < nt; t++) {
            famspan(m->rod, g->ni, Wt + (size_t)t * n, a), famsum(a, fc);
            famspan(m->rod, g->ni, rec.U + (size_t)t * n, a), famsum(a, fu);
            double tot = fu[0] + fu[1] + fu[2] + fu[3];
            for (int f = 0; f < 4; f++)
                sc[f] += fc[f], su[f] += fu[f], cmax[f] = fmax(cmax[f], sqrt(fc[f] / fmax(fu[f], 4e-4 * tot)));
        }
        int tb = 0;
        double cb = -1;
        for (int t = 0; t < nt; t++) {
            double c2 = mdot(m->rod, Wt + (size_t)t * n, Wt + (size_t)t * n);
            if (c2 > cb) cb = c2, tb = t;
        }
        g->Pst = malloc((size_t)n * 6 * sizeof(double));
        double shs[6];
        cubic_tangent_pod(m, th, eta + (size_t)tb * nm, 1, 0, nm < 6 ? nm : 6, g->Pst, shs);
        printf("INDICATOR largest cubic content at %.1f s\n", rec.tU[tb]);
        printf("INDICATOR cubic part outside V / motion per family (rms; max):");
        for (int f = 0; f < 4; f++) printf(" %s %.4f (%.4f)", gal_family_names[f], sqrt(sc[f] / su[f]), cmax[f]);
        printf("\n");
    }
    g->Pt = malloc((size_t)n * 16 * sizeof(double)), g->Ptan = malloc((size_t)n * 16 * sizeof(double));
    g->Prt = malloc((size_t)n * 32 * sizeof(double));
    pod(m->rod, Wt, nt, 16, g->Pt, g->sht);
    free(Wt), free(eta);
    eta = trajectory_eta(m, rec.ns > 200 ? rec.ns / 200 : 1, &nt);
    cubic_tangent_pod(m, th, eta, nt, 0, 16, g->Ptan, g->shtan);
    free(eta);
    eta = malloc((size_t)NTR * nm * sizeof(double));
    training_states(m, NTR, eta);
    cubic_tangent_pod(m, th, eta, NTR, !g->massw, 32, g->Prt, g->shrt);
    free(eta);
    printf("cubic part's content along the trajectory, POD shares:");
    for (int k = 0; k < 8; k++) printf(" %.3f", g->sht[k]);
    printf("; the first 4 capture %.3f of the projection error\n", captured(m->rod, g->E, rec.ns, g->Pt, 4));
    printf("cubic part's tangent along the trajectory, POD shares:");
    for (int k = 0; k < 16; k++) printf(" %.1e", g->shtan[k]);
    printf("\ncubic part's tangent at %d training states (%s), POD shares:", NTR, g->massw ? "mass-weighted" : "each snapshot normalized");
    for (int k = 0; k < 32; k++) printf(" %.1e", g->shrt[k]);
    printf("\n");
}

/* what share of the projection error each group (and its best single vector) captures */
static void capture_report(diag *g)
{
    static const char *gname[4] = {"modes", "aero", "third", "pod"};
    const gal_rod *rod = g->m->rod;
    int n = rod->ndof;
    double *Q = malloc((size_t)n * NCAND_MAX * sizeof(double));
    for (int k = 0; k < 4; k++) {
        int kept = cand_orth(&g->c, g->m, g->g0[k], g->g1[k], Q);
        printf("candidates %-6s %3d (kept %3d after V): capture %.3f of the error", gname[k], g->g1[k] - g->g0[k], kept,
               captured(rod, g->E, rec.ns, Q, kept));
        double bestc = 0;
        int bi = -1;
        for (int j = g->g0[k]; j < g->g1[k]; j++) {
            double cj = cand_orth(&g->c, g->m, j, j + 1, Q) ? captured(rod, g->E, rec.ns, Q, 1) : 0;
            if (cj > bestc) bestc = cj, bi = j;
            if (g->detail && cj > 0.01) printf("\n   %s %.3f", g->c.name[j], cj);
        }
        if (bi >= 0) printf("; best single %s %.3f", g->c.name[bi], bestc);
        printf("\n");
    }
    free(Q);
}

/* one --run: the group's vectors into X, then the reduced run */
static void run_group(diag *g, const char *spec, double *X)
{
    int n = g->m->ndof, nx = 0, *g0 = g->g0, *g1 = g->g1;
    const double *C = g->c.X;
    if (!strcmp(spec, "base")) nx = 0;
    else if (!strcmp(spec, "modes") || !strcmp(spec, "aero") || !strcmp(spec, "third") || !strcmp(spec, "aero+third")) {
        int a = spec[0] == 'm' ? 0 : spec[0] == 't' ? 2 : 1, b = !strcmp(spec, "aero+third") ? 2 : a;
        nx = g1[b] - g0[a];
        memcpy(X, C + (size_t)g0[a] * n, (size_t)n * nx * sizeof(double));
    } else if (!strncmp(spec, "match:", 6)) {
        char pat[512];
        for (int j = 0; j < g1[2]; j++) {
            snprintf(pat, sizeof pat, "%s", spec + 6);
            for (char *tok = strtok(pat, ","); tok; tok = strtok(NULL, ","))
                if (!fnmatch(tok, g->c.name[j], 0)) {
                    memcpy(X + (size_t)nx++ * n, C + (size_t)j * n, n * sizeof(double));
                    break;
                }
        }
    } else {
        int np = atoi(spec + (spec[0] == 'p' ? 3 : 4)), cap = 16;
        const double *src = g->Pt;
        if (!strncmp(spec, "pod", 3)) src = g->P, cap = g->npod;
        else if (!strncmp(spec, "ttan", 4)) src = g->Ptan;
        else if (!strncmp(spec, "stan", 4)) src = g->Pst, cap = 6;
        else if (!strncmp(spec, "rtan", 4)) {
            src = g->Prt, cap = 32;
            if (np == 0)
                while (np < 32 && g->shrt[np] >= 1e-5) np++;
        } else if (strncmp(spec, "tpod", 4)) {
            printf("RUN %s: unknown group\n", spec);
            return;
        }
        nx = np < cap ? np : cap;
        memcpy(X, src, (size_t)n * nx * sizeof(double));
        if (strstr(spec, "+aero"))
            memcpy(X + (size_t)n * nx, C + (size_t)g0[1] * n, (size_t)n * (g1[1] - g0[1]) * sizeof(double)), nx += g1[1] - g0[1];
    }
    if (g->cost) cost_probe(&g->s, X, nx, spec);
    else run_reduced(&g->s, &g->rf, X, nx, g->tol, spec);
}

int main(int argc, char **argv)
{
    const char *ov[32], *runs[16];
    int nov = 0, nrun = 0;
    diag g = {.npod = 8, .tol = -1};
    rec.every = 0.2, rec.from = -1;
    for (int i = 2; i < argc; i++)
        if (!strcmp(argv[i], "--set") && i + 1 < argc && nov < 32) ov[nov++] = argv[++i];
        else if (!strcmp(argv[i], "--every") && i + 1 < argc) rec.every = atof(argv[++i]);
        else if (!strcmp(argv[i], "--from") && i + 1 < argc) rec.from = atof(argv[++i]);
        else if (!strcmp(argv[i], "--pod") && i + 1 < argc) g.npod = atoi(argv[++i]) > 64 ? 64 : atoi(argv[i]);
        else if (!strcmp(argv[i], "--run") && i + 1 < argc && nrun < 16) runs[nrun++] = argv[++i];
        else if (!strcmp(argv[i], "--tol") && i + 1 < argc) g.tol = atof(argv[++i]);
        else if (!strcmp(argv[i], "--detail")) g.detail = 1;
        else if (!strcmp(argv[i], "--cost")) g.cost = 1;
        else if (!strcmp(argv[i], "--cost-from") && i + 1 < argc) cost_from = atof(argv[++i]);
        else if (!strcmp(argv[i], "--cost-span") && i + 1 < argc) cost_span = atof(argv[++i]);
        else if (!strcmp(argv[i], "--mass-weighted")) g.massw = 1;
    gal_scene sc;
    if (argc < 2 || gal_scene_load(&sc, argv[1], ov, nov, NULL) || gal_sim_setup_init(&g.s, &sc, 1) || setup(&g, &sc)) {
        fprintf(stderr, "%s\n", gal_error_message());
        return 1;
    }
    if (g.s.data->eq.rod->p.ecc_mass > 0 && g.s.data->eq.rod->p.ecc != 0) fprintf(stderr, "warning: eccentric ice: the POD's mass is the diagonal\n");
    projection(&g);
    candidates(&g);
    capture_report(&g);
    double *X = malloc((size_t)g.m->ndof * NCAND_MAX * sizeof(double));
    for (int k = 0; k < nrun; k++) run_group(&g, runs[k], X);
    return 0;
}
