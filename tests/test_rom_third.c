/* test_rom_third.c: a check tripped by the cubic indicator (rom_adapt.h) grows the basis by the
 * selected modes' third-order modal derivatives, on the initial basis, and the grown model's replay
 * from the start is handed to the run's record (replay_observe), so that what a run reports before
 * a late growth is the grown model's. The case: tests/rom/grosbeak_300_soft_gj.ini (the span whose
 * basis lacks that coupling: BENCHMARKS.md, issue 13, helper soft) at 40 elements, 30 s.
 *  - the growth: the initial selection back (the corrections and modes grown before dropped), the
 *    nsel (nsel+1)(nsel+2)/6 derivatives added, the cubic indicator then reads nothing outside the
 *    basis (before: the vertical part it trips on);
 *  - the replay's observations are those of a model allocated on the grown basis and run from the
 *    start through the same output times, to the bit;
 *  - a second cubic trip, or a residual's, is not grown on (GAL_ROM_ELIMIT, naming the third-order
 *    derivatives). */
#include "check.h"
#include "sim_fixture.h"
#include "gallop.h"
#include "gallop/reduced/rom_adapt.h"

#define DT_OUT 0.05
#define NREC 1024

static struct {
    int nprobe;
    const double *probe;
    long n;
    double row[NREC][4 * 2 + 2];
} rec;

static void observe(void *ctx, const gal_rom *m, long i)
{
    (void)ctx;
    if (i >= NREC || i != rec.n) { rec.n = -1; return; } /* in order, from 0, each once */
    gal_rom_observe(m, rec.nprobe, rec.probe, rec.row[i], rec.row[i] + 4 * rec.nprobe);
    rec.n++;
}

/* A check at the state of m that trips by the cubic part of family f. */
static void cubic_trip(gal_rom_adapt *a, gal_rom *m, gal_rom_check *chk, double *du, gal_family f)
{
    int st = gal_rom_adapt_residual(a, m, chk, du);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    chk->cubic[f] = 0.5;
    chk->rel[f] = chk->max = chk->cubic[f] / GAL_ROM_CUBIC_SHARE;
}

