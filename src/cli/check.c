/* cli/check.c: `gallop check SCENE [--set section.key=value ...]`: parse, validate and print the
 * resolved scene (as INI that gallop reads back). */
#include <stdio.h>

#include "cli.h"
#include "gallop.h"
#include "gallop/scene/scene.h"

int gal_cli_check(int argc, char **argv)
{
    gal_scene sc;
    int rc = gal_cli_load_scene(argc, argv, &sc, NULL);
    if (rc) return rc;
    gal_scene_print(&sc, stdout);
    if (fflush(stdout) != 0) {
        perror("gallop check: stdout");
        return 1;
    }
    return 0;
}
