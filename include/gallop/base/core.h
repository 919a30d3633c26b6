/* core.h: what every module shares: status codes and errors (error.h), output files, a JSON
 * writer, pi. */
#ifndef GALLOP_CORE_H
#define GALLOP_CORE_H

#include <stdio.h>
#include <stddef.h>

#include "gallop/base/error.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GAL_PI 3.14159265358979323846

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

#ifdef __cplusplus
}
#endif

#endif
