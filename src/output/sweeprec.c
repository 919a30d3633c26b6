/* sweeprec.c: the records of a sweep's finished cases in DIR/cases/ (sweepreport.h): the
 * fingerprint that names them, each case committed atomically on its own (temporary file, fsync,
 * rename; the state before the record), and read back by a rerun. */
#define _POSIX_C_SOURCE 200809L
#include "gallop/output/sweepreport.h"
#include "gallop/base/core.h"
#include "gallop/output/ofile.h"
#include "gallop/output/record.h"

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define RECORD_MAGIC "gallop-sweep-case 1"

int gal_sweep_fingerprint(const gal_scene *sc, gal_model_kind kind, gal_sweep_branch branch, uint64_t prev,
                          uint64_t *fp)
{
    uint64_t h = 0, t = 0;
    long bytes = 0;
    int st = gal_record_scene_hash(sc, &h);
    if (st) return st;
    if (sc->ice.aero_table[0] && (st = gal_record_file_hash(sc->ice.aero_table, &t, &bytes))) return st;
    char tail[128];
    int n = snprintf(tail, sizeof tail, "%s|%016" PRIx64 "|%s|%s|%016" PRIx64, RECORD_MAGIC, t,
                     kind == GAL_MODEL_FULL ? "full" : "reduced", gal_sweep_branch_names[branch], prev);
    *fp = gal_record_fnv1a64(tail, (size_t)n, h);
    return GAL_OK;
}

static char *case_path(const char *dir, uint64_t fp, const char *ext)
{
    size_t n = strlen(dir) + 48;
    char *p = malloc(n);
    if (p) snprintf(p, n, "%s/cases/%016" PRIx64 ".%s", dir, fp, ext);
    return p;
}

int gal_sweep_cases_dir(const char *dir)
{
    char *p = gal_path_join(dir, "cases");
    if (!p) return gal_error(GAL_ENOMEM, "out of memory");
    int st = gal_mkdirs(p);
    free(p);
    return st;
}

/* flushed to the disk before the rename: a record never names a state that is not all there */
static int commit(gal_ofile *f)
{
    int ok = fflush(f->fp) == 0 && fsync(fileno(f->fp)) == 0;
    return gal_ofile_close(f, ok);
}

static int write_state(const char *dir, uint64_t fp, const double *q, const double *v, int nq)
{
    char *path = case_path(dir, fp, "state");
    if (!path) return gal_error(GAL_ENOMEM, "out of memory");
    gal_ofile f;
    int st = gal_ofile_open(&f, path);
    free(path);
    if (st) return st;
    fwrite(q, sizeof(double), (size_t)nq, f.fp);
    fwrite(v, sizeof(double), (size_t)nq, f.fp);
    return commit(&f);
}

static void put_num(FILE *fp, const char *key, double x) { fprintf(fp, "%s %.17g\n", key, x); }

int gal_sweep_record_write(const char *dir, uint64_t fp, const gal_sweep_result *r, const double *q,
                           const double *v, int nq)
{
    int st = q ? write_state(dir, fp, q, v, nq) : GAL_OK;
    char *path = case_path(dir, fp, "case");
    if (!path) return gal_error(GAL_ENOMEM, "out of memory");
    gal_ofile f;
    if (!st) st = gal_ofile_open(&f, path);
    free(path);
    if (st) return st;
    FILE *o = f.fp;
    fprintf(o, "%s\nfingerprint %016" PRIx64 "\nstatus %d\n", RECORD_MAGIC, fp, r->status);
    put_num(o, "vertical_pp_m", r->vertical_pp_m);
    put_num(o, "horizontal_pp_m", r->horizontal_pp_m);
    put_num(o, "twist_pp_deg", r->twist_pp_deg);
    put_num(o, "frequency_hz", r->frequency_hz);
    put_num(o, "tension_max_n", r->tension_max_n);
    put_num(o, "onset_speed_m_s", r->onset_speed_m_s);
    fprintf(o, "has_onset %d\nvalid %d\n", r->has_onset, r->valid);
    put_num(o, "residual_max", r->residual_max);
    put_num(o, "wall_time_s", r->wall_time_s);
    for (int k = 0; k < r->nsub; k++) /* an explicit bundle's sub-conductors (optional lines) */
        fprintf(o, "sub%d %.17g %.17g %.17g %.17g\n", k + 1, r->sub_vertical_pp_m[k], r->sub_horizontal_pp_m[k],
                r->sub_twist_pp_deg[k], r->sub_tension_max_n[k]);
    fprintf(o, "nq %d\n", q ? nq : 0);
    /* the message last: the rest of its line, whatever it holds */
    char msg[sizeof r->message];
    snprintf(msg, sizeof msg, "%s", r->message);
    for (char *c = msg; *c; c++)
        if (*c == '\n') *c = ' ';
    fprintf(o, "message %s\n", msg);
    return commit(&f);
}

