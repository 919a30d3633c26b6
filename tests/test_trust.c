/* test_trust.c: issue 14's library promises not covered elsewhere: trace time stamps that never
 * repeat (output/simreport.c), the sample count of a run bounded with the key named
 * (scene/finish.c gal_scene_sample_count). */
#include "check.h"
#include "gallop.h"
#include "gallop/output/simreport.h"
#include "gallop/scene/scene.h"

#include <unistd.h>

/* trace.csv's time stamps: distinct for consecutive samples even 1e-7 s apart at 1e3 s */
static void test_time_stamps_distinct(void)
{
    double time[4], trace[16] = {0}, tension[8] = {0};
    gal_sim_result r;
    memset(&r, 0, sizeof r);
    r.nprobe = 1, r.probe[0] = 0.5, r.nsamples = 4, r.dt_out = 1e-7;
    r.time = time, r.trace = trace, r.tension = tension;
    for (int i = 0; i < 4; i++) time[i] = 1000 + i * r.dt_out;
    char path[64];
    snprintf(path, sizeof path, "/tmp/gallop_trust_%ld.csv", (long)getpid());
    CHECK(gal_sim_write_trace(path, &r) == GAL_OK, "%s", gal_error_message());
    FILE *fp = fopen(path, "r");
    char line[512], stamp[4][64];
    int n = 0;
    while (fp && fgets(line, sizeof line, fp))
        if (line[0] >= '0' && line[0] <= '9' && n < 4) sscanf(line, "%63[^,]", stamp[n++]);
    if (fp) fclose(fp);
    remove(path);
    CHECK(n == 4, "%d samples read", n);
    for (int i = 1; i < n; i++)
        CHECK(strcmp(stamp[i], stamp[i - 1]) != 0, "time stamps %d and %d repeat: %s", i - 1, i, stamp[i]);
}

static void test_sample_count(void)
{
    gal_scene sc;
    memset(&sc, 0, sizeof sc);
    snprintf(sc.path, sizeof sc.path, "x.ini");
    sc.simulation.duration = 10;
    long ns;
    CHECK(gal_scene_sample_count(&sc, 10, 0.01, 64, &ns) == GAL_OK && ns == 1001, "%ld", ns);
    CHECK(gal_scene_sample_count(&sc, 10, 1.0, 64, &ns) == GAL_EINPUT && ns == 0, "11 samples accepted");
    CHECK(strstr(gal_error_message(), "[simulation] duration") != NULL, "%s", gal_error_message());
    CHECK(gal_scene_sample_count(&sc, 10, 1e-300, 64, &ns) == GAL_EINPUT, "1e301 samples accepted");
    CHECK(strstr(gal_error_message(), "[simulation] output_interval") != NULL, "%s", gal_error_message());
}

int main(void)
{
    RUN(test_time_stamps_distinct);
    RUN(test_sample_count);
    return CHECK_SUMMARY();
}
