/* json.c: a minimal streaming JSON writer (objects, arrays, numbers, strings). */
#include "gallop/output/json.h"

#include <math.h>
#include <stdio.h>

/* Separator before an element: a comma after the first, a newline and indentation. A value that
 * follows its key takes none. */
static void json_sep(gal_json *j)
{
    if (j->after_key) {
        j->after_key = 0;
        return;
    }
    if (j->depth > 0 && j->depth < 32) {
        if (!j->first[j->depth]) fputc(',', j->fp);
        j->first[j->depth] = 0;
        fputc('\n', j->fp);
        for (int i = 0; i < j->depth; i++) fputs("  ", j->fp);
    }
}

static void json_string(FILE *fp, const char *s)
{
    fputc('"', fp);
    for (const unsigned char *c = (const unsigned char *)s; *c; c++) {
        if (*c == '"' || *c == '\\') fprintf(fp, "\\%c", *c);
        else if (*c == '\n') fputs("\\n", fp);
        else if (*c == '\t') fputs("\\t", fp);
        else if (*c < 0x20) fprintf(fp, "\\u%04x", *c);
        else fputc(*c, fp);
    }
    fputc('"', fp);
}

void gal_json_begin(gal_json *j, FILE *fp)
{
    j->fp = fp;
    j->after_key = 0;
    fputc('{', fp);
    j->depth = 1;
    j->first[1] = 1;
}

void gal_json_end(gal_json *j)
{
    fputs("\n}\n", j->fp);
    j->depth = 0;
}

void gal_json_key(gal_json *j, const char *key)
{
    json_sep(j);
    json_string(j->fp, key);
    fputs(": ", j->fp);
    j->after_key = 1;
}

void gal_json_num(gal_json *j, double v)
{
    json_sep(j);
    if (isfinite(v)) fprintf(j->fp, "%.10g", v);
    else fputs("null", j->fp);
}

void gal_json_int(gal_json *j, long v)
{
    json_sep(j);
    fprintf(j->fp, "%ld", v);
}

void gal_json_str(gal_json *j, const char *s)
{
    json_sep(j);
    json_string(j->fp, s ? s : "");
}

void gal_json_bool(gal_json *j, int v)
{
    json_sep(j);
    fputs(v ? "true" : "false", j->fp);
}

static void json_open(gal_json *j, int c)
{
    json_sep(j);
    fputc(c, j->fp);
    if (j->depth < 31) j->depth++;
    j->first[j->depth] = 1;
}

static void json_close(gal_json *j, int c)
{
    int empty = j->first[j->depth];
    j->depth--;
    if (!empty) {
        fputc('\n', j->fp);
        for (int i = 0; i < j->depth; i++) fputs("  ", j->fp);
    }
    fputc(c, j->fp);
}

void gal_json_obj_begin(gal_json *j) { json_open(j, '{'); }
void gal_json_obj_end(gal_json *j) { json_close(j, '}'); }
void gal_json_arr_begin(gal_json *j) { json_open(j, '['); }
void gal_json_arr_end(gal_json *j) { json_close(j, ']'); }

void gal_json_kv_num(gal_json *j, const char *key, double v) { gal_json_key(j, key); gal_json_num(j, v); }
void gal_json_kv_int(gal_json *j, const char *key, long v) { gal_json_key(j, key); gal_json_int(j, v); }
void gal_json_kv_str(gal_json *j, const char *key, const char *s) { gal_json_key(j, key); gal_json_str(j, s); }
