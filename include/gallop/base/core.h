/* core.h: status codes, error reporting, output files and small utilities shared by every module. */
#ifndef GALLOP_CORE_H
#define GALLOP_CORE_H

#include <stdio.h>
#include <stddef.h>

#define GAL_PI 3.14159265358979323846

/* One status enum for the whole library: 0 success, negative failure. */
typedef enum {
    GAL_OK = 0,
    GAL_EINPUT = -1,  /* bad input: scene, table, option (exit 2) */
    GAL_EFAIL = -2,   /* the computation failed: no convergence, lost stability, NaN (exit 1) */
    GAL_ENOMEM = -3,  /* out of memory (exit 1) */
    GAL_EIO = -4      /* a file could not be read or written (exit 2 when reading input) */
} gal_status;

/* The last error message (library code sets it, main prints it). */
const char *gal_error_message(void);
/* Set the message (printf format) and return `status` so that callers can `return gal_error(...)`. */
int gal_error(int status, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
void gal_error_clear(void);
/* Process exit status for a library status: 0, 1 (computation), 2 (input). */
int gal_exit_code(int status);

/* Wall-clock seconds from an arbitrary origin (monotonic). */
double gal_wall_time(void);

/* ---- output files that appear whole or not at all ----
 * gal_ofile_open writes to "<path>.tmp.<pid>"; gal_ofile_close renames it to <path> on success
 * (ok != 0) or removes it (ok == 0). A failed write or close returns GAL_EIO. */
typedef struct gal_ofile {
    FILE *fp;
    char *path;
    char *tmp;
} gal_ofile;
int gal_ofile_open(gal_ofile *f, const char *path);
int gal_ofile_close(gal_ofile *f, int ok);
/* gal_ofile_open on dir/name. */
int gal_ofile_open_in(gal_ofile *f, const char *dir, const char *name);

/* mkdir -p; GAL_EIO with a message when it fails. */
int gal_mkdirs(const char *path);
/* Join dir and name into a freshly malloc'ed string. */
char *gal_path_join(const char *dir, const char *name);

/* ---- a minimal streaming JSON writer (objects, arrays, numbers, strings) ---- */
typedef struct gal_json {
    FILE *fp;
    int depth;
    int first[32];   /* first element at this depth still to come */
    int after_key;   /* a key was written, its value comes next */
} gal_json;
void gal_json_begin(gal_json *j, FILE *fp);         /* opens the top-level object */
void gal_json_end(gal_json *j);                      /* closes it, newline */
void gal_json_key(gal_json *j, const char *key);     /* inside an object: "key": */
void gal_json_num(gal_json *j, double v);            /* NaN/Inf written as null */
void gal_json_int(gal_json *j, long v);
void gal_json_str(gal_json *j, const char *s);
void gal_json_bool(gal_json *j, int v);
void gal_json_obj_begin(gal_json *j);
void gal_json_obj_end(gal_json *j);
void gal_json_arr_begin(gal_json *j);
void gal_json_arr_end(gal_json *j);
/* shorthands: key plus value */
void gal_json_kv_num(gal_json *j, const char *key, double v);
void gal_json_kv_int(gal_json *j, const char *key, long v);
void gal_json_kv_str(gal_json *j, const char *key, const char *s);

#endif
