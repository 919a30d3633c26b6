/* cli/common.c: what the sub-commands share: reading SCENE [--set section.key=value ...] [-o DIR]
 * from the command line, loading the scene and reading the tables it names. */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "gallop.h"
#include "gallop/model/tables.h"
#include "gallop/scene/scene.h"

#define MAX_SETS 256

static int usage_error(const char *cmd, const char *what, const char *arg)
{
    fprintf(stderr, "gallop %s: %s%s%s\nusage: gallop %s SCENE [--set section.key=value ...] "
            "[-o DIR]\n", cmd, what, arg ? " " : "", arg ? arg : "", cmd);
    return 2;
}

int gal_cli_load_scene_opts(int argc, char **argv, gal_scene *sc, const char **outdir,
                            const char *const *opts, const char **vals)
{
    const char *cmd = argc > 0 && argv[0] ? argv[0] : "?";
    const char *sets[MAX_SETS];
    const char *scene = NULL, *dir = NULL;
    int nsets = 0;
    for (int j = 0; opts && opts[j]; j++) vals[j] = NULL;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        int j = -1;
        for (int q = 0; opts && opts[q]; q++)
            if (!strcmp(a, opts[q])) j = q;
        if (j >= 0) {
            if (i + 1 >= argc) return usage_error(cmd, "missing value after", a);
            vals[j] = argv[++i];
        } else if (!strcmp(a, "--set") || !strncmp(a, "--set=", 6)) {
            const char *v = a[5] == '=' ? a + 6 : (i + 1 < argc ? argv[++i] : NULL);
            if (!v) return usage_error(cmd, "missing section.key=value after", a);
            if (nsets == MAX_SETS) return usage_error(cmd, "too many --set options", NULL);
            sets[nsets++] = v;
        } else if (!strcmp(a, "-o")) {
            if (i + 1 >= argc) return usage_error(cmd, "missing directory after", a);
            dir = argv[++i];
        } else if (a[0] == '-' && a[1] != '\0') {
            return usage_error(cmd, "unknown option", a);
        } else if (scene) {
            return usage_error(cmd, "more than one scene:", a);
        } else {
            scene = a;
        }
    }
    if (!scene) return usage_error(cmd, "no scene given", NULL);
    int st = gal_scene_load(sc, scene, sets, nsets, NULL);
    if (st == GAL_OK && sc->ice.aero_table[0]) {
        /* the table is read now, whatever the command: a bad one is bad input before any output */
        gal_aero_table *t = NULL;
        st = gal_model_aero_table(sc, &t);
        gal_aero_table_free(t);
    }
    if (st != GAL_OK) {
        fprintf(stderr, "gallop %s: %s\n", cmd, gal_error_message());
        return gal_exit_code(st);
    }
    if (dir) {
        if (!*dir || strlen(dir) >= sizeof sc->output.directory)
            return usage_error(cmd, "-o: directory name empty or too long:", dir);
        strcpy(sc->output.directory, dir);
    }
    if (outdir) *outdir = sc->output.directory;
    return 0;
}

int gal_cli_load_scene(int argc, char **argv, gal_scene *sc, const char **outdir)
{
    return gal_cli_load_scene_opts(argc, argv, sc, outdir, NULL, NULL);
}
