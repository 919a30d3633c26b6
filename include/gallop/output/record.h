/* record.h: what every summary.json records of the run that wrote it: the gallop version, the git
 * commit it was built from, a schema version, and a hash of what it computed from. */
#ifndef GALLOP_OUTPUT_RECORD_H
#define GALLOP_OUTPUT_RECORD_H

#include <stddef.h>
#include <stdint.h>

#include "gallop/scene/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GAL_VERSION "0.1"
/* Schema of summary.json: 1 is the first with schema_version, gallop_version, git_commit,
 * scene_hash (trace_hash for `gallop spectrum`) and commit_record. */
#define GAL_SCHEMA_VERSION 1
#define GAL_FNV1A64_INIT 0xcbf29ce484222325ull

/* GAL_VERSION. */
const char *gal_record_version(void);
/* The short git commit baked in by the Makefile (-DGAL_COMMIT), "unknown" outside a checkout. */
const char *gal_record_commit(void);

/* 64-bit FNV-1a of n bytes, continuing from h (GAL_FNV1A64_INIT to start). */
uint64_t gal_record_fnv1a64(const void *data, size_t n, uint64_t h);
/* FNV-1a 64 of the resolved scene: the text `gallop check` prints for it (gal_scene_print)
 * without its '#' comment lines (the scene file's name) and without the [output] section (where
 * the files go), so that the same computation has the same hash wherever it is run from or
 * written to. */
int gal_record_scene_hash(const gal_scene *sc, uint64_t *hash);
/* FNV-1a 64 and size of a file's bytes. GAL_EIO when it cannot be read. */
int gal_record_file_hash(const char *path, uint64_t *hash, long *bytes);
/* "fnv1a64:" and 16 hex digits into buf (at least 25 chars). */
void gal_record_hash_format(uint64_t hash, char *buf, size_t n);

#ifdef __cplusplus
}
#endif

#endif
