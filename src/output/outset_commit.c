/* outset_commit.c: the commit of an output set (outset.h): the lock of the directory, the files a
 * summary.json says gallop wrote, the check that a commit replaces or removes only those, the
 * moves, and the recovery of the runs that died before or during their commit. */
#define _POSIX_C_SOURCE 200809L
#include "output/outset_int.h"
#include "gallop/base/core.h"
#include "gallop/output/ofile.h"
#include "gallop/output/record.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

void (*gal_outset_fault)(void);

void gal_outset_changed(void)
{
    if (gal_outset_fault) gal_outset_fault();
}

/* ---- the lock ---- */

int gal_outset_lock(const char *dir, int *fd)
{
    *fd = open(dir, O_RDONLY | O_DIRECTORY);
    if (*fd < 0) return gal_error(GAL_EIO, "%s: cannot open the output directory: %s", dir, strerror(errno));
    while (flock(*fd, LOCK_EX) != 0)
        if (errno != EINTR) {
            int e = errno;
            close(*fd);
            return gal_error(GAL_EIO, "%s: cannot lock the output directory: %s", dir, strerror(e));
        }
    return GAL_OK;
}

void gal_outset_unlock(int fd)
{
    fsync(fd); /* the renames and removals reach the disk */
    close(fd); /* releases the lock */
}

/* ---- what a summary.json says gallop wrote ---- */

/* The files of each command before summary.json had a commit record (gallop 0.1), and the first
 * key of its summary.json. */
static const struct {
    const char *first_key, *command, *files[3];
} legacy[] = {
    {"command", "modes", {"equilibrium.csv", "modes.csv", "shapes.csv"}},
    {"command", "simulate", {"trace.csv"}},
    {"command", "compare", {"compare.csv"}},
    {"command", "stability", {"stability.csv"}},
    {"command", "wind", {"wind.csv"}},
    {"trace", NULL, {"psd.csv"}},
    {"scene", NULL, {"accuracy.csv"}},
};
#define NLEGACY (int)(sizeof legacy / sizeof legacy[0])

static char *slurp(const char *path, int *missing)
{
    FILE *fp = fopen(path, "rb");
    *missing = !fp && errno == ENOENT;
    if (!fp) return NULL;
    size_t cap = 1 << 16, n = 0, k;
    char *s = malloc(cap + 1);
    while (s && (k = fread(s + n, 1, cap - n, fp)) > 0) {
        n += k;
        if (n == cap && cap < (64u << 20)) {
            char *t = realloc(s, 2 * cap + 1);
            if (!t) free(s);
            s = t, cap *= 2;
        } else if (n == cap) {
            break; /* over 64 MB: not a summary.json */
        }
    }
    fclose(fp);
    if (s) s[n] = '\0';
    return s;
}

/* the string value after `"key": "` within [p, end), into out */
static int str_value(const char *p, const char *end, const char *key, char *out, size_t n)
{
    char pat[64];
    snprintf(pat, sizeof pat, "\"%s\": \"", key);
    const char *s = strstr(p, pat);
    if (!s || s >= end) return 0;
    s += strlen(pat);
    const char *e = strchr(s, '"');
    if (!e || e >= end || (size_t)(e - s) >= n) return 0;
    memcpy(out, s, (size_t)(e - s));
    out[e - s] = '\0';
    return 1;
}

/* commit_record.files: [{"name": .., "bytes": .., "hash": "fnv1a64:.."}, ...] */
static int parse_record(const char *text, outset_owned *w)
{
    const char *p = strstr(text, "\"commit_record\": {");
    p = p ? strstr(p, "\"files\": [") : NULL;
    const char *end = p ? strchr(p, ']') : NULL;
    if (!end) return 0;
    for (const char *o = strchr(p, '{'); o && o < end; o = strchr(o + 1, '{')) {
        const char *oe = strchr(o, '}'), *b = strstr(o, "\"bytes\": ");
        char hash[40];
        outset_file *f = w->f + w->n;
        if (w->n == GAL_OUTSET_MAX_FILES || !oe || oe > end || !b || b > oe) return 0;
        if (!str_value(o, oe, "name", f->name, sizeof f->name) || !str_value(o, oe, "hash", hash, sizeof hash) ||
            strncmp(hash, "fnv1a64:", 8) || strchr(f->name, '/') || f->name[0] == '.')
            return 0;
        f->bytes = strtol(b + 9, NULL, 10);
        f->hash = strtoull(hash + 8, NULL, 16);
        w->n++;
    }
    return 1;
}

