/* diag_line.c: what feeds a reduced run's undamped high line (issue 13: data/scenes/iced_gallop.ini at
 * 600 elements rings 1.6 deg of twist at 6.38 Hz that the full model does not have). Per 30-s
 * window, the power that each term of the equations of motion puts into one direction psi
 * (M-normalized, free dofs), along the run's own trajectory:
 *   eta = psi^T M u, eta' = psi^T M v, E = eta'^2/2 + w2 eta^2/2, dE/dt = P_int + P_aero + P_damp,
 *   P_int = -eta' (psi^T g(q) - w2 eta)   (the rod's internal force less its linear part),
 *   P_aero = eta' psi^T F(t, q, v), split into the loads on the translations and on the twist,
 *   P_damp = -eta' psi^T C v;
 * for the reduced run both from the whole rod at the reconstructed state (exact projections) and
 * from the model's own forces (the sampled internal force fi, the loads fe it held, Cr v); the
 * remainder dE/dt - sum is the integrator's. The reduced run is the CLI's (integrator_rom.c's
 * loop: self-check, growth replayed from the start, the sample's check at the self-check): a first
 * pass finds the final basis, a second runs it from the start, recorded. psi: the reduced modes of
 * (K0r, I) in [--lo, --hi] Hz (V y), and the full rod's modes there (--full: the full run too,
 * measured along both). --kill aero|int T: from T on, the loads' (or the internal force's
 * nonlinear part's) projection on the strongest reduced band mode is removed (no load sample).
 * Usage: diag_line SCENE [--set key=value]... [--from T0] [--win W] [--lo HZ] [--hi HZ] [--full]
 *        [--nohyper] [--loads-every] [--tol T] [--kill aero|int|none T]
 * Built like the bench programs (make diag, or by hand as tests/bench/run.sh does). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gallop.h"
#include "gallop/base/core.h"
#include "gallop/reduced/rom_adapt.h"
#include "base/chol.h"

void dsyev_(const char *jobz, const char *uplo, const int *n, double *a, const int *lda, double *w, double *work,
            const int *lwork, int *info);

#include "diag_line.h"

/* ---- the kill wrapper: the loads less psi's share (aero) or plus the internal force's
 * nonlinear part along psi (int), from t_kill on ---- */
typedef struct {
    ctx_t *c;
    dir_t *d;
    int mode; /* 0 none, 1 aero, 2 int */
    double t_kill;
} kill_t;

static int kill_eval(void *ctx, double t, const double *q, const double *v, double *f)
{
    kill_t *k = ctx;
    int st = gal_loads_full((void *)k->c->loads, t, q, v, f);
    if (st || k->mode == 0 || t < k->t_kill) return st;
    const gal_rod *rod = k->c->rod;
    int n = rod->ndof;
    double s = 0;
    if (k->mode == 1)
        for (int i = 0; i < n; i++) s -= k->d->psi[i] * f[rod->free_q[i]];
    else {
        double lin = 0;
        for (int i = 0; i < n; i++) k->c->u[i] = q[rod->free_q[i]] - k->c->q_eq[rod->free_q[i]];
        gal_csc_symv(k->c->K0, k->c->u, k->c->w);
        for (int i = 0; i < n; i++) lin += k->d->psi[i] * k->c->w[i];
        gal_rod_eval(rod, q, NULL, k->c->g, NULL);
        for (int i = 0; i < n; i++) s += k->d->psi[i] * (k->c->g[rod->free_q[i]] - k->c->geq[i]);
        s -= lin;
    }
    for (int i = 0; i < n; i++) f[rod->free_q[i]] += s * k->d->mpsi[i];
    return GAL_OK;
}

/* ---- the reduced run, integrator_rom.c's loop ---- */
static double *g_twist; /* the mid-span twist (deg) at each recorded step */
typedef struct {
    double dt_out, t_end, h;
    gal_rom_opts ro;
    gal_force F;
    double tol;
    double tgrow;          /* the last growth's time (0: none) */
    double checks[4096];   /* the checks' times after it */
    int nchecks;
} run_t;

