/* ofile.c: output files that appear whole or not at all (a temporary file renamed on success),
 * mkdir -p and path joining. */
#define _POSIX_C_SOURCE 200809L
#include "gallop/output/ofile.h"
#include "gallop/base/core.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

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
    if (!path || !*path) return gal_error(GAL_EIO, "cannot create a directory of an empty name");
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