static void test_third(void)
{
    gal_scene sc;
    const char *ov[] = {"model.elements=40", "simulation.duration=30"};
    gal_sim_setup s;
    gal_data *d = forward_fixture(&sc, &s, "tests/rom/grosbeak_300_soft_gj.ini", ov, 2);
    if (!d) return;
    const gal_rod *rod = d->eq.rod;
    double fhi = 0;
    for (int k = 0; k < d->basis; k++) fhi = fmax(fhi, d->md.mode[d->sel[k]].frequency_hz);
    gal_rom_opts o;
    gal_rom_default_opts(&o);
    o.h = DT_OUT / ceil(DT_OUT * 40 * fhi - 1e-9), o.damping = d->damping;
    gal_force F = {gal_loads_full, (void *)&d->loads, gal_loads_element, gal_loads_full_framed};
    gal_rom_adapt a;
    gal_rom *m = NULL, *ref = NULL;
    gal_rom_check chk;
    double *du = malloc((size_t)rod->ndof * sizeof(double)), ce0[GAL_FAMILY_COUNT], ce1[GAL_FAMILY_COUNT];
    int nsel = d->basis, nt = nsel * (nsel + 1) * (nsel + 2) / 6;
    int st = gal_rom_adapt_init(&a, &m, rod, d->eq.q, &d->md, d->sel, nsel, &o, &F);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    if (st) goto done;
    a.relax = 0;
    gal_rom_adapt_replay_from(&a, d->q_start, d->v_start);
    rec.nprobe = s.model->nprobe, rec.probe = s.model->probe, rec.n = 0;
    CHECK(rec.nprobe <= 2, "probes %d", rec.nprobe);
    a.replay_observe = observe, a.replay_dt = DT_OUT;
    int r0 = m->r;
    /* ordinary growths first (a mode, then a correction), which the cubic one drops */
    if (!(st = gal_rom_start(m, 0.0, d->q_start, d->v_start))) st = gal_rom_advance(m, 10.0);
    a.policy = GAL_ROM_ADD_MODE;
    if (!st) st = gal_rom_adapt_residual(&a, m, &chk, du);
    if (!st) st = gal_rom_adapt_grow(&a, &m, &chk, du);
    a.policy = GAL_ROM_ADD_CORRECTION;
    if (!st) st = gal_rom_advance(m, 15.0);
    if (!st) st = gal_rom_adapt_residual(&a, m, &chk, du);
    if (!st) st = gal_rom_adapt_grow(&a, &m, &chk, du);
    CHECK(st == GAL_OK && a.nsel == nsel + 1 && a.nextra == 1, "a mode and a correction: %s (modes %d, extra %d)",
          st ? gal_error_message() : "", a.nsel, a.nextra);
    rec.n = 0;
    if (!st) st = gal_rom_advance(m, 25.0);
    if (!st) st = gal_rom_cubic(m, m->x, ce0);
    double t = m->t;
    if (!st) cubic_trip(&a, m, &chk, du, GAL_FAMILY_VERTICAL), st = gal_rom_adapt_grow(&a, &m, &chk, du);
    CHECK(st == GAL_OK, "the cubic growth: %s", gal_error_message());
    if (st) goto done;
    const gal_rom_event *e = &a.ev[a.nevents - 1];
    printf("    grosbeak 40 el.: %d modes, basis %d -> %d (%d third-order derivatives, %d kept) at %.2f s\n", nsel,
           e->basis_before, e->basis_after, nt, m->r - r0, t);
    CHECK(a.nevents == 3 && e->corrections == nt && e->mode_added < 0 && a.third == nt && a.nsel == nsel &&
              a.nextra == nt && m->nmodes == nsel && m->r > r0 + nt / 2 && m->r <= r0 + nt && m->t == t,
          "the cubic growth: events %d, added %d (want %d), modes %d, extra %d, basis %d, t %g", a.nevents,
          e->corrections, nt, a.nsel, a.nextra, m->r, m->t);
    /* the indicator reads nothing left outside the grown basis */
    st = gal_rom_cubic(m, m->x, ce1);
    printf("    cubic part outside the basis, vertical / horizontal: before %.3g / %.3g, after %.3g / %.3g\n",
           ce0[0], ce0[1], ce1[0], ce1[1]);
    CHECK(!st && ce0[GAL_FAMILY_VERTICAL] > 0 && ce1[GAL_FAMILY_VERTICAL] <= 1e-5 * ce0[GAL_FAMILY_VERTICAL] &&
              ce1[GAL_FAMILY_HORIZONTAL] <= 1e-5 * ce0[GAL_FAMILY_VERTICAL],
          "the cubic part outside: %g, %g (before %g)", ce1[0], ce1[1], ce0[0]);
    /* the replay's record: every output time before t, the grown model's run from the start */
    long want = (long)ceil(t / DT_OUT - 1e-3 * m->o.h / DT_OUT);
    CHECK(rec.n == want, "replay observations %ld, want %ld", rec.n, want);
    gal_rom_opts o2 = o;
    o2.extra = a.extra, o2.nextra = a.nextra;
    ref = gal_rom_alloc(rod, d->eq.q, a.md, a.sel, a.nsel, &o2, &F);
    CHECK(ref && ref->r == m->r, "the grown basis again: %s", ref ? "" : gal_error_message());
    if (ref && !(st = gal_rom_start(ref, 0.0, d->q_start, d->v_start))) {
        double worst = 0, row[4 * 2 + 2];
        for (long i = 0; i < rec.n && !st; i++) {
            if ((st = gal_rom_advance(ref, i * DT_OUT))) break;
            gal_rom_observe(ref, rec.nprobe, rec.probe, row, row + 4 * rec.nprobe);
            for (int k = 0; k < 4 * rec.nprobe + 2; k++) worst = fmax(worst, fabs(row[k] - rec.row[i][k]));
        }
        CHECK(!st && worst == 0, "the replay's record differs from the grown model's run by %g", worst);
    }
    /* a second cubic trip: nothing more to add */
    cubic_trip(&a, m, &chk, du, GAL_FAMILY_HORIZONTAL);
    int r1 = m->r;
    st = gal_rom_adapt_grow(&a, &m, &chk, du);
    CHECK(st == GAL_ROM_ELIMIT && m->r == r1 && strstr(gal_error_message(), "third-order"),
          "a second cubic trip: status %d, basis %d: %s", st, m->r, gal_error_message());
    /* nor a residual's trip: no correction or mode past the third-order set */
    st = gal_rom_adapt_residual(&a, m, &chk, du);
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) chk.cubic[f] = 0;
    chk.rel[GAL_FAMILY_TORSIONAL] = chk.max = 0.5;
    if (!st) st = gal_rom_adapt_grow(&a, &m, &chk, du);
    CHECK(st == GAL_ROM_ELIMIT && m->r == r1 && a.nevents == 3 && strstr(gal_error_message(), "does not grow past"),
          "a residual's trip past the third-order set: status %d, basis %d: %s", st, m->r, gal_error_message());
done:
    gal_rom_free(ref);
    gal_rom_free(m);
    gal_rom_adapt_clear(&a);
    free(du);
    gal_sim_setup_clear(&s);
}

int main(void)
{
    RUN(test_third);
    return CHECK_SUMMARY();
}