/* pass 1: the run as the CLI's, its growths; the final basis left in *a */
static int pass1(gal_sim_setup *s, run_t *R, gal_rom_adapt *a)
{
    gal_data *d = s->data;
    gal_rom *m;
    int st = gal_rom_adapt_init(a, &m, d->eq.rod, d->eq.q, &d->md, d->sel, d->basis, &R->ro, &R->F);
    if (st) return st;
    gal_rom_adapt_replay_from(a, d->q_start, d->v_start);
    if ((st = gal_rom_start(m, 0, d->q_start, d->v_start))) return st;
    double *du = malloc((size_t)d->eq.rod->ndof * sizeof(double)), next = 0;
    long ns = (long)floor(R->t_end / R->dt_out + 0.5) + 1;
    for (long i = 0; i < ns && !st; i++) {
        double tout = i * R->dt_out;
        if ((st = gal_rom_advance(m, tout))) break;
        if (!(m->t >= next - 1e-9 || i == ns - 1)) continue;
        if (next > 0 && m->t >= next - 1e-9 && (st = gal_rom_sample_check(m))) break;
        gal_rom_check chk;
        if ((st = gal_rom_adapt_residual(a, m, &chk, du))) break;
        if (R->nchecks < 4096) R->checks[R->nchecks++] = m->t;
        if (R->tol > 0 && chk.max > R->tol) {
            int g = gal_rom_adapt_grow(a, &m, &chk, du);
            if (g == GAL_OK) {
                R->tgrow = m->t, R->nchecks = 0;
                const gal_rom_event *e = &a->ev[a->nevents - 1];
                printf("GROW|%.3f s|residual %.3g|%s|%d -> %d|mode %.4f Hz|corrections %d\n", m->t, chk.max,
                       gal_family_names[e->family], e->basis_before, e->basis_after, e->mode_added_hz, e->corrections);
            } else if (g != GAL_ROM_ELIMIT) st = g;
        }
        double dt = gal_rom_check_interval(m, 1.0);
        while (next <= m->t + 1e-9) next += dt;
    }
    free(du);
    gal_rom_free(m);
    return st;
}

/* The reduced modes of the model in [lo, hi] Hz as directions (at most 8) */
static int band_dirs(gal_rom *m, double lo, double hi, dir_t *dir, int maxd)
{
    int r = m->r, n = m->ndof, lw = 64 * r, info = 0, nd = 0;
    double *A = malloc(((size_t)r * r + r + lw) * sizeof(double)), *w = A + (size_t)r * r, *wk = w + r;
    memcpy(A, m->K0r, (size_t)r * r * sizeof(double));
    dsyev_("V", "U", &r, A, &r, w, wk, &lw, &info);
    for (int k = 0; k < r && !info && nd < maxd; k++) {
        double hz = w[k] > 0 ? sqrt(w[k]) / (2 * GAL_PI) : 0;
        if (hz < lo || hz > hi) continue;
        dir_t *d = &dir[nd++];
        double *y = malloc((size_t)r * sizeof(double));
        memcpy(y, A + (size_t)k * r, (size_t)r * sizeof(double));
        d->y = y, d->w2 = w[k], d->hz = hz;
        d->psi = calloc((size_t)n, sizeof(double)), d->mpsi = malloc((size_t)n * sizeof(double));
        for (int i = 0; i < r; i++)
            for (int j = 0; j < n; j++) d->psi[j] += y[i] * m->V[(size_t)i * n + j];
        gal_rod_mass_mult(m->rod, d->psi, d->mpsi);
        d->deg = mid_twist(m->rod, d->psi);
        snprintf(d->name, sizeof d->name, "reduced mode %.4f Hz", hz);
    }
    free(A);
    return nd;
}

/* --corr: the corrections' translations zeroed (1), or each replaced by K0^-1 of its residual's
 * twist part, R = K0 du restricted to the twist (2) */