/* "key value" lines into r; 0 when one is missing or bad */
static int parse_record(FILE *fp, uint64_t fp_want, gal_sweep_result *r, int *nq)
{
    static const char *const nums[] = {"vertical_pp_m", "horizontal_pp_m", "twist_pp_deg", "frequency_hz",
                                       "tension_max_n", "onset_speed_m_s", "residual_max", "wall_time_s"};
    double *dst[] = {&r->vertical_pp_m, &r->horizontal_pp_m, &r->twist_pp_deg, &r->frequency_hz,
                     &r->tension_max_n, &r->onset_speed_m_s, &r->residual_max, &r->wall_time_s};
    char line[1024];
    unsigned seen = 0;
    uint64_t got = 0;
    if (!fgets(line, sizeof line, fp) || strncmp(line, RECORD_MAGIC "\n", sizeof RECORD_MAGIC)) return 0;
    while (fgets(line, sizeof line, fp)) {
        char *sp = strchr(line, ' ');
        if (!sp) return 0;
        *sp++ = '\0';
        sp[strcspn(sp, "\n")] = '\0';
        for (int k = 0; k < 8; k++)
            if (!strcmp(line, nums[k])) *dst[k] = strtod(sp, NULL), seen |= 1u << k;
        if (!strcmp(line, "fingerprint")) got = strtoull(sp, NULL, 16), seen |= 1u << 8;
        if (!strcmp(line, "status")) r->status = atoi(sp), seen |= 1u << 9;
        if (!strcmp(line, "has_onset")) r->has_onset = atoi(sp), seen |= 1u << 10;
        if (!strcmp(line, "valid")) r->valid = atoi(sp), seen |= 1u << 11;
        if (!strcmp(line, "nq")) *nq = atoi(sp), seen |= 1u << 12;
        int k = !strncmp(line, "sub", 3) ? atoi(line + 3) : 0;
        if (k >= 1 && k <= GAL_SWEEP_MAX_SUB && k == r->nsub + 1 &&
            sscanf(sp, "%lf %lf %lf %lf", &r->sub_vertical_pp_m[k - 1], &r->sub_horizontal_pp_m[k - 1],
                   &r->sub_twist_pp_deg[k - 1], &r->sub_tension_max_n[k - 1]) == 4)
            r->nsub = k;
        if (!strcmp(line, "message")) snprintf(r->message, sizeof r->message, "%s", sp), seen |= 1u << 13;
    }
    return seen == (1u << 14) - 1 && got == fp_want && *nq >= 0;
}

static int read_state(const char *dir, uint64_t fp, int nq, double **q, double **v)
{
    char *path = case_path(dir, fp, "state");
    FILE *f = path ? fopen(path, "rb") : NULL;
    free(path);
    *q = malloc((size_t)nq * sizeof(double));
    *v = malloc((size_t)nq * sizeof(double));
    int ok = f && *q && *v && fread(*q, sizeof(double), (size_t)nq, f) == (size_t)nq &&
             fread(*v, sizeof(double), (size_t)nq, f) == (size_t)nq && fgetc(f) == EOF;
    if (f) fclose(f);
    if (!ok) {
        free(*q), free(*v);
        *q = *v = NULL;
    }
    return ok;
}

int gal_sweep_record_read(const char *dir, uint64_t fp, gal_sweep_result *r, double **q, double **v, int *nq)
{
    char *path = case_path(dir, fp, "case");
    FILE *f = path ? fopen(path, "r") : NULL;
    free(path);
    if (q) *q = *v = NULL;
    if (!f) return 0;
    memset(r, 0, sizeof *r);
    int n = 0, ok = parse_record(f, fp, r, &n);
    fclose(f);
    if (!ok) return 0;
    if (nq) *nq = n;
    /* a case that continues needs the state its successor starts from */
    if (q && r->status == GAL_OK && !(n > 0 && read_state(dir, fp, n, q, v))) return 0;
    return 1;
}
