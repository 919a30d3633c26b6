/* outset.c: one output set per run (outset.h): the staging area, the files written there,
 * summary.json and its run record; the commit itself is in outset_commit.c. */
#define _POSIX_C_SOURCE 200809L
#include "output/outset_int.h"
#include "gallop/base/core.h"
#include "gallop/output/ofile.h"
#include "gallop/output/record.h"

#include <errno.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

static atomic_uint stage_count; /* staging areas made by this process */

const char *gal_outset_dir(const gal_outset *o) { return o->dir; }

/* Lock DIR, clean the leftovers of dead runs, check that DIR/summary.json is gallop's. */
static int prepare_dir(const char *dir)
{
    int fd, st = gal_outset_lock(dir, &fd);
    if (st) return st;
    st = gal_outset_recover(dir);
    char *path = gal_path_join(dir, "summary.json");
    outset_owned old;
    if (!st && !path) st = gal_error(GAL_ENOMEM, "out of memory");
    if (!st) st = gal_outset_read_owned(path, &old);
    if (!st && old.kind == OWNED_FOREIGN)
        st = gal_error(GAL_EIO, "%s exists and was not written by gallop: gallop replaces only its own files; "
                       "move it away or choose another directory with -o", path);
    free(path);
    gal_outset_unlock(fd);
    return st;
}

int gal_outset_check(const char *dir)
{
    if (!dir || !*dir) return gal_error(GAL_EINPUT, "output directory: empty name; allowed: a path");
    char *p = strdup(dir);
    if (!p) return gal_error(GAL_ENOMEM, "out of memory");
    int st = GAL_OK, missing = 0;
    struct stat sb;
    /* the path itself, else its nearest existing ancestor: a writable directory */
    for (;;) {
        if (stat(p, &sb) == 0) {
            if (!S_ISDIR(sb.st_mode))
                st = gal_error(GAL_EIO, "output directory %s: %s exists and is not a directory", dir, p);
            else if (access(p, W_OK | X_OK) != 0)
                st = gal_error(GAL_EIO, "output directory %s: %s is not writable: %s", dir, p, strerror(errno));
            break;
        }
        if (errno != ENOENT) {
            st = gal_error(GAL_EIO, "output directory %s: %s: %s", dir, p, strerror(errno));
            break;
        }
        missing = 1;
        char *slash = strrchr(p, '/');
        while (slash && slash > p && slash[1] == '\0') *slash = '\0', slash = strrchr(p, '/'); /* trailing '/' */
        if (!slash) { strcpy(p, "."); continue; }
        if (slash == p) { p[1] = '\0'; continue; }
        *slash = '\0';
    }
    free(p);
    if (st || missing) return st;
    /* an existing directory: its summary.json, if any, must be gallop's */
    char *path = gal_path_join(dir, "summary.json");
    outset_owned old;
    if (!path) return gal_error(GAL_ENOMEM, "out of memory");
    st = gal_outset_read_owned(path, &old);
    if (!st && old.kind == OWNED_FOREIGN)
        st = gal_error(GAL_EIO, "%s exists and was not written by gallop: gallop replaces only its own files; "
                       "move it away or choose another directory with -o", path);
    free(path);
    return st;
}

/* The highest component of dir that does not exist yet (malloc'ed; NULL when dir exists): the
 * directory gal_mkdirs makes first, removed again if the set is never committed. */
static char *first_missing(const char *dir)
{
    struct stat sb;
    if (stat(dir, &sb) == 0) return NULL;
    char *p = strdup(dir);
    if (!p) return NULL;
    for (size_t i = 1; p[i]; i++) {
        if (p[i] != '/') continue;
        p[i] = '\0';
        if (stat(p, &sb) != 0) return p;
        p[i] = '/';
    }
    return p;
}

/* Remove the empty directories between dir and made (both included; rmdir fails on a non-empty
 * one, which stops the walk). */
static void remove_made(const char *dir, const char *made)
{
    char *p = made ? strdup(dir) : NULL;
    size_t lm = made ? strlen(made) : 0;
    while (p && strlen(p) >= lm && rmdir(p) == 0) {
        char *slash = strrchr(p, '/');
        if (!slash || strlen(p) == lm) break;
        *slash = '\0';
    }
    free(p);
}

