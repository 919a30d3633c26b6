/* fuzz_aero.c: libFuzzer harness for the aerodynamic table parser (issue 8): the input is written
 * to a CSV file and read by gal_aero_table_read, which must return a status (a table, or an
 * error with a message), never crash, leak or read out of bounds. An accepted table is evaluated
 * over more than a period (and at non-finite angles): its coefficients and their derivatives
 * must be finite wherever the angle is, since the reader accepts only finite, bounded values.
 * Built by `make fuzz`. */
#define _XOPEN_SOURCE 700
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "gallop/loads/aero.h"
#include "gallop/base/core.h"

static char tmpdir[64], table_path[96];

static void cleanup(void) { unlink(table_path), rmdir(tmpdir); }

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc, (void)argv;
    strcpy(tmpdir, "/tmp/gallop_fuzz_aero_XXXXXX");
    if (!mkdtemp(tmpdir)) { perror("mkdtemp"); exit(1); }
    snprintf(table_path, sizeof table_path, "%s/table.csv", tmpdir);
    atexit(cleanup);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FILE *fp = fopen(table_path, "wb");
    if (!fp) abort();
    if (size && fwrite(data, 1, size, fp) != size) abort();
    fclose(fp);
    gal_aero_table *t = NULL;
    int st = gal_aero_table_read(table_path, &t);
    if (st != GAL_OK) {
        if (t || !gal_error_message() || !*gal_error_message()) abort();
        return 0;
    }
    if (!t) abort();
    for (int k = -400; k <= 400; k += 7) {
        double c[3], dc[3];
        gal_aero_eval(t, k * (M_PI / 180.0) + 1e-3, c, dc);
        for (int i = 0; i < 3; i++)
            if (!isfinite(c[i]) || !isfinite(dc[i])) abort();
    }
    double c[3], dc[3];
    gal_aero_eval(t, NAN, c, dc); /* documented: NaN in, NaN out, no crash */
    gal_aero_eval(t, 1e300, c, dc);
    gal_aero_table_free(t);
    return 0;
}
