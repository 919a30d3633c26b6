/* bench_modes.c: statics + the modes `gallop modes` asks of data/scenes/drake_300m.ini (3 vertical,
 * 2 horizontal, 2 torsional) on a 300 m ACSR Drake span at 100, 1000 and 10000 elements: medians of
  * repeats (CPU time), each size in its own process (its peak memory beside its times), and the modes stage
 * against its arithmetic floor (issue 16): one factorization of K - sigma M (CHOLMOD's flop count),
 * the m = 2a + 1 solves of a Lanczos basis twice the a asked modes (4 lnz + 2 n each: the triangular
 * solves and the mass) and its orthogonalization (one Gram-Schmidt pass per step: 4 n j at step j,
 * 2 n m (m + 1) in all) with the Ritz vectors (2 n m a), at the measured sparse rates (factorization
 * and solve, on this matrix) and the dense rate (dgemm; dgemv, the Lanczos kernel, beside it). */
#include "bench_util.h"

#include "gallop/modes/modes.h"
#include "gallop/statics/statics.h"

typedef struct {
    int nel, reps;
} mcase;

enum { R_TOTAL, R_STATICS, R_MODES, R_FLOP_FACT, R_FLOP_SOLVE, R_FLOP_DENSE, R_FLOOR, R_FLOOR_GEMV, R_FACT_RATE,
       R_SOLVE_RATE, R_GEMM, R_GEMV, R_OPS, R_FACTS, R_N, R_COUNT };

static gal_rod_params drake(int nel)
{
    gal_rod_params p = {.length = 300, .elements = nel, .EA = 2.9e7, .EI = 28, .GJ = 160, .mass = 1.628,
                        .polar_inertia = 1.6e-4, .gravity = 9.80665, .torsion = 1, .twist_clamped = 1};
    return p;
}

static int run_case(void *arg, double *out)
{
    const mcase *c = arg;
    int want[GAL_FAMILY_COUNT] = {3, 2, 2, 0}, a = 7;
    double ts[32], tm[32], tt[32];
    gal_rod_params p = drake(c->nel);
    gal_equilibrium eq;
    gal_modes md;
    for (int r = 0; r < c->reps; r++) {
        double t0 = bench_cpu(), t1 = t0;
        int st = gal_statics_solve(&p, GAL_BY_TENSION, 28000, NULL, &eq);
        t1 = bench_cpu();
        if (st || gal_modes_find_eq(&eq, want, 400, &md)) {
            fprintf(stderr, "bench_modes: %s\n", gal_error_message());
            return 1;
        }
        tt[r] = bench_cpu() - t0, ts[r] = t1 - t0, tm[r] = tt[r] - ts[r];
        out[R_OPS] = md.op_applications, out[R_FACTS] = md.factorizations;
        gal_modes_clear(&md);
        if (r < c->reps - 1) gal_equilibrium_clear(&eq);
    }
    out[R_TOTAL] = bench_median(tt, c->reps), out[R_STATICS] = bench_median(ts, c->reps);
    out[R_MODES] = bench_median(tm, c->reps);
    double fl, lnz, n = eq.rod->ndof, m = 2 * a + 1;
    if (bench_sparse_rates(eq.rod, eq.q, &out[R_FACT_RATE], &out[R_SOLVE_RATE], &fl, &lnz)) return 1;
    bench_dense_rates(&out[R_GEMM], &out[R_GEMV]);
    out[R_FLOP_FACT] = fl, out[R_FLOP_SOLVE] = m * (4 * lnz + 2 * n);
    out[R_FLOP_DENSE] = 2 * n * m * (m + 1) + 2 * n * m * a;
    double sparse = 1e-9 * (out[R_FLOP_FACT] / out[R_FACT_RATE] + out[R_FLOP_SOLVE] / out[R_SOLVE_RATE]);
    out[R_FLOOR] = sparse + 1e-9 * out[R_FLOP_DENSE] / out[R_GEMM];
    out[R_FLOOR_GEMV] = sparse + 1e-9 * out[R_FLOP_DENSE] / out[R_GEMV];
    out[R_N] = n;
    gal_equilibrium_clear(&eq);
    return 0;
}

int main(void)
{
    mcase cs[3] = {{100, 15}, {1000, 9}, {10000, 5}};
    for (int k = 0; k < 3; k++) {
        double o[R_COUNT], mb;
        if (bench_fork(run_case, &cs[k], o, R_COUNT, &mb)) return 1;
        int nel = cs[k].nel;
        printf("BENCH|statics + modes (3 vertical, 2 horizontal, 2 torsional), %d elements (300 m Drake)|%.2f|ms|median "
               "of %d (statics %.2f, modes %.2f); peak memory %.1f MB\n",
               nel, 1e3 * o[R_TOTAL], cs[k].reps, 1e3 * o[R_STATICS], 1e3 * o[R_MODES], mb);
        printf("BENCH|modes stage / its floor, %d elements|%.2f|x|floor %.3f ms = factorization %.3f MFlop + %d solves "
               "%.3f MFlop + orthogonalization and Ritz vectors %.3f MFlop (dense at dgemm's rate; %.2fx at "
               "dgemv's); the stage did %.0f factorizations and %.0f solves\n",
               nel, o[R_MODES] / o[R_FLOOR], 1e3 * o[R_FLOOR], 1e-6 * o[R_FLOP_FACT], 15, 1e-6 * o[R_FLOP_SOLVE],
               1e-6 * o[R_FLOP_DENSE], o[R_MODES] / o[R_FLOOR_GEMV], o[R_FACTS], o[R_OPS]);
        if (k == 1)
            printf("BENCH|flop rates (one core)|%.2f / %.2f / %.2f / %.2f|GFlop/s|dense dgemm 400^3 / dgemv 4000 x 15 / "
                   "CHOLMOD factorization / solve of the %d-element rod (%.0f dofs)\n",
                   o[R_GEMM], o[R_GEMV], o[R_FACT_RATE], o[R_SOLVE_RATE], nel, o[R_N]);
    }
    return 0;
}
