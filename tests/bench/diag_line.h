/* diag_line.h: the measures of tests/bench/diag_line.c (issue 13): the terms of the equations of
 * motion along a direction over a run, their power per window and their lines; the makeup of a
 * reduced band mode. Included by diag_line.c alone. */
#ifndef GALLOP_DIAG_LINE_H
#define GALLOP_DIAG_LINE_H

enum { T_ETA, T_ETAD, T_INT, T_ATR, T_ATW, T_DAMP, T_SINT, T_SAER, T_SDMP, T_FNL, T_FAER, T_KEFF, NT };

typedef struct {
    const gal_rod *rod;
    const gal_loads *loads;
    const gal_damping *damp;
    const gal_csc *K0;
    gal_csc *K;                  /* the tangent's scratch (the rod's pattern) */
    const double *q_eq;
    double *g, *f, *u, *w, *mp;  /* nq, nq, ndof, ndof, ndof */
    double *geq;                 /* ndof: the free gradient at q_eq */
} ctx_t;

typedef struct {     /* a direction and its record */
    double *psi, *mpsi, w2, hz, deg; /* ndof, ndof: M psi; deg: the twist at mid-span per unit eta */
    const double *y; /* reduced shape (r) or NULL */
    double *rec;     /* nrec x NT */
    char name[48];
} dir_t;

/* The terms along d at the full state (t, q, v) (v over the configuration); the model's own from
 * fi, fe, Cr v (r each) when given. */
static void terms(ctx_t *c, dir_t *d, double t, const double *q, const double *vq, const double *fi,
                  const double *fe, const double *crv, const double *fi0, int r, double *out)
{
    const gal_rod *rod = c->rod;
    int n = rod->ndof;
    double eta = 0, etad = 0, gi = 0, atr = 0, atw = 0, dm = 0, lin = 0;
    for (int k = 0; k < n; k++) c->u[k] = q[rod->free_q[k]] - c->q_eq[rod->free_q[k]];
    for (int k = 0; k < n; k++) eta += d->mpsi[k] * c->u[k], etad += d->mpsi[k] * vq[rod->free_q[k]];
    gal_csc_symv(c->K0, c->u, c->w);
    for (int k = 0; k < n; k++) lin += d->psi[k] * c->w[k];
    gal_rod_eval(rod, q, NULL, c->g, c->K);
    double ke = 0;
    gal_csc_symv(c->K, d->psi, c->w);
    for (int k = 0; k < n; k++) ke += d->psi[k] * c->w[k];
    out[T_KEFF] = ke;
    memset(c->f, 0, (size_t)rod->nq * sizeof(double));
    if (c->loads->table) gal_loads_full((void *)c->loads, t, q, vq, c->f);
    for (int k = 0; k < n; k++) {
        int qi = rod->free_q[k];
        gi += d->psi[k] * (c->g[qi] - c->geq[k]);
        if (qi < 3 * rod->nn) atr += d->psi[k] * c->f[qi];
        else atw += d->psi[k] * c->f[qi];
        c->w[k] = vq[qi];
    }
    memset(c->u, 0, (size_t)n * sizeof(double));
    if (c->damp) gal_damping_apply(c->damp, c->w, c->u);
    for (int k = 0; k < n; k++) dm += d->psi[k] * c->u[k];
    out[T_ETA] = eta, out[T_ETAD] = etad;
    out[T_INT] = -(gi - lin) * etad, out[T_ATR] = atr * etad, out[T_ATW] = atw * etad, out[T_DAMP] = -dm * etad;
    out[T_SINT] = out[T_SAER] = out[T_SDMP] = 0;
    out[T_FNL] = gi - lin, out[T_FAER] = atr + atw;
    if (fi && d->y) {
        double si = 0, sa = 0, sd = 0, yl = 0;
        for (int k = 0; k < r; k++) si += d->y[k] * (fi[k] - fi0[k]), sa += d->y[k] * fe[k], sd += d->y[k] * crv[k];
        yl = d->w2 * eta;
        out[T_SINT] = -(si - yl) * etad, out[T_SAER] = sa * etad, out[T_SDMP] = -sd * etad;
    }
}

/* |DFT| amplitude of x (n samples every dt) at its peak in [lo, hi] Hz (Hann), the peak into *fp */
static double line(const double *x, long n, int stride, double dt, double lo, double hi, double *fp)
{
    double best = 0, mean = 0;
    for (long i = 0; i < n; i++) mean += x[i * stride];
    mean /= n;
    *fp = 0;
    for (double f = lo; f <= hi; f += 0.2 / (n * dt)) {
        double re = 0, im = 0, ws = 0;
        for (long i = 0; i < n; i++) {
            double w = 0.5 - 0.5 * cos(2 * GAL_PI * i / (n - 1)), a = 2 * GAL_PI * f * i * dt;
            re += w * (x[i * stride] - mean) * cos(a), im += w * (x[i * stride] - mean) * sin(a), ws += w;
        }
        double amp = 2 * sqrt(re * re + im * im) / ws;
        if (amp > best) best = amp, *fp = f;
    }
    return best;
}

