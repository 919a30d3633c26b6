/* cli/version.c: `gallop version`. */
#include <stdio.h>

#include "cli.h"
#include "gallop/output/record.h"

int gal_cli_version(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    printf("gallop %s\n", gal_record_version());
    return 0;
}
