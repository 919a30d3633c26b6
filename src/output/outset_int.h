/* outset_int.h: the inside of the output set (outset.c: the API; outset_commit.c: the lock, the
 * recovery of dead runs, the ownership of files, the moves). */
#ifndef GALLOP_OUTSET_INT_H
#define GALLOP_OUTSET_INT_H

#include <stdint.h>
#include <stdio.h>

#include "gallop/output/outset.h"

#define OUTSET_STAGE_PREFIX ".gallop-staging."
#define OUTSET_MARK ".commit"         /* in the staging area: the commit has begun */
#define OUTSET_PREVIOUS ".previous.json" /* in the staging area: the replaced summary.json */
#define OUTSET_NAME_MAX 64

typedef struct outset_file {
    char name[OUTSET_NAME_MAX];
    FILE *fp;        /* open, or NULL once closed */
    long bytes;      /* -1: any (a file of a summary.json without a commit record) */
    uint64_t hash;   /* FNV-1a 64 of its bytes */
} outset_file;

struct gal_outset {
    char *dir;        /* DIR */
    char *stage;      /* DIR/.gallop-staging.<pid>.<n> */
    char *made;       /* the highest directory of DIR gal_outset_begin made, or NULL */
    char command[32];
    char input_key[32];
    uint64_t input_hash;
    int nfiles;
    outset_file file[GAL_OUTSET_MAX_FILES];
    FILE *summary;    /* stage/summary.json while open */
    gal_json json;
    int journal;      /* the commit has begun: the staging area is its journal, kept on failure */
    int committed;
};

/* The files a summary.json says gallop wrote. */
typedef enum { OWNED_NONE, OWNED_RECORD, OWNED_LEGACY, OWNED_FOREIGN } owned_kind;
typedef struct outset_owned {
    owned_kind kind;  /* NONE: no such file; FOREIGN: not a gallop summary */
    int n;
    outset_file f[GAL_OUTSET_MAX_FILES];
} outset_owned;

int gal_outset_read_owned(const char *summary_path, outset_owned *w);
/* Exclusive lock of DIR (flock on the directory; released by close or death). */
int gal_outset_lock(const char *dir, int *fd);
void gal_outset_unlock(int fd);
/* Under the lock: finish the interrupted commits and delete the staging areas of dead processes,
 * delete gal_ofile leftovers "<gallop output name>.tmp.<pid>" of dead processes. */
int gal_outset_recover(const char *dir);
/* Under the lock: every file the commit of `stage` would replace or remove is gallop's. */
int gal_outset_check_owned(const char *dir, const char *stage);
/* Under the lock, once stage/.commit exists: the moves (idempotent; resumes where a dead process
 * stopped), then the staging area is removed. */
int gal_outset_finish(const char *dir, const char *stage);
/* Delete the regular files of a staging area and the directory. */
void gal_outset_remove_stage(const char *stage);

/* Fault injection for the tests: when set, gal_outset_changed calls it after each change of the
 * file system during a commit (the mark, each rename and removal); a test kills the process there. */
extern void (*gal_outset_fault)(void);
void gal_outset_changed(void);

#endif