static void report(const char *who, dir_t *d, long nrec, const double *tt, double t0, double win, double lo, double hi)
{
    printf("DIR|%s|%s|%.4f Hz|twist at mid-span %.4g deg per unit\n", who, d->name, d->hz, d->deg);
    printf("WIN|%s|%s|t0|t1|line deg|at Hz|dE/dt|P_int|P_aero_tr|P_aero_tw|P_damp|P_int model|P_aero model|P_damp model|"
           "integrator|F_int line|at Hz|F_aero line|at Hz\n", who, d->name);
    for (double a = t0; a + win <= tt[nrec - 1] + 1e-6; a += win) {
        long i0 = -1, i1 = -1;
        for (long i = 0; i < nrec; i++) {
            if (i0 < 0 && tt[i] >= a - 1e-9) i0 = i;
            if (tt[i] <= a + win + 1e-9) i1 = i;
        }
        if (i0 < 0 || i1 <= i0 + 10) continue;
        double s[NT] = {0}, fp;
        for (long i = i0; i < i1; i++)
            for (int k = T_INT; k <= T_SDMP; k++) s[k] += 0.5 * (d->rec[i * NT + k] + d->rec[(i + 1) * NT + k]) * (tt[i + 1] - tt[i]);
        double T = tt[i1] - tt[i0];
        const double *r0 = d->rec + i0 * NT, *r1 = d->rec + i1 * NT;
        double e0 = 0.5 * r0[T_ETAD] * r0[T_ETAD] + 0.5 * d->w2 * r0[T_ETA] * r0[T_ETA];
        double e1 = 0.5 * r1[T_ETAD] * r1[T_ETAD] + 0.5 * d->w2 * r1[T_ETA] * r1[T_ETA];
        double amp = line(d->rec + i0 * NT + T_ETA, i1 - i0 + 1, NT, (tt[i1] - tt[i0]) / (i1 - i0), lo, hi, &fp);
        double kmin = INFINITY, kmax = -INFINITY, km = 0;
        for (long i = i0; i <= i1; i++) {
            double kk = d->rec[i * NT + T_KEFF];
            kmin = fmin(kmin, kk), kmax = fmax(kmax, kk), km += kk / (i1 - i0 + 1);
        }
        printf("KEFF|%s|%s|%.1f|%.1f|mean %.4f Hz|min %.4f|max %.4f|psi^T K0 psi %.4f Hz\n", who, d->name, tt[i0], tt[i1],
               sqrt(fmax(km, 0)) / (2 * GAL_PI), sqrt(fmax(kmin, 0)) / (2 * GAL_PI), sqrt(fmax(kmax, 0)) / (2 * GAL_PI),
               sqrt(d->w2) / (2 * GAL_PI));
        double de = (e1 - e0) / T, own = s[T_SINT] + s[T_SAER] + s[T_SDMP], ff, fa;
        double dt = (tt[i1] - tt[i0]) / (i1 - i0);
        double fn = line(d->rec + i0 * NT + T_FNL, i1 - i0 + 1, NT, dt, lo, hi, &ff);
        double an = line(d->rec + i0 * NT + T_FAER, i1 - i0 + 1, NT, dt, lo, hi, &fa);
        printf("WIN|%s|%s|%.1f|%.1f|%.3g|%.3f|%.3g|%.3g|%.3g|%.3g|%.3g|%.3g|%.3g|%.3g|%.3g|%.3g|%.3f|%.3g|%.3f\n", who, d->name, tt[i0], tt[i1],
               amp * fabs(d->deg), fp, de, s[T_INT] / T, s[T_ATR] / T, s[T_ATW] / T, s[T_DAMP] / T, s[T_SINT] / T,
               s[T_SAER] / T, s[T_SDMP] / T, d->y ? de - own / T : de - (s[T_INT] + s[T_ATR] + s[T_ATW] + s[T_DAMP]) / T,
               fn, ff, an, fa);
    }
}

/* the twist dof at mid-span of a free-dof vector */
static double mid_twist(const gal_rod *rod, const double *x)
{
    int d = rod->dof[3 * rod->nn + rod->p.elements / 2];
    return d < 0 ? 0 : x[d] * 180 / GAL_PI;
}

/* the basis vectors that make up a reduced band mode (its largest coefficients) */
static void compose(const gal_rom *m, const gal_rom_adapt *a, const dir_t *d)
{
    int r = m->r, used[96] = {0};
    printf("COMPOSE|%s", d->name);
    for (int t = 0; t < 6 && t < r; t++) {
        int b = -1;
        for (int i = 0; i < r; i++)
            if (!used[i] && (b < 0 || fabs(d->y[i]) > fabs(d->y[b]))) b = i;
        used[b] = 1;
        if (b < m->nmodes) printf("|mode %.4f Hz %.3f", sqrt(m->omega2[b]) / (2 * GAL_PI), d->y[b]);
        else if (b >= r - a->nextra) printf("|correction %d %.3f", b - (r - a->nextra), d->y[b]);
        else printf("|derivative col %d %.3f", b, d->y[b]);
    }
    printf("\n");
}

/* psi's part outside the full mode phi (ov = phi^T M psi): its mass share per family and its
 * share of psi's stiffness psi^T K0 psi */
static void rest(ctx_t *c, const dir_t *d, const dir_t *f, double ov)
{
    const gal_rod *rod = c->rod;
    int n = rod->ndof;
    double tw = 0, tr = 0, kr = 0, kp = 0;
    for (int j = 0; j < n; j++) c->u[j] = d->psi[j] - ov * f->psi[j];
    for (int j = 0; j < n; j++) {
        double e = c->u[j] * c->u[j] * rod->mdiag[j];
        if (rod->free_q[j] < 3 * rod->nn) tr += e;
        else tw += e;
    }
    gal_csc_symv(c->K0, c->u, c->w);
    for (int j = 0; j < n; j++) kr += c->u[j] * c->w[j];
    gal_csc_symv(c->K0, d->psi, c->w);
    for (int j = 0; j < n; j++) kp += d->psi[j] * c->w[j];
    printf("REST|%s less %s|mass: translations %.3g, twist %.3g|stiffness %.3g of psi's (%.4g Hz alone)\n", d->name,
           f->name, tr, tw, kr / kp, sqrt(kr / fmax(tr + tw, 1e-300)) / (2 * GAL_PI));
}

#endif
