/* record.c: the run record of every summary.json (record.h): version, build commit, FNV-1a
 * hashes of the resolved scene and of files. */
#define _POSIX_C_SOURCE 200809L
#include "gallop/output/record.h"
#include "gallop/base/core.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef GAL_COMMIT
#define GAL_COMMIT "unknown"
#endif

const char *gal_record_version(void) { return GAL_VERSION; }
const char *gal_record_commit(void) { return GAL_COMMIT[0] ? GAL_COMMIT : "unknown"; }

uint64_t gal_record_fnv1a64(const void *data, size_t n, uint64_t h)
{
    const unsigned char *p = data;
    for (size_t i = 0; i < n; i++) {
        h ^= p[i];
        h *= 0x100000001b3ull; /* the FNV 64-bit prime */
    }
    return h;
}

void gal_record_hash_format(uint64_t hash, char *buf, size_t n)
{
    snprintf(buf, n, "fnv1a64:%016llx", (unsigned long long)hash);
}

/* The printed scene line by line: '#' lines and the [output] section left out. */
static uint64_t hash_scene_text(const char *text)
{
    uint64_t h = GAL_FNV1A64_INIT;
    int in_output = 0;
    for (const char *s = text; *s;) {
        const char *e = strchr(s, '\n');
        size_t n = e ? (size_t)(e - s) + 1 : strlen(s);
        if (s[0] == '[') in_output = !strncmp(s, "[output]", 8);
        if (s[0] != '#' && !in_output) h = gal_record_fnv1a64(s, n, h);
        s += n;
    }
    return h;
}

int gal_record_scene_hash(const gal_scene *sc, uint64_t *hash)
{
    char *text = NULL;
    size_t len = 0;
    FILE *fp = open_memstream(&text, &len);
    if (!fp) return gal_error(GAL_ENOMEM, "out of memory hashing the scene");
    gal_scene_print(sc, fp);
    int bad = ferror(fp);
    if (fclose(fp) != 0 || bad || !text) {
        free(text);
        return gal_error(GAL_ENOMEM, "out of memory hashing the scene");
    }
    *hash = hash_scene_text(text);
    free(text);
    return GAL_OK;
}

int gal_record_file_hash(const char *path, uint64_t *hash, long *bytes)
{
    FILE *fp = fopen(path, "rb");
    if (!fp) return gal_error(GAL_EIO, "%s: cannot read: %s", path, strerror(errno));
    unsigned char buf[16384];
    uint64_t h = GAL_FNV1A64_INIT;
    long total = 0;
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, fp)) > 0) h = gal_record_fnv1a64(buf, n, h), total += (long)n;
    int bad = ferror(fp);
    fclose(fp);
    if (bad) return gal_error(GAL_EIO, "%s: read error", path);
    *hash = h;
    if (bytes) *bytes = total;
    return GAL_OK;
}
