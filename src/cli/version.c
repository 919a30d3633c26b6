/* cli/version.c: `gallop version`. */
#include <stdio.h>

#include "cli.h"

int gal_cli_version(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    printf("gallop 0.1\n");
    return 0;
}
