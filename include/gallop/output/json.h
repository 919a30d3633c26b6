/* json.h: a minimal streaming JSON writer (objects, arrays, numbers, strings). */
#ifndef GALLOP_OUTPUT_JSON_H
#define GALLOP_OUTPUT_JSON_H

#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

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
