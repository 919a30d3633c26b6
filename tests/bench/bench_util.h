/* bench_util.h: what the benchmarks share: medians, a fork per measured case (so that each case's
 * peak memory, getrusage's ru_maxrss of the child, is its own), and the machine's flop rates: a
 * dense one (BLAS dgemm, and dgemv: the kernel of a Lanczos orthogonalization) and the sparse
 * ones of CHOLMOD on a rod's own matrix (factorization: CHOLMOD's flop count over its time; solve:
 * 4 lnz + n per solve). Times are the process's CPU time (CLOCK_PROCESS_CPUTIME_ID): on one thread
 * what the wall clock shows on an idle machine, and far steadier on a shared one. Include first. */
#ifndef GALLOP_BENCH_UTIL_H
#define GALLOP_BENCH_UTIL_H

#define _DEFAULT_SOURCE /* wait4 */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "gallop.h"

#include "base/chol.h"

void dgemm_(const char *ta, const char *tb, const int *m, const int *n, const int *k, const double *alpha,
            const double *a, const int *lda, const double *b, const int *ldb, const double *beta, double *c,
            const int *ldc);
void dgemv_(const char *t, const int *m, const int *n, const double *alpha, const double *a, const int *lda,
            const double *x, const int *incx, const double *beta, double *y, const int *incy);

static double bench_cpu(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int bench_cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

__attribute__((unused)) static double bench_median(double *a, int n)
{
    qsort(a, (size_t)n, sizeof(double), bench_cmp);
    return a[n / 2];
}

/* Runs fn(arg, out) in a child; out (nout doubles) comes back through a pipe; *peak_mb is the
 * child's peak resident memory. Returns 0 when the child succeeded. */
__attribute__((unused)) static int bench_fork(int (*fn)(void *, double *), void *arg, double *out, int nout, double *peak_mb)
{
    int fd[2];
    if (pipe(fd)) return 1;
    fflush(stdout);
    pid_t pid = fork();
    if (pid < 0) return 1;
    if (pid == 0) {
        close(fd[0]);
        int st = fn(arg, out);
        if (!st && write(fd[1], out, (size_t)nout * sizeof(double)) != (ssize_t)(nout * sizeof(double))) st = 1;
        _exit(st ? 1 : 0);
    }
    close(fd[1]);
    size_t want = (size_t)nout * sizeof(double), got = 0;
    while (got < want) {
        ssize_t r = read(fd[0], (char *)out + got, want - got);
        if (r <= 0) break;
        got += (size_t)r;
    }
    close(fd[0]);
    int status;
    struct rusage ru;
    if (wait4(pid, &status, 0, &ru) != pid) return 1;
    *peak_mb = ru.ru_maxrss / 1024.0;
    return !(WIFEXITED(status) && WEXITSTATUS(status) == 0 && got == want);
}

/* Dense rates, GFlop/s: dgemm of n x n (2 n^3 flops) and dgemv of an n x m basis transposed and
 * not (the two products of a Gram-Schmidt pass, 4 n m flops), medians of repeats. */
__attribute__((unused)) static void bench_dense_rates(double *gemm, double *gemv)
{
    int n = 400, N = 4000, m = 15, one = 1;
    double al = 1, be = 0, t[15];
    double *a = malloc(sizeof(double) * n * n), *b = malloc(sizeof(double) * n * n), *c = malloc(sizeof(double) * n * n);
    double *V = malloc(sizeof(double) * N * m), *x = malloc(sizeof(double) * N), *h = malloc(sizeof(double) * m);
    for (int i = 0; i < n * n; i++) a[i] = 1.0 / (1 + i % 7), b[i] = 1.0 / (1 + i % 5);
    for (int i = 0; i < N * m; i++) V[i] = 1.0 / (1 + i % 11);
    for (int i = 0; i < N; i++) x[i] = 1;
    for (int r = 0; r < 15; r++) {
        double t0 = bench_cpu();
        dgemm_("N", "N", &n, &n, &n, &al, a, &n, b, &n, &be, c, &n);
        t[r] = bench_cpu() - t0;
    }
    *gemm = 2.0 * n * n * n / bench_median(t, 15) * 1e-9;
    for (int r = 0; r < 15; r++) {
        double t0 = bench_cpu();
        for (int k = 0; k < 50; k++) {
            dgemv_("T", &N, &m, &al, V, &N, x, &one, &be, h, &one);
            dgemv_("N", &N, &m, &al, V, &N, h, &one, &be, x, &one);
            x[0] = 1;
        }
        t[r] = (bench_cpu() - t0) / 50;
    }
    *gemv = 4.0 * N * m / bench_median(t, 15) * 1e-9;
    free(a); free(b); free(c); free(V); free(x); free(h);
}

/* CHOLMOD on the rod's tangent at q shifted to positive definite (K + M): factorization rate
 * (CHOLMOD's flop count / median time) and solve rate ((4 lnz + n) / median time), GFlop/s; and
 * the flop counts themselves. */
__attribute__((unused)) static int bench_sparse_rates(const gal_rod *rod, const double *q, double *fact, double *solve, double *fl_fact,
                              double *lnz)
{
    int n = rod->ndof;
    gal_csc *K = gal_csc_clone(rod->K);
    double *b = malloc(sizeof(double) * n), *x = malloc(sizeof(double) * n), t[21];
    if (!K || !b || !x || gal_rod_eval(rod, q, NULL, NULL, K)) return 1;
    for (int k = 0; k < K->nnz; k++) K->val[k] += rod->M->val[k];
    gal_chol *ch = gal_chol_alloc(K);
    if (!ch) return 1;
    for (int r = 0; r < 21; r++) {
        double t0 = bench_cpu();
        if (gal_chol_factor(ch, K, 0, NULL)) return 1;
        t[r] = bench_cpu() - t0;
    }
    *fl_fact = ch->c.fl, *lnz = ch->c.lnz;
    *fact = ch->c.fl / bench_median(t, 21) * 1e-9;
    for (int i = 0; i < n; i++) b[i] = 1;
    for (int r = 0; r < 21; r++) {
        double t0 = bench_cpu();
        for (int k = 0; k < 20; k++) gal_chol_solve(ch, b, x);
        t[r] = (bench_cpu() - t0) / 20;
    }
    *solve = (4 * ch->c.lnz + n) / bench_median(t, 21) * 1e-9;
    gal_chol_free(ch);
    gal_csc_free(K);
    free(b); free(x);
    return 0;
}

#endif