static int alter_corrections(gal_sim_setup *s, gal_rom_adapt *a, int how)
{
    const gal_rod *rod = s->data->eq.rod;
    int n = rod->ndof, st = GAL_OK;
    gal_rom *m0 = NULL;
    double *R = malloc((size_t)n * sizeof(double));
    if (how == 2) { /* K0 and its factorization from a model on the initial basis */
        gal_rom_opts o = a->o;
        m0 = gal_rom_alloc(rod, a->q_eq, a->md, a->sel, a->nsel, &o, &a->force);
        if (!m0) return GAL_EFAIL;
    }
    for (int k = 0; k < a->nextra && !st; k++) {
        double *du = a->extra + (size_t)k * n;
        if (how == 1) {
            for (int j = 0; j < n; j++)
                if (rod->free_q[j] < 3 * rod->nn) du[j] = 0;
            continue;
        }
        gal_csc_symv(m0->K0, du, R);
        for (int j = 0; j < n; j++)
            if (rod->free_q[j] < 3 * rod->nn) R[j] = 0;
        st = gal_chol_solve(m0->chol0, R, du);
    }
    free(R);
    gal_rom_free(m0);
    return st;
}

/* pass 2: the final basis from the start (the replay: no sample check up to the last growth),
 * every step recorded from t0 along the band directions; the kill from kt */
static int pass2(gal_sim_setup *s, run_t *R, gal_rom_adapt *a, ctx_t *c, double t0, double lo, double hi,
                 int kmode, double kt, dir_t *dir, int *nd, double **tt, long *nrec, gal_rom **mout)
{
    gal_data *d = s->data;
    gal_rom_opts o = a->o;
    o.extra = a->extra, o.nextra = a->nextra;
    static kill_t K;
    gal_force F = R->F;
    if (kmode) K.c = c, K.mode = kmode, K.t_kill = kt, F.eval = kill_eval, F.element = NULL, F.ctx = &K;
    gal_rom *m = gal_rom_alloc(d->eq.rod, d->eq.q, a->md, a->sel, a->nsel, &o, &F);
    if (!m) return GAL_EFAIL;
    *nd = band_dirs(m, lo, hi, dir, 8);
    if (kmode && *nd) { /* the strongest twist of the band */
        int b = 0;
        for (int k = 1; k < *nd; k++)
            if (fabs(dir[k].deg) > fabs(dir[b].deg)) b = k;
        K.d = &dir[b];
        printf("KILL|%s|along %s from %.1f s\n", kmode == 1 ? "aero" : "int", dir[b].name, kt);
    }
    c->K0 = m->K0;
    int r = m->r, ic = 0;
    double *fi0 = calloc((size_t)3 * r, sizeof(double)), *crv = fi0 + r, *x0 = crv + r;
    int st = gal_rom_internal_force(m, x0, fi0); /* before the start: the state's forces are its */
    if (!st) st = gal_rom_start(m, 0, d->q_start, d->v_start);
    long cap = (long)((R->t_end - t0) / m->o.h) + 16, nr = 0;
    *tt = malloc((size_t)cap * sizeof(double));
    g_twist = malloc((size_t)cap * sizeof(double));
    for (int k = 0; k < *nd; k++) dir[k].rec = malloc((size_t)cap * NT * sizeof(double));
    long ns = (long)floor(R->t_end / R->dt_out + 0.5) + 1;
    for (long i = 0; i < ns && !st; i++) {
        double tout = i * R->dt_out;
        while (m->t < tout - 1e-3 * m->o.h && !st) {
            if ((st = gal_rom_step(m))) break;
            if (m->t < t0 - 1e-9 || nr >= cap) continue;
            for (int p = 0; p < r; p++) {
                double sc = 0;
                for (int q = 0; q < r; q++) sc += m->Cr[p * r + q] * m->v[q];
                crv[p] = sc;
            }
            double *q = malloc((size_t)2 * m->nq * sizeof(double));
            gal_rom_reconstruct(m, q, q + m->nq);
            for (int k = 0; k < *nd; k++) terms(c, &dir[k], m->t, q, q + m->nq, m->fi, m->fe, crv, fi0, r, dir[k].rec + nr * NT);
            free(q);
            double half = 0.5, row[4], ten[2];
            gal_rom_observe(m, 1, &half, row, ten);
            g_twist[nr] = row[3];
            (*tt)[nr++] = m->t;
        }
        if (st) break;
        while (ic < R->nchecks && R->checks[ic] < m->t - 1e-9) ic++;
        if (ic < R->nchecks && fabs(R->checks[ic] - m->t) < 1e-9 && m->t > R->tgrow + 1e-9) st = gal_rom_sample_check(m);
    }
    free(fi0);
    *nrec = nr, *mout = m;
    return st;
}

