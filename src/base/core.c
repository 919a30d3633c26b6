/* core.c: atomic output files, a small JSON writer. */
#define _POSIX_C_SOURCE 200809L
#include "gallop/base/core.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- output files ---- */

int gal_ofile_open(gal_ofile *f, const char *path)
{
    size_t n = strlen(path) + 32;
    f->fp = NULL;
    f->path = strdup(path);
    f->tmp = malloc(n);
    if (!f->path || !f->tmp) {
        free(f->path); free(f->tmp);
        f->path = f->tmp = NULL;
        return gal_error(GAL_ENOMEM, "out of memory opening %s", path);
    }
    snprintf(f->tmp, n, "%s.tmp.%ld", path, (long)getpid());
    f->fp = fopen(f->tmp, "w");
    if (!f->fp) {
        int e = errno;
        free(f->path); free(f->tmp);
        f->path = f->tmp = NULL;
        return gal_error(GAL_EIO, "%s: cannot write: %s", path, strerror(e));
    }
    return GAL_OK;
}

int gal_ofile_open_in(gal_ofile *f, const char *dir, const char *name)
{
    char *path = gal_path_join(dir, name);
    if (!path) return gal_error(GAL_ENOMEM, "out of memory");
    int st = gal_ofile_open(f, path);
    free(path);
    return st;
}

int gal_ofile_close(gal_ofile *f, int ok)
{
    int st = GAL_OK;
    if (!f->fp) return GAL_OK;
    if (ferror(f->fp)) ok = 0, st = gal_error(GAL_EIO, "%s: write error", f->path);
    if (fclose(f->fp) != 0 && ok) ok = 0, st = gal_error(GAL_EIO, "%s: write error on close", f->path);
    f->fp = NULL;
    if (ok) {
        if (rename(f->tmp, f->path) != 0) {
            st = gal_error(GAL_EIO, "%s: cannot rename from %s: %s", f->path, f->tmp, strerror(errno));
            remove(f->tmp);
        }
    } else {
        remove(f->tmp);
    }
    free(f->path); free(f->tmp);
    f->path = f->tmp = NULL;
    return st;
}

int gal_mkdirs(const char *path)
{
    char *p = strdup(path);
    if (!p) return gal_error(GAL_ENOMEM, "out of memory");
    for (char *s = p + 1; ; s++) {
        if (*s == '/' || *s == '\0') {
            char c = *s;
            *s = '\0';
            if (mkdir(p, 0777) != 0 && errno != EEXIST) {
                int e = errno;
                int st = gal_error(GAL_EIO, "%s: cannot create directory: %s", p, strerror(e));
                free(p);
                return st;
            }
            *s = c;
            if (c == '\0') break;
        }
    }
    free(p);
    struct stat sb;
    if (stat(path, &sb) != 0 || !S_ISDIR(sb.st_mode))
        return gal_error(GAL_EIO, "%s: not a directory", path);
    return GAL_OK;
}

char *gal_path_join(const char *dir, const char *name)
{
    size_t n = strlen(dir) + strlen(name) + 2;
    char *s = malloc(n);
    if (s) snprintf(s, n, "%s/%s", dir, name);
    return s;
}

/* ---- JSON ---- */

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
