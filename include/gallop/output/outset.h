/* outset.h: one output set per run, for every command that writes files. The run's files appear
 * in DIR together or not at all, and summary.json, moved in last, is the commit record that names
 * the run and its files:
 *
 *   gal_outset_begin  DIR/.gallop-staging.<pid>.<n>/ is made; leftovers of dead runs are cleaned
 *   gal_outset_open/close  each file is written there under its final name (fsync on close)
 *   gal_outset_summary     summary.json is opened there; the caller writes its keys
 *   gal_outset_commit      the run record is appended to summary.json (schema_version,
 *                          gallop_version, git_commit, scene_hash or trace_hash, commit_record:
 *                          run_id, command, created, pid and each file's name, bytes, fnv1a64);
 *                          then, under an exclusive lock of DIR: the old summary.json is moved
 *                          aside into the staging area, the old run's other files are removed,
 *                          the new files are renamed in, the new summary.json last.
 *
 * A reader takes DIR/summary.json as the run: while it is absent, DIR holds no complete run; when
 * it is present, every file it names is the one it describes (bytes, fnv1a64). A kill at any point
 * leaves DIR with the old run, the new run, or no summary.json; the next run in DIR finishes an
 * interrupted commit of a dead process (its staging area holds a ".commit" mark) or deletes the
 * staging area of a dead process that had not begun to commit, and the "<name>.tmp.<pid>" files
 * gal_ofile leaves of a dead process (for gallop's own output names). The staging area of a live
 * process (kill(pid, 0)) is never touched.
 *
 * DIR may hold the user's own files: gallop replaces or removes a file only when DIR/summary.json
 * names it and it still has the size and hash recorded there (or, for a summary.json written
 * before the commit record, the files that command wrote). Any other file under a name the run
 * writes makes the commit fail (GAL_EIO, the old files untouched), with a message naming it. */
#ifndef GALLOP_OUTPUT_OUTSET_H
#define GALLOP_OUTPUT_OUTSET_H

#include <stdio.h>

#include "gallop/output/json.h"
#include "gallop/scene/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GAL_OUTSET_MAX_FILES 16

typedef struct gal_outset gal_outset;

/* Check, before any computation, that dir can hold a run, without making anything: dir is a
 * writable directory whose summary.json (if any) is gallop's, or it does not exist and its
 * nearest existing ancestor is a writable directory (no component is a regular file).
 * GAL_EINPUT for an empty name, GAL_EIO otherwise, with a message naming the path. */
int gal_outset_check(const char *dir);
/* Begin the outputs of `command` in dir (made as by mkdir -p; the directories it made are removed
 * again when the set is freed uncommitted: a failed run leaves no empty directory). GAL_EIO when dir cannot be made
 * or written, or when dir/summary.json is not gallop's. *set is NULL on failure. */
int gal_outset_begin(gal_outset **set, const char *dir, const char *command);
/* What the run computed from: the resolved scene (scene_hash, record.h) or an input file
 * (trace_hash: the hash of its bytes; key is the summary.json key). */
int gal_outset_scene(gal_outset *o, const gal_scene *sc);
int gal_outset_input(gal_outset *o, const char *key, const char *path);
/* A data file of the run; name is a plain file name ([A-Za-z0-9._-], not starting with '.', not
 * summary.json, once per set). NULL with a message on failure. */
FILE *gal_outset_open(gal_outset *o, const char *name);
/* Flush, fsync and close a file of gal_outset_open; GAL_EIO on any write error (a full disk). */
int gal_outset_close(gal_outset *o, FILE *fp);
/* summary.json, begun ('{' written): the caller writes its keys, then calls gal_outset_commit.
 * NULL with a message on failure. */
gal_json *gal_outset_summary(gal_outset *o);
/* Append the run record, close summary.json and move the run into place (see above). */
int gal_outset_commit(gal_outset *o);
/* Free; an uncommitted set's staging area is removed (the old files stay). Accepts NULL;
 * returns NULL. */
gal_outset *gal_outset_free(gal_outset *o);
/* The output directory. */
const char *gal_outset_dir(const gal_outset *o);

#ifdef __cplusplus
}
#endif

#endif