/* the mid-span twist p-p over [a, b] */
static double pp(const double *tt, const double *x, long n, double a, double b)
{
    double lo = INFINITY, hi = -INFINITY;
    for (long i = 0; i < n; i++)
        if (tt[i] >= a && tt[i] <= b) lo = fmin(lo, x[i]), hi = fmax(hi, x[i]);
    return hi - lo;
}

/* the full run (integrator_full.c's), recorded from t0 along the directions */
static int full_run(gal_sim_setup *s, run_t *R, ctx_t *c, double t0, dir_t *dir, int nd, double **tt, long *nrec)
{
    gal_data *d = s->data;
    const gal_rod *rod = d->eq.rod;
    gal_dyn_opts go;
    gal_dyn_default_opts(&go);
    go.h = R->h, go.rho_inf = R->ro.rho_inf, go.newton_tol = R->ro.newton_tol, go.damping = d->damping;
    gal_force F = {0};
    if (d->loads.table) F.eval = gal_loads_full, F.ctx = (void *)&d->loads;
    gal_dyn *dy = gal_dyn_alloc(rod, d->q_start, d->v_start, &go, &F);
    if (!dy) return GAL_EFAIL;
    long nsteps = (long)floor(R->t_end / go.h + 0.5), cap = nsteps + 16, nr = 0;
    *tt = malloc((size_t)cap * sizeof(double));
    g_twist = malloc((size_t)cap * sizeof(double));
    for (int k = 0; k < nd; k++) dir[k].rec = malloc((size_t)cap * NT * sizeof(double));
    int st = GAL_OK, mid = 3 * rod->nn + rod->p.elements / 2;
    while (dy->steps < nsteps && !st) {
        if ((st = gal_dyn_step(dy))) break;
        if (dy->t < t0 - 1e-9) continue;
        for (int k = 0; k < nd; k++) terms(c, &dir[k], dy->t, dy->q, dy->v, NULL, NULL, NULL, NULL, 0, dir[k].rec + nr * NT);
        g_twist[nr] = 0.5 * (dy->q[mid] - d->eq.q[mid] + dy->q[mid - 1] - d->eq.q[mid - 1]) * 180 / GAL_PI;
        (*tt)[nr++] = dy->t;
    }
    *nrec = nr;
    gal_dyn_free(dy);
    return st;
}

typedef struct {
    const char *ov[32];
    int nov, full, nohyper, every, kmode, corr;
    double t0, win, lo, hi, tol, kt;
} args_t;

static int parse(int argc, char **argv, args_t *A)
{
    memset(A, 0, sizeof *A);
    A->t0 = 150, A->win = 30, A->lo = 5.5, A->hi = 7.5, A->tol = -1;
    for (int i = 2; i < argc; i++) {
        const char *s = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(s, "--full")) A->full = 1;
        else if (!strcmp(s, "--nohyper")) A->nohyper = 1;
        else if (!strcmp(s, "--loads-every")) A->every = 1;
        else if (!v) return 2;
        else if (!strcmp(s, "--set") && A->nov < 32) A->ov[A->nov++] = v, i++;
        else if (!strcmp(s, "--from")) A->t0 = atof(v), i++;
        else if (!strcmp(s, "--win")) A->win = atof(v), i++;
        else if (!strcmp(s, "--lo")) A->lo = atof(v), i++;
        else if (!strcmp(s, "--hi")) A->hi = atof(v), i++;
        else if (!strcmp(s, "--tol")) A->tol = atof(v), i++;
        else if (!strcmp(s, "--corr")) A->corr = !strcmp(v, "twist0") ? 1 : !strcmp(v, "twistR") ? 2 : 0, i++;
        else if (!strcmp(s, "--kill") && i + 2 < argc) {
            A->kmode = !strcmp(v, "aero") ? 1 : !strcmp(v, "int") ? 2 : 0;
            A->kt = atof(argv[i + 2]), i += 2;
        } else return 2;
    }
    return 0;
}

