/* fuzz_scene.c: libFuzzer harness for the scene parser (issue 8): the input is written to a
 * scene file and read by gal_scene_load, which must return a status (GAL_OK or an error with a
 * message), never crash, leak or read out of bounds. A resolved scene is printed back (to
 * /dev/null) so that gal_scene_print sees every accepted value too. Built by `make fuzz`; run
 * from the repository root so that `name = Drake` finds data/conductors.csv. The temporary
 * directory holds scenes/ and a link aero -> data/aero, so the seeds from data/scenes resolve
 * their aero_table (../aero/...). */
#define _XOPEN_SOURCE 700
#include <limits.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "gallop/base/core.h"
#include "gallop/scene/scene.h"

static char tmpdir[64], scene_path[PATH_MAX], conductors[PATH_MAX], aero_link[PATH_MAX],
    scenes_dir[PATH_MAX];
static FILE *devnull;

static void cleanup(void)
{
    unlink(scene_path), unlink(aero_link), rmdir(scenes_dir), rmdir(tmpdir);
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc, (void)argv;
    char aero[PATH_MAX];
    strcpy(tmpdir, "/tmp/gallop_fuzz_scene_XXXXXX");
    if (!mkdtemp(tmpdir)) { perror("mkdtemp"); exit(1); }
    snprintf(scenes_dir, sizeof scenes_dir, "%s/scenes", tmpdir);
    snprintf(aero_link, sizeof aero_link, "%s/aero", tmpdir);
    snprintf(scene_path, sizeof scene_path, "%s/fuzz.ini", scenes_dir);
    atexit(cleanup);
    if (mkdir(scenes_dir, 0700) != 0) { perror("mkdir"); exit(1); }
    if (realpath("data/aero", aero)) (void)!symlink(aero, aero_link);
    if (!realpath("data/conductors.csv", conductors)) {
        fprintf(stderr, "fuzz_scene: run from the repository root (data/conductors.csv)\n");
        exit(1);
    }
    devnull = fopen("/dev/null", "w");
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FILE *fp = fopen(scene_path, "wb");
    if (!fp) abort();
    if (size && fwrite(data, 1, size, fp) != size) abort();
    fclose(fp);
    gal_scene sc;
    int st = gal_scene_load(&sc, scene_path, NULL, 0, conductors);
    if (st == GAL_OK) {
        gal_scene_print(&sc, devnull);
    } else if (!gal_error_message() || !*gal_error_message()) {
        abort(); /* every refusal says why */
    }
    return 0;
}
