/* ofile.h: output files that appear whole or not at all, mkdir -p, path joining. */
#ifndef GALLOP_OUTPUT_OFILE_H
#define GALLOP_OUTPUT_OFILE_H

#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

/* gal_ofile_open writes to "<path>.tmp.<pid>"; gal_ofile_close renames it to <path> on success
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

#ifdef __cplusplus
}
#endif

#endif
