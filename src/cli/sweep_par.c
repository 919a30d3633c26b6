/* cli/sweep_par.c: the units of a sweep handed out to one process or to the ranks of an MPI run
 * (sweep_par.h). With MPI (GAL_MPI) and more than one rank: rank 0's main thread is the master
 * (a request of a rank answered with the next unit, -1 when none is left; each finished case
 * reported to it), polling without spinning so that it leaves the core to the computations, and a
 * second thread of rank 0 runs units like every other rank. Alone: a loop. */
#define _POSIX_C_SOURCE 200809L
#include "sweep_par.h"

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "gallop/base/error.h"

#ifdef GAL_MPI
#include <mpi.h>
#define TAG_REQUEST 1 /* a rank asks for a unit */
#define TAG_UNIT 2    /* the answer: a long, -1 for none */
#define TAG_DONE 3    /* a rank finished a case: two doubles, how (gal_par_case_done) and its set-up time */
#endif

#define PROGRESS_EVERY_S 2.0

struct gal_par {
    int rank, size, mpi;
    long nunits, ncases, next;     /* units handed out so far */
    long done, computed;           /* cases finished, of which computed now */
    long printed;                  /* done at the last progress line */
    long setups, reused, damping;  /* computed cases with their own set-up, with a reused one, that
                                    * built their damping */
    long rom_setups, rom_reused;   /* reduced cases that computed their own set-up, reused one */
    double setup_time_s;
    int local_done, threaded;
    double t0, last_print;
    pthread_mutex_t lock;
    gal_par_unit_fn fn;
    void *ctx;
};

gal_par *gal_par_init(void)
{
    gal_par *p = calloc(1, sizeof *p);
    if (!p) {
        fprintf(stderr, "gallop sweep: out of memory\n");
        return NULL;
    }
    p->size = 1;
    pthread_mutex_init(&p->lock, NULL);
#ifdef GAL_MPI
    int provided = 0;
    if (MPI_Init_thread(NULL, NULL, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
        fprintf(stderr, "gallop sweep: MPI_Init_thread failed\n");
        pthread_mutex_destroy(&p->lock);
        free(p);
        return NULL;
    }
    p->mpi = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &p->rank);
    MPI_Comm_size(MPI_COMM_WORLD, &p->size);
    if (p->size > 1 && provided < MPI_THREAD_FUNNELED && p->rank == 0)
        fprintf(stderr, "gallop sweep: warning: MPI gives no thread support: rank 0 hands out the cases and runs "
                "none\n");
    p->threaded = provided >= MPI_THREAD_FUNNELED;
#endif
    return p;
}

int gal_par_rank(const gal_par *p) { return p->rank; }
int gal_par_size(const gal_par *p) { return p->size; }

gal_par *gal_par_free(gal_par *p)
{
    if (!p) return NULL;
#ifdef GAL_MPI
    if (p->mpi) MPI_Finalize();
#endif
    pthread_mutex_destroy(&p->lock);
    free(p);
    return NULL;
}

/* ---- the shared counters ---- */

static long take_unit(gal_par *p)
{
    pthread_mutex_lock(&p->lock);
    long u = p->next < p->nunits ? p->next++ : -1;
    pthread_mutex_unlock(&p->lock);
    return u;
}

static void format_time(double s, char *buf, size_t n)
{
    if (s < 90) snprintf(buf, n, "%.0f s", s);
    else if (s < 5400) snprintf(buf, n, "%.0f min", s / 60);
    else snprintf(buf, n, "%.1f h", s / 3600);
}

/* rank 0: done, remaining and the time left at the rate of the cases computed so far */
static void progress(gal_par *p, int final)
{
    double now = gal_wall_time();
    double since = now - p->last_print;
    if (final ? p->printed == p->done : since < PROGRESS_EVERY_S || (p->printed == p->done && since < 30)) return;
    p->last_print = now, p->printed = p->done;
    long done = p->done, computed = p->computed, left = p->ncases - done;
    char eta[32] = "unknown";
    if (computed > 0) format_time((now - p->t0) / (double)computed * (double)left, eta, sizeof eta);
    fprintf(stderr, "gallop sweep: %ld of %ld cases done (%ld computed, %ld resumed), %ld remaining, about %s left\n",
            done, p->ncases, computed, done - computed, left, left ? eta : "0 s");
}