/* the run's step, sampling and model options as the CLI's (sim.c, integrator_rom.c) */
static void run_setup(const gal_scene *sc, const gal_data *d, const args_t *A, run_t *R)
{
    gal_run_opts o;
    gal_run_opts_from_scene(sc, &o);
    double fhi = 0;
    for (int k = 0; k < d->md.n; k++)
        if (d->md.mode[k].selected) fhi = fmax(fhi, d->md.mode[k].frequency_hz);
    R->dt_out = o.output_interval > 0 ? o.output_interval : fmin(0.05, 1.0 / (10 * fhi));
    double h = o.time_step > 0 ? o.time_step : fmin(R->dt_out, 1.0 / (40 * fhi));
    int sub = (int)ceil(R->dt_out / h - 1e-9);
    R->h = R->dt_out / sub, R->t_end = o.duration;
    gal_rom_default_opts(&R->ro);
    R->ro.h = R->h, R->ro.rho_inf = o.rho_inf, R->ro.damping = d->damping, R->ro.hyper_check_interval = 0;
    if (o.newton_tol > 0) R->ro.newton_tol = o.newton_tol;
    if (A->nohyper) R->ro.hyper = 0;
    if (A->every) R->ro.loads_once = 0;
    if (d->loads.table) R->F.eval = gal_loads_full, R->F.element = gal_loads_element, R->F.ctx = (void *)&d->loads;
    R->tol = A->tol >= 0 ? A->tol : sc->model.residual_tolerance;
}

/* the full rod's modes in [lo, hi] as directions after dir[0..nd-1]; their overlaps with those */
static int full_dirs(const gal_scene *sc, const gal_data *d, ctx_t *c, const gal_rom *m, const gal_rom_adapt *a,
                     double lo, double hi, dir_t *dir, int nd)
{
    const gal_rod *rod = d->eq.rod;
    int n = rod->ndof, nfull = 0;
    static gal_modes fm;
    int want[GAL_FAMILY_COUNT] = {sc->model.modes_vertical, sc->model.modes_horizontal, 4, 0};
    if (gal_modes_find(rod, d->eq.q, want, 200, &fm)) printf("ERR|modes: %s\n", gal_error_message());
    for (int k = 0; k < fm.n && nd + nfull < 16; k++) {
        if (fm.mode[k].frequency_hz < lo || fm.mode[k].frequency_hz > hi) continue;
        dir_t *e = &dir[nd + nfull++];
        e->psi = fm.shape + (size_t)k * n, e->mpsi = malloc((size_t)n * sizeof(double));
        gal_rod_mass_mult(rod, e->psi, e->mpsi);
        e->w2 = fm.mode[k].omega * fm.mode[k].omega, e->hz = fm.mode[k].frequency_hz, e->deg = mid_twist(rod, e->psi);
        snprintf(e->name, sizeof e->name, "full mode %.4f Hz (%s)", e->hz, gal_family_names[fm.mode[k].family]);
    }
    for (int i = 0; i < nd; i++) {
        compose(m, a, &dir[i]);
        for (int k = nd; k < nd + nfull; k++) {
            double ov = 0;
            for (int j = 0; j < n; j++) ov += dir[i].mpsi[j] * dir[k].psi[j];
            printf("OVERLAP|%s|%s|%.4f\n", dir[i].name, dir[k].name, ov);
            rest(c, &dir[i], &dir[k], ov);
        }
    }
    return nfull;
}