static int parse_legacy(const char *text, outset_owned *w)
{
    for (int i = 0; i < NLEGACY; i++) {
        char head[64];
        if (legacy[i].command) snprintf(head, sizeof head, "{\n  \"%s\": \"%s\"", legacy[i].first_key, legacy[i].command);
        else snprintf(head, sizeof head, "{\n  \"%s\": \"", legacy[i].first_key);
        if (strncmp(text, head, strlen(head))) continue;
        for (int k = 0; k < 3 && legacy[i].files[k]; k++) {
            snprintf(w->f[w->n].name, sizeof w->f[w->n].name, "%s", legacy[i].files[k]);
            w->f[w->n++].bytes = -1;
        }
        return 1;
    }
    return 0;
}

int gal_outset_read_owned(const char *path, outset_owned *w)
{
    int missing;
    memset(w, 0, sizeof *w);
    char *text = slurp(path, &missing);
    w->kind = OWNED_NONE;
    if (missing) return GAL_OK;
    if (!text) return gal_error(GAL_EIO, "%s: cannot read: %s", path, strerror(errno));
    if (parse_record(text, w)) w->kind = OWNED_RECORD;
    else if ((w->n = 0, parse_legacy(text, w))) w->kind = OWNED_LEGACY;
    else w->kind = OWNED_FOREIGN, w->n = 0;
    free(text);
    return GAL_OK;
}

/* ---- the check: a commit replaces or removes only gallop's files ---- */

static const outset_file *find(const outset_owned *w, const char *name)
{
    for (int i = 0; i < w->n; i++)
        if (!strcmp(w->f[i].name, name)) return w->f + i;
    return NULL;
}

/* DIR/name: 0 absent, 1 a regular file that `w` names with its size and hash (or a legacy name),
 * -1 anything else */
static int mine(const char *dir, const char *name, const outset_owned *w)
{
    char *path = gal_path_join(dir, name);
    struct stat sb;
    int r = -1, got = path ? lstat(path, &sb) : -1;
    if (path && got != 0 && errno == ENOENT) r = 0;
    else if (got == 0 && S_ISREG(sb.st_mode)) {
        const outset_file *f = find(w, name);
        uint64_t h;
        long n;
        if (f && (f->bytes < 0 || (f->bytes == (long)sb.st_size && !gal_record_file_hash(path, &h, &n) &&
                                   h == f->hash && n == f->bytes)))
            r = 1;
    }
    free(path);
    return r;
}

static int refuse(const char *dir, const char *name, const char *what)
{
    return gal_error(GAL_EIO, "%s/%s %s: gallop replaces or removes only the files it wrote, unchanged; move it "
                     "away or choose another directory with -o (the files in %s are left as they were)",
                     dir, name, what, dir);
}

int gal_outset_check_owned(const char *dir, const char *stage)
{
    char *po = gal_path_join(dir, "summary.json"), *pn = gal_path_join(stage, "summary.json");
    outset_owned old, neu;
    int st = po && pn ? GAL_OK : gal_error(GAL_ENOMEM, "out of memory");
    if (!st) st = gal_outset_read_owned(po, &old);
    if (!st) st = gal_outset_read_owned(pn, &neu);
    free(po);
    free(pn);
    if (st) return st;
    if (neu.kind != OWNED_RECORD) return gal_error(GAL_EFAIL, "%s: the new summary.json has no commit record", stage);
    if (old.kind == OWNED_FOREIGN) return refuse(dir, "summary.json", "was not written by gallop");
    for (int i = 0; i < neu.n && !st; i++)
        if (mine(dir, neu.f[i].name, &old) < 0)
            st = refuse(dir, neu.f[i].name, "exists and is not named, unchanged, by the summary.json there");
    for (int i = 0; i < old.n && !st; i++)
        if (!find(&neu, old.f[i].name) && mine(dir, old.f[i].name, &old) < 0)
            st = refuse(dir, old.f[i].name, "of the previous run changed since gallop wrote it and would be left "
                        "beside the new run's files");
    return st;
}

/* ---- the moves ---- */

static int move(const char *from_dir, const char *to_dir, const char *name, const char *to_name)
{
    char *a = gal_path_join(from_dir, name), *b = gal_path_join(to_dir, to_name);
    int st = a && b ? GAL_OK : gal_error(GAL_ENOMEM, "out of memory");
    if (!st && rename(a, b) != 0 && errno != ENOENT)
        st = gal_error(GAL_EIO, "%s: cannot rename to %s: %s", a, b, strerror(errno));
    else if (!st) gal_outset_changed();
    free(a);
    free(b);
    return st;
}