/* a finished case counted (the lock held) */
static void count(gal_par *p, int how, double setup_time_s)
{
    int rom = how >> GAL_PAR_ROM_SHIFT;
    how &= (1 << GAL_PAR_ROM_SHIFT) - 1;
    p->rom_setups += rom == 1, p->rom_reused += rom == 2;
    p->done++, p->computed += how != 0;
    p->setups += how == GAL_PAR_SETUP_COMPUTED, p->reused += how >= GAL_PAR_SETUP_REUSED;
    p->damping += how == GAL_PAR_SETUP_COMPUTED || how == GAL_PAR_SETUP_REUSED_MODES;
    p->setup_time_s += setup_time_s;
}

void gal_par_case_done(gal_par *p, int how, double setup_time_s)
{
#ifdef GAL_MPI
    if (p->rank != 0) {
        double msg[2] = {how, setup_time_s};
        MPI_Send(msg, 2, MPI_DOUBLE, 0, TAG_DONE, MPI_COMM_WORLD);
        return;
    }
#endif
    pthread_mutex_lock(&p->lock);
    count(p, how, setup_time_s);
    if (!p->threaded || p->size == 1) progress(p, 0);
    pthread_mutex_unlock(&p->lock);
}

void gal_par_setups(const gal_par *p, long *computed, long *reused, long *damping, double *time_s)
{
    *computed = p->setups, *reused = p->reused, *damping = p->damping, *time_s = p->setup_time_s;
}

void gal_par_rom_setups(const gal_par *p, long *computed, long *reused)
{
    *computed = p->rom_setups, *reused = p->rom_reused;
}

/* units from the shared counter until none is left */
static void *local_worker(void *arg)
{
    gal_par *p = arg;
    for (long u; (u = take_unit(p)) >= 0;) p->fn(p->ctx, u);
    pthread_mutex_lock(&p->lock);
    p->local_done = 1;
    pthread_mutex_unlock(&p->lock);
    return NULL;
}

#ifdef GAL_MPI
static void nap(void)
{
    struct timespec ts = {0, 1000000}; /* 1 ms */
    nanosleep(&ts, NULL);
}

/* rank 0's main thread: answer requests and reports until every other rank has been told that no
 * unit is left and the local worker is finished */
static void master(gal_par *p)
{
    pthread_t th;
    int local = p->threaded && pthread_create(&th, NULL, local_worker, p) == 0;
    int stopped = 0;
    for (;;) {
        pthread_mutex_lock(&p->lock);
        int busy = local && !p->local_done;
        progress(p, 0);
        pthread_mutex_unlock(&p->lock);
        if (stopped == p->size - 1 && !busy) break;
        int flag = 0;
        MPI_Status s;
        MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &s);
        if (!flag) {
            nap();
            continue;
        }
        if (s.MPI_TAG == TAG_DONE) {
            double msg[2];
            MPI_Recv(msg, 2, MPI_DOUBLE, s.MPI_SOURCE, TAG_DONE, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            pthread_mutex_lock(&p->lock);
            count(p, (int)msg[0], msg[1]);
            pthread_mutex_unlock(&p->lock);
        } else {
            MPI_Recv(NULL, 0, MPI_BYTE, s.MPI_SOURCE, TAG_REQUEST, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            long u = take_unit(p);
            MPI_Send(&u, 1, MPI_LONG, s.MPI_SOURCE, TAG_UNIT, MPI_COMM_WORLD);
            stopped += u < 0;
        }
    }
    if (local) pthread_join(th, NULL);
}

/* a rank other than 0: ask, run, until told that none is left (waiting without spinning) */
static void worker(gal_par *p)
{
    for (;;) {
        long u = -1;
        MPI_Request rq;
        MPI_Send(NULL, 0, MPI_BYTE, 0, TAG_REQUEST, MPI_COMM_WORLD);
        MPI_Irecv(&u, 1, MPI_LONG, 0, TAG_UNIT, MPI_COMM_WORLD, &rq);
        for (int flag = 0; MPI_Test(&rq, &flag, MPI_STATUS_IGNORE), !flag;) nap();
        if (u < 0) break;
        p->fn(p->ctx, u);
    }
}
#endif

void gal_par_run(gal_par *p, long nunits, long ncases, gal_par_unit_fn fn, void *ctx, long *computed)
{
    p->nunits = nunits, p->ncases = ncases, p->next = 0;
    p->done = p->computed = p->setups = p->reused = p->damping = p->rom_setups = p->rom_reused = 0;
    p->setup_time_s = 0;
    p->printed = -1;
    p->local_done = 0;
    p->fn = fn, p->ctx = ctx;
    p->t0 = p->last_print = gal_wall_time();
#ifdef GAL_MPI
    if (p->size > 1) {
        if (p->rank == 0) master(p);
        else worker(p);
    } else
#endif
        local_worker(p);
    if (p->rank == 0) progress(p, 1);
    if (computed) *computed = p->computed;
}
