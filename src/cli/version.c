/* cli/version.c: `gallop version` and `gallop --version`: the version and the git commit built. */
#include <stdio.h>

#include "cli.h"
#include "gallop/output/record.h"

int gal_cli_version(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    printf("gallop %s (commit %s)\n", gal_record_version(), gal_record_commit());
    return 0;
}