static int exists(const char *dir, const char *name)
{
    char *p = gal_path_join(dir, name);
    struct stat sb;
    int r = p && lstat(p, &sb) == 0;
    free(p);
    return r;
}

int gal_outset_finish(const char *dir, const char *stage)
{
    outset_owned neu, old;
    char *pn = gal_path_join(stage, "summary.json"), *pp = gal_path_join(stage, OUTSET_PREVIOUS);
    int st = pn && pp ? gal_outset_read_owned(pn, &neu) : gal_error(GAL_ENOMEM, "out of memory");
    if (!st && neu.kind == OWNED_RECORD) {
        /* the summary.json in DIR is still the old run's while the new one is in the staging area */
        if (!exists(stage, OUTSET_PREVIOUS)) st = move(dir, stage, "summary.json", OUTSET_PREVIOUS);
        if (!st) st = gal_outset_read_owned(pp, &old);
        for (int i = 0; !st && i < old.n; i++) {
            if (find(&neu, old.f[i].name) || mine(dir, old.f[i].name, &old) != 1) continue;
            char *p = gal_path_join(dir, old.f[i].name);
            if (p && unlink(p) == 0) gal_outset_changed();
            free(p);
        }
        for (int i = 0; !st && i < neu.n; i++) st = move(stage, dir, neu.f[i].name, neu.f[i].name);
        if (!st) st = move(stage, dir, "summary.json", "summary.json");
    }
    free(pn);
    free(pp);
    if (!st) gal_outset_remove_stage(stage);
    return st;
}

void gal_outset_remove_stage(const char *stage)
{
    DIR *d = opendir(stage);
    struct dirent *e;
    while (d && (e = readdir(d))) {
        char *p = gal_path_join(stage, e->d_name);
        struct stat sb;
        if (p && lstat(p, &sb) == 0 && S_ISREG(sb.st_mode)) unlink(p);
        free(p);
    }
    if (d) closedir(d);
    rmdir(stage);
}

/* ---- the leftovers of dead runs ---- */

/* "<prefix><pid>[.<n>]" or "<name>.tmp.<pid>": the pid, else 0 */
static long pid_of(const char *s, const char *prefix)
{
    size_t lp = strlen(prefix);
    if (strncmp(s, prefix, lp)) return 0;
    char *end;
    long pid = strtol(s + lp, &end, 10);
    if (end == s + lp || (*end && *end != '.')) return 0;
    return pid > 0 ? pid : 0;
}

static int dead(long pid)
{
    return pid != (long)getpid() && kill((pid_t)pid, 0) != 0 && errno == ESRCH;
}

/* a gal_ofile leftover of one of gallop's output names: "<name>.tmp.<pid>" */
static long tmp_pid(const char *s)
{
    const char *t = strstr(s, ".tmp.");
    if (!t) return 0;
    size_t ln = (size_t)(t - s);
    int known = ln == 12 && !strncmp(s, "summary.json", 12);
    for (int i = 0; i < NLEGACY && !known; i++)
        for (int k = 0; k < 3 && legacy[i].files[k]; k++)
            known |= strlen(legacy[i].files[k]) == ln && !strncmp(s, legacy[i].files[k], ln);
    return known && !strchr(t + 5, '.') ? pid_of(t, ".tmp.") : 0;
}

int gal_outset_recover(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d) return gal_error(GAL_EIO, "%s: cannot read the output directory: %s", dir, strerror(errno));
    char **names = NULL;
    size_t n = 0, cap = 0;
    struct dirent *e;
    int st = GAL_OK;
    while (!st && (e = readdir(d))) { /* first the names: the directory changes below */
        long ps = pid_of(e->d_name, OUTSET_STAGE_PREFIX), pt = tmp_pid(e->d_name);
        if (!(ps && dead(ps)) && !(pt && dead(pt))) continue;
        char **t = n == cap ? realloc(names, (cap = 2 * cap + 4) * sizeof *names) : names;
        if (t) names = t;
        if (!t || !(names[n] = strdup(e->d_name))) st = gal_error(GAL_ENOMEM, "out of memory");
        else n++;
    }
    closedir(d);
    for (size_t i = 0; i < n; i++) {
        char *p = gal_path_join(dir, names[i]);
        if (!st && p && pid_of(names[i], OUTSET_STAGE_PREFIX)) {
            /* a commit that had begun is finished; a run that had not begun to commit is dropped */
            if (exists(p, OUTSET_MARK)) st = gal_outset_finish(dir, p);
            else gal_outset_remove_stage(p);
        } else if (!st && p) {
            unlink(p);
        }
        free(p);
        free(names[i]);
    }
    free(names);
    return st;
}