int main(int argc, char **argv)
{
    args_t A;
    if (argc < 2 || parse(argc, argv, &A)) {
        fprintf(stderr, "usage: diag_line SCENE [--set k=v]... [--from T0] [--win W] [--lo HZ] [--hi HZ] [--full] "
                        "[--nohyper] [--loads-every] [--tol T] [--corr twist0|twistR] [--kill aero|int|none T]\n");
        return 2;
    }
    gal_scene sc;
    gal_sim_setup s;
    if (gal_scene_load(&sc, argv[1], A.ov, A.nov, NULL) || gal_sim_setup_init(&s, &sc, 1) ||
        gal_forward(s.model, s.data, GAL_STAGE_REDUCED)) {
        printf("ERR|%s\n", gal_error_message());
        return 1;
    }
    gal_data *d = s.data;
    const gal_rod *rod = d->eq.rod;
    run_t *R = calloc(1, sizeof *R);
    run_setup(&sc, d, &A, R);
    printf("RUN|%s|%d elements|h %.6g s|output %.6g s|rho_inf %.3g|duration %.0f s|hyper %d|loads_once %d|tol %.3g\n",
           argv[1], rod->p.elements, R->h, R->dt_out, R->ro.rho_inf, R->t_end, R->ro.hyper, R->ro.loads_once, R->tol);
    gal_rom_adapt a;
    int st = pass1(&s, R, &a);
    if (!st && A.corr) st = alter_corrections(&s, &a, A.corr);
    if (st) { printf("ERR|pass 1: %s\n", gal_error_message()); return 1; }
    int n = rod->ndof, nd = 0;
    ctx_t c = {rod, &d->loads, d->damping, NULL, NULL, d->eq.q, NULL, NULL, NULL, NULL, NULL, NULL};
    c.g = malloc((size_t)2 * rod->nq * sizeof(double)), c.f = c.g + rod->nq, c.K = gal_csc_clone(rod->K);
    c.u = malloc((size_t)4 * n * sizeof(double)), c.w = c.u + n, c.mp = c.w + n, c.geq = c.mp + n;
    gal_rod_eval(rod, d->eq.q, NULL, c.g, NULL);
    gal_rod_gather(rod, c.g, c.geq);
    dir_t dir[16];
    memset(dir, 0, sizeof dir);
    double *tt;
    long nrec;
    gal_rom *m;
    if ((st = pass2(&s, R, &a, &c, A.t0, A.lo, A.hi, A.kmode, A.kt, dir, &nd, &tt, &nrec, &m))) {
        printf("ERR|pass 2: %s\n", gal_error_message());
        return 1;
    }
    printf("BASIS|%d vectors|%d modes|%d corrections|last growth %.2f s\n", m->r, a.nsel, a.nextra, R->tgrow);
    double te = tt[nrec - 1], tw = fmax(tt[0], te - 60);
    printf("TWIST|reduced|p-p %.4g deg over %.0f-%.0f s\n", pp(tt, g_twist, nrec, tw, te), tw, te);
    int nfull = full_dirs(&sc, d, &c, m, &a, A.lo, A.hi, dir, nd);
    for (int k = 0; k < nd; k++) report("reduced run", &dir[k], nrec, tt, A.t0, A.win, A.lo, A.hi);
    if (!A.full) return 0;
    for (int k = 0; k < nd + nfull; k++) free(dir[k].rec), dir[k].rec = NULL;
    if ((st = full_run(&s, R, &c, A.t0, dir, nd + nfull, &tt, &nrec))) { printf("ERR|full: %s\n", gal_error_message()); return 1; }
    printf("TWIST|full|p-p %.4g deg over %.0f-%.0f s\n", pp(tt, g_twist, nrec, tw, te), tw, te);
    for (int k = 0; k < nd + nfull; k++) report("full run", &dir[k], nrec, tt, A.t0, A.win, A.lo, A.hi);
    return 0;
}