int gal_outset_begin(gal_outset **set, const char *dir, const char *command)
{
    *set = NULL;
    int st = gal_outset_check(dir);
    if (st) return st;
    char *made = first_missing(dir);
    st = gal_mkdirs(dir);
    if (!st) st = prepare_dir(dir);
    if (st) {
        remove_made(dir, made);
        free(made);
        return st;
    }
    gal_outset *o = calloc(1, sizeof *o);
    char name[64];
    snprintf(name, sizeof name, OUTSET_STAGE_PREFIX "%ld.%u", (long)getpid(), atomic_fetch_add(&stage_count, 1));
    if (o) o->dir = strdup(dir), o->stage = gal_path_join(dir, name);
    if (!o || !o->dir || !o->stage) {
        if (o) free(o->dir), free(o->stage);
        free(o);
        remove_made(dir, made);
        free(made);
        return gal_error(GAL_ENOMEM, "out of memory");
    }
    o->made = made;
    snprintf(o->command, sizeof o->command, "%s", command);
    if (mkdir(o->stage, 0700) != 0) {
        st = gal_error(GAL_EIO, "%s: cannot create the staging directory: %s", o->stage, strerror(errno));
        remove_made(dir, made);
        free(o->dir), free(o->stage), free(o->made), free(o);
        return st;
    }
    *set = o;
    return GAL_OK;
}

int gal_outset_scene(gal_outset *o, const gal_scene *sc)
{
    snprintf(o->input_key, sizeof o->input_key, "scene_hash");
    return gal_record_scene_hash(sc, &o->input_hash);
}

int gal_outset_input(gal_outset *o, const char *key, const char *path)
{
    snprintf(o->input_key, sizeof o->input_key, "%s", key);
    return gal_record_file_hash(path, &o->input_hash, NULL);
}

static int plain_name(const char *s)
{
    if (!s[0] || s[0] == '.' || strlen(s) >= OUTSET_NAME_MAX) return 0;
    for (; *s; s++)
        if (!((*s >= 'a' && *s <= 'z') || (*s >= 'A' && *s <= 'Z') || (*s >= '0' && *s <= '9') || *s == '.' ||
              *s == '_' || *s == '-'))
            return 0;
    return 1;
}

FILE *gal_outset_open(gal_outset *o, const char *name)
{
    int dup = 0;
    for (int i = 0; i < o->nfiles; i++) dup |= !strcmp(o->file[i].name, name);
    if (!plain_name(name) || !strcmp(name, "summary.json") || dup || o->nfiles == GAL_OUTSET_MAX_FILES) {
        gal_error(GAL_EINPUT, "output set %s: file name '%s': a plain name, once, not summary.json, at most %d",
                  o->dir, name, GAL_OUTSET_MAX_FILES);
        return NULL;
    }
    char *path = gal_path_join(o->stage, name);
    FILE *fp = path ? fopen(path, "w") : NULL;
    if (!fp) gal_error(GAL_EIO, "%s/%s: cannot write: %s", o->dir, name, path ? strerror(errno) : "out of memory");
    free(path);
    if (!fp) return NULL;
    outset_file *f = o->file + o->nfiles++;
    snprintf(f->name, sizeof f->name, "%s", name);
    f->fp = fp;
    return fp;
}

/* flush, fsync, close: GAL_EIO on any error (a full disk shows here) */
static int close_synced(FILE *fp, const char *dir, const char *name)
{
    int bad = fflush(fp) != 0 || ferror(fp);
    int e = errno;
    if (!bad && fsync(fileno(fp)) != 0) bad = 1, e = errno;
    if (fclose(fp) != 0 && !bad) bad = 1, e = errno;
    return bad ? gal_error(GAL_EIO, "%s/%s: write error: %s", dir, name, strerror(e)) : GAL_OK;
}

int gal_outset_close(gal_outset *o, FILE *fp)
{
    outset_file *f = NULL;
    for (int i = 0; i < o->nfiles; i++)
        if (o->file[i].fp == fp && fp) f = o->file + i;
    if (!f) return gal_error(GAL_EINPUT, "output set %s: closing a file it did not open", o->dir);
    f->fp = NULL;
    int st = close_synced(fp, o->dir, f->name);
    char *path = gal_path_join(o->stage, f->name);
    if (!st) st = path ? gal_record_file_hash(path, &f->hash, &f->bytes) : gal_error(GAL_ENOMEM, "out of memory");
    free(path);
    return st;
}

