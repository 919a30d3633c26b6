/* test_core.c: atomic output files and the JSON writer. */
#include "check.h"
#include "gallop.h"

#include <unistd.h>

static void test_ofile_commit_and_abort(void)
{
    char dir[] = "/tmp/gallop_test_XXXXXX";
    CHECK(mkdtemp(dir) != NULL, "mkdtemp");
    char *p = gal_path_join(dir, "a.csv");
    gal_ofile f;
    CHECK(gal_ofile_open(&f, p) == GAL_OK, "open");
    fprintf(f.fp, "x\n1\n");
    CHECK(access(p, F_OK) != 0, "the final file must not exist before close");
    CHECK(gal_ofile_close(&f, 1) == GAL_OK, "close");
    CHECK(access(p, F_OK) == 0, "the file exists after a successful close");
    remove(p);
    CHECK(gal_ofile_open(&f, p) == GAL_OK, "open again");
    fprintf(f.fp, "half");
    gal_ofile_close(&f, 0);
    CHECK(access(p, F_OK) != 0, "an aborted file leaves nothing");
    free(p);
    rmdir(dir);
}

static void test_ofile_unwritable(void)
{
    gal_ofile f;
    CHECK(gal_ofile_open(&f, "/nonexistent-dir/x.csv") == GAL_EIO, "open must fail");
    CHECK(strstr(gal_error_message(), "/nonexistent-dir/x.csv") != NULL, "message names the file");
}

static void test_json(void)
{
    char buf[512] = {0};
    FILE *fp = fmemopen(buf, sizeof buf - 1, "w");
    gal_json j;
    gal_json_begin(&j, fp);
    gal_json_kv_num(&j, "a", 1.5);
    gal_json_key(&j, "list");
    gal_json_arr_begin(&j);
    gal_json_obj_begin(&j);
    gal_json_kv_str(&j, "s", "q\"x");
    gal_json_obj_end(&j);
    gal_json_num(&j, NAN);
    gal_json_arr_end(&j);
    gal_json_end(&j);
    fclose(fp);
    const char *want = "{\n  \"a\": 1.5,\n  \"list\": [\n    {\n      \"s\": \"q\\\"x\"\n    },\n"
                       "    null\n  ]\n}\n";
    CHECK(!strcmp(buf, want), "got:\n%s", buf);
}

int main(void)
{
    RUN(test_ofile_commit_and_abort);
    RUN(test_ofile_unwritable);
    RUN(test_json);
    return CHECK_SUMMARY();
}