gal_json *gal_outset_summary(gal_outset *o)
{
    char *path = gal_path_join(o->stage, "summary.json");
    o->summary = path && !o->summary ? fopen(path, "w") : NULL;
    if (!o->summary) gal_error(GAL_EIO, "%s/summary.json: cannot write: %s", o->dir, path ? strerror(errno) : "out of memory");
    free(path);
    if (!o->summary) return NULL;
    gal_json_begin(&o->json, o->summary);
    return &o->json;
}

/* the run record: the last keys of summary.json */
static void write_record(gal_outset *o)
{
    gal_json *j = &o->json;
    char buf[64], created[32], id[64];
    time_t now = time(NULL);
    struct tm tm;
    gmtime_r(&now, &tm);
    strftime(created, sizeof created, "%Y-%m-%dT%H:%M:%SZ", &tm);
    snprintf(id, sizeof id, "%s-%s", created, strrchr(o->stage, '/') + 1 + strlen(OUTSET_STAGE_PREFIX));
    gal_json_kv_int(j, "schema_version", GAL_SCHEMA_VERSION);
    gal_json_kv_str(j, "gallop_version", gal_record_version());
    gal_json_kv_str(j, "git_commit", gal_record_commit());
    if (o->input_key[0]) {
        gal_record_hash_format(o->input_hash, buf, sizeof buf);
        gal_json_kv_str(j, o->input_key, buf);
    }
    gal_json_key(j, "commit_record");
    gal_json_obj_begin(j);
    gal_json_kv_str(j, "run_id", id);
    gal_json_kv_str(j, "command", o->command);
    gal_json_kv_str(j, "created", created);
    gal_json_kv_int(j, "pid", (long)getpid());
    gal_json_key(j, "files");
    gal_json_arr_begin(j);
    for (int i = 0; i < o->nfiles; i++) {
        gal_json_obj_begin(j);
        gal_json_kv_str(j, "name", o->file[i].name);
        gal_json_kv_int(j, "bytes", o->file[i].bytes);
        gal_record_hash_format(o->file[i].hash, buf, sizeof buf);
        gal_json_kv_str(j, "hash", buf);
        gal_json_obj_end(j);
    }
    gal_json_arr_end(j);
    gal_json_obj_end(j);
    gal_json_end(j);
}

int gal_outset_commit(gal_outset *o)
{
    if (!o->summary) return gal_error(GAL_EINPUT, "output set %s: commit without summary.json", o->dir);
    for (int i = 0; i < o->nfiles; i++)
        if (o->file[i].fp) return gal_error(GAL_EINPUT, "output set %s: %s still open", o->dir, o->file[i].name);
    write_record(o);
    FILE *fp = o->summary;
    o->summary = NULL;
    int st = close_synced(fp, o->dir, "summary.json"), fd;
    if (st || (st = gal_outset_lock(o->dir, &fd))) return st;
    st = gal_outset_recover(o->dir);
    if (!st) st = gal_outset_check_owned(o->dir, o->stage);
    char *mark = st ? NULL : gal_path_join(o->stage, OUTSET_MARK);
    FILE *m = mark ? fopen(mark, "w") : NULL;
    if (!st && (!m || close_synced(m, o->stage, OUTSET_MARK)))
        st = gal_error(GAL_EIO, "%s: cannot begin the commit: %s", o->dir, strerror(errno));
    free(mark);
    if (!st) {
        gal_outset_changed();
        o->journal = 1; /* from here the staging area is the journal: kept if the moves fail */
        st = gal_outset_finish(o->dir, o->stage);
        o->committed = !st;
    }
    gal_outset_unlock(fd);
    return st;
}

gal_outset *gal_outset_free(gal_outset *o)
{
    if (!o) return NULL;
    if (o->summary) fclose(o->summary);
    for (int i = 0; i < o->nfiles; i++)
        if (o->file[i].fp) fclose(o->file[i].fp);
    if (!o->committed && !o->journal) {
        gal_outset_remove_stage(o->stage);
        remove_made(o->dir, o->made); /* no empty directory left by a run that wrote nothing */
    }
    free(o->made);
    free(o->dir);
    free(o->stage);
    free(o);
    return NULL;
}
