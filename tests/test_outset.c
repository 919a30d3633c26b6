/* test_outset.c: the output set (output/outset.c): a run's files appear together under summary.json,
 * the commit record; a run killed before or at any point of its commit, or failing on a full disk,
 * leaves the previous run whole or (mid-commit) no summary.json, and the next run finishes or drops
 * it; dead runs' leftovers are cleaned, a live run's never; files gallop did not write survive. */
#define _XOPEN_SOURCE 700 /* setrlimit */
#include "check.h"
#include "gallop.h"
#include "gallop/output/outset.h"
#include "gallop/output/record.h"
#include "output/outset_int.h"

#include <dirent.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

static char root[64];
static int ndirs;

static char *fresh_dir(void)
{
    char *d = malloc(128);
    snprintf(d, 128, "%s/d%d", root, ndirs++);
    return d;
}

static char *path(const char *dir, const char *name)
{
    static char buf[4][256];
    static int k;
    k = (k + 1) % 4;
    snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
    return buf[k];
}

/* the first line of a file, "" when absent */
static const char *line(const char *dir, const char *name)
{
    static char buf[4][128];
    static int k;
    k = (k + 1) % 4;
    buf[k][0] = '\0';
    FILE *fp = fopen(path(dir, name), "r");
    if (fp) {
        if (!fgets(buf[k], sizeof buf[k], fp)) buf[k][0] = '\0';
        fclose(fp);
    }
    buf[k][strcspn(buf[k], "\n")] = '\0';
    return buf[k];
}

static void put(const char *dir, const char *name, const char *text)
{
    FILE *fp = fopen(path(dir, name), "w");
    if (fp) fputs(text, fp), fclose(fp);
}

static int exists(const char *dir, const char *name)
{
    struct stat sb;
    return lstat(path(dir, name), &sb) == 0;
}

/* entries of dir starting with prefix */
static int count(const char *dir, const char *prefix)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    int n = 0;
    while (d && (e = readdir(d)))
        n += !strncmp(e->d_name, prefix, strlen(prefix));
    if (d) closedir(d);
    return n;
}

/* A run "tag": each file's first line is "tag name", summary.json's first key "tag". `size` bytes
 * of padding in the first file (a full disk). Returns the status. */
static int run(const char *dir, const char *tag, const char *const *names, long size)
{
    gal_outset *o;
    int st = gal_outset_begin(&o, dir, "test");
    for (int i = 0; !st && names[i]; i++) {
        FILE *fp = gal_outset_open(o, names[i]);
        if (!fp) { st = GAL_EIO; break; }
        fprintf(fp, "%s %s\n", tag, names[i]);
        for (long k = 0; i == 0 && k < size; k++) fputc('x', fp);
        st = gal_outset_close(o, fp);
    }
    gal_json *j = st ? NULL : gal_outset_summary(o);
    if (!st && !j) st = GAL_EIO;
    if (!st) gal_json_kv_str(j, "tag", tag), st = gal_outset_commit(o);
    gal_outset_free(o);
    return st;
}

static const char *const run1[] = {"a.csv", "b.csv", NULL};
static const char *const run2[] = {"a.csv", "c.csv", NULL};

/* the tag of DIR/summary.json ("" when absent) */
static const char *summary_tag(const char *dir)
{
    static char tag[32];
    tag[0] = '\0';
    FILE *fp = fopen(path(dir, "summary.json"), "r");
    char buf[256];
    while (fp && fgets(buf, sizeof buf, fp))
        if (sscanf(buf, " \"tag\": \"%31[^\"]\"", tag) == 1) break;
    if (fp) fclose(fp);
    return tag;
}

/* summary.json and every file of `names` are run `tag`'s */
static int files_are(const char *dir, const char *tag, const char *const *names)
{
    int ok = !strcmp(summary_tag(dir), tag);
    char want[64];
    for (int i = 0; names[i]; i++) {
        snprintf(want, sizeof want, "%s %s", tag, names[i]);
        ok &= !strcmp(line(dir, names[i]), want);
    }
    return ok;
}

/* DIR holds exactly run `tag` of `names`, nothing of the other run, no staging area */
static int holds(const char *dir, const char *tag, const char *const *names, const char *const *other)
{
    int ok = files_are(dir, tag, names) && count(dir, ".gallop-staging.") == 0;
    for (int i = 0; other[i]; i++) {
        int mine = 0;
        for (int k = 0; names[k]; k++) mine |= !strcmp(names[k], other[i]);
        ok &= mine || !exists(dir, other[i]);
    }
    return ok;
}

static void test_commit_replace_remove(void)
{
    char *d = fresh_dir();
    put(root, "d0-sibling", "");
    CHECK(run(d, "1", run1, 0) == GAL_OK, "%s", gal_error_message());
    CHECK(holds(d, "1", run1, run2), "run 1 in place");
    outset_owned w;
    CHECK(!gal_outset_read_owned(path(d, "summary.json"), &w) && w.kind == OWNED_RECORD && w.n == 2, "record of 2");
    uint64_t h;
    long n;
    CHECK(!gal_record_file_hash(path(d, "a.csv"), &h, &n) && h == w.f[0].hash && n == w.f[0].bytes, "a.csv hash");
    CHECK(run(d, "2", run2, 0) == GAL_OK, "%s", gal_error_message());
    CHECK(holds(d, "2", run2, run1), "run 2 replaced a.csv, added c.csv, removed b.csv");
    free(d);
}

static void test_user_files(void)
{
    char *d = fresh_dir();
    mkdir(d, 0777);
    put(d, "notes.txt", "mine\n");
    put(d, "c.csv", "my own c\n");
    CHECK(run(d, "1", run1, 0) == GAL_OK, "%s", gal_error_message());
    CHECK(run(d, "2", run2, 0) == GAL_EIO, "c.csv is not gallop's: refused");
    CHECK(strstr(gal_error_message(), "c.csv") != NULL, "message names it: %s", gal_error_message());
    CHECK(files_are(d, "1", run1) && !strcmp(line(d, "c.csv"), "my own c"), "run 1 and c.csv untouched");
    CHECK(count(d, ".gallop-staging.") == 0, "the refused run's staging area removed");
    remove(path(d, "c.csv"));
    put(d, "b.csv", "1 b.csv edited\n");
    CHECK(run(d, "2", run2, 0) == GAL_EIO, "b.csv changed since run 1: refused");
    CHECK(!strcmp(line(d, "b.csv"), "1 b.csv edited") && !strcmp(summary_tag(d), "1"), "b.csv kept");
    remove(path(d, "b.csv"));
    CHECK(run(d, "2", run2, 0) == GAL_OK && holds(d, "2", run2, run1), "%s", gal_error_message());
    CHECK(!strcmp(line(d, "notes.txt"), "mine"), "the user's notes survive every run");
    put(d, "summary.json", "{\"mine\": 1}\n");
    gal_outset *o;
    CHECK(gal_outset_begin(&o, d, "test") == GAL_EIO && o == NULL, "a summary.json not gallop's: refused");
    CHECK(!strcmp(line(d, "summary.json"), "{\"mine\": 1}") && count(d, ".gallop-staging.") == 0, "untouched");
    free(d);
}

/* a summary.json of gallop 0.1 (no commit record) owns its command's files */
static void test_legacy_summary(void)
{
    char *d = fresh_dir();
    mkdir(d, 0777);
    put(d, "summary.json", "{\n  \"command\": \"stability\",\n  \"scene\": \"x.ini\"\n}\n");
    put(d, "stability.csv", "old\n");
    const char *const names[] = {"stability.csv", NULL};
    CHECK(run(d, "1", names, 0) == GAL_OK && holds(d, "1", names, run1), "%s", gal_error_message());
    free(d);
}

static void test_bad_names(void)
{
    char *d = fresh_dir();
    gal_outset *o;
    CHECK(gal_outset_begin(&o, d, "test") == GAL_OK, "%s", gal_error_message());
    const char *bad[] = {"../x.csv", ".hidden", "summary.json", "a/b", "", "a b"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) CHECK(gal_outset_open(o, bad[i]) == NULL, "'%s'", bad[i]);
    FILE *fp = gal_outset_open(o, "x.csv");
    CHECK(fp && gal_outset_open(o, "x.csv") == NULL, "a name twice");
    CHECK(gal_outset_commit(o) != GAL_OK, "commit without summary.json or with a file open");
    if (fp) gal_outset_close(o, fp);
    gal_outset_free(o);
    CHECK(count(d, ".gallop-staging.") == 0 && !exists(d, "x.csv") && !exists(d, "summary.json"), "aborted: nothing");
    free(d);
}

/* fork; the child runs fn and _exits with its status; returns the wait status */
static int in_child(int (*fn)(const char *), const char *d)
{
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) _exit(fn(d) == GAL_OK ? 0 : 3);
    int ws = 0;
    waitpid(pid, &ws, 0);
    return ws;
}

static int killed_before_commit(const char *d)
{
    gal_outset *o;
    if (gal_outset_begin(&o, d, "test")) return GAL_EFAIL;
    FILE *fp = gal_outset_open(o, "a.csv");
    if (fp) fputs("2 a.csv\n", fp), gal_outset_close(o, fp);
    gal_json *j = gal_outset_summary(o);
    if (j) gal_json_kv_str(j, "tag", "2");
    raise(SIGKILL);
    return GAL_EFAIL;
}

static void test_killed_before_commit(void)
{
    char *d = fresh_dir();
    CHECK(run(d, "1", run1, 0) == GAL_OK, "%s", gal_error_message());
    int ws = in_child(killed_before_commit, d);
    CHECK(WIFSIGNALED(ws) && WTERMSIG(ws) == SIGKILL, "the child was killed");
    CHECK(!strcmp(summary_tag(d), "1") && !strcmp(line(d, "a.csv"), "1 a.csv") && !strcmp(line(d, "b.csv"), "1 b.csv"),
          "the previous run intact and unmixed");
    CHECK(count(d, ".gallop-staging.") == 1, "the dead run's staging area is left until the next run");
    CHECK(run(d, "3", run2, 0) == GAL_OK && holds(d, "3", run2, run1), "the next run cleans it: %s",
          gal_error_message());
    free(d);
}

static int kill_at, fault_calls;
static void fault(void)
{
    if (++fault_calls == kill_at) raise(SIGKILL);
}
static int run2_faulty(const char *d)
{
    gal_outset_fault = fault;
    return run(d, "2", run2, 0);
}

/* a kill after each change of the file system during the commit of run 2 over run 1 */
static void test_killed_during_commit(void)
{
    int steps = 0;
    for (kill_at = 1; kill_at < 20; kill_at++) {
        char *d = fresh_dir();
        CHECK(run(d, "1", run1, 0) == GAL_OK, "%s", gal_error_message());
        int ws = in_child(run2_faulty, d);
        if (WIFEXITED(ws)) {
            CHECK(WEXITSTATUS(ws) == 0 && holds(d, "2", run2, run1), "commit without a kill");
            free(d);
            break;
        }
        steps++;
        const char *tag = summary_tag(d);
        int consistent = !tag[0] || (!strcmp(tag, "1") && files_are(d, "1", run1) && !exists(d, "c.csv")) ||
                         (!strcmp(tag, "2") && files_are(d, "2", run2) && !exists(d, "b.csv"));
        CHECK(consistent, "killed at step %d: summary.json '%s' with a.csv '%s', b.csv '%s', c.csv '%s'", kill_at, tag,
              line(d, "a.csv"), line(d, "b.csv"), line(d, "c.csv"));
        gal_outset *o; /* the next run in DIR finishes the commit */
        CHECK(gal_outset_begin(&o, d, "test") == GAL_OK, "%s", gal_error_message());
        gal_outset_free(o);
        CHECK(holds(d, "2", run2, run1), "killed at step %d: run 2 not finished by the next run", kill_at);
        free(d);
    }
    CHECK(steps >= 5, "%d kill points (mark, old summary aside, b.csv removed, a.csv, c.csv, summary.json)", steps);
}

static int full_disk(const char *d)
{
    struct rlimit rl = {4096, 4096};
    signal(SIGXFSZ, SIG_IGN);
    setrlimit(RLIMIT_FSIZE, &rl); /* writes past 4 KB fail with EFBIG, as on a full disk */
    int st = run(d, "2", run2, 100000);
    return st == GAL_EIO && strstr(gal_error_message(), "write error") ? GAL_OK : GAL_EFAIL;
}

static void test_full_disk(void)
{
    char *d = fresh_dir();
    CHECK(run(d, "1", run1, 0) == GAL_OK, "%s", gal_error_message());
    int ws = in_child(full_disk, d);
    CHECK(WIFEXITED(ws) && WEXITSTATUS(ws) == 0, "the run fails with a write error (status %d)", ws);
    CHECK(holds(d, "1", run1, run2), "run 1 intact, no staging area left");
    free(d);
}

static int sleeper(const char *d)
{
    (void)d;
    pause();
    return GAL_OK;
}

/* leftovers of a dead process go, a live process's stay, a user's look-alike stays */
static void test_stale_leftovers(void)
{
    char *d = fresh_dir();
    mkdir(d, 0777);
    fflush(stdout);
    pid_t live = fork();
    if (live == 0) sleeper(d), _exit(0);
    pid_t gone = fork();
    if (gone == 0) _exit(0);
    waitpid(gone, NULL, 0);
    char sd[64], sl[64], td[64], tl[64], ud[64];
    snprintf(sd, sizeof sd, ".gallop-staging.%ld.0", (long)gone);
    snprintf(sl, sizeof sl, ".gallop-staging.%ld.0", (long)live);
    snprintf(td, sizeof td, "summary.json.tmp.%ld", (long)gone);
    snprintf(tl, sizeof tl, "trace.csv.tmp.%ld", (long)live);
    snprintf(ud, sizeof ud, "notes.csv.tmp.%ld", (long)gone);
    mkdir(path(d, sd), 0700), put(path(d, sd), "a.csv", "dead\n");
    mkdir(path(d, sl), 0700), put(path(d, sl), "a.csv", "alive\n");
    put(d, td, ""), put(d, tl, ""), put(d, ud, "");
    CHECK(run(d, "1", run1, 0) == GAL_OK, "%s", gal_error_message());
    CHECK(!exists(d, sd) && !exists(d, td), "the dead process's staging area and tmp file are cleaned");
    CHECK(exists(d, sl) && !strcmp(line(path(d, sl), "a.csv"), "alive") && exists(d, tl), "the live one's stay");
    CHECK(exists(d, ud), "a dead pid's tmp file of a name gallop does not write stays");
    kill(live, SIGKILL);
    waitpid(live, NULL, 0);
    CHECK(run(d, "2", run2, 0) == GAL_OK && !exists(d, sl) && !exists(d, tl), "once dead, cleaned by the next run");
    free(d);
}

/* the scene hash: the same for another output directory, another for another tension */
static void test_scene_hash(void)
{
    gal_scene a, b;
    const char *o1[] = {"output.directory=/tmp/x"}, *t[] = {"span.horizontal_tension=30001"};
    uint64_t ha = 0, hb = 1, hc = 2;
    CHECK(!gal_scene_load(&a, "data/scenes/drake_300m.ini", NULL, 0, NULL), "%s", gal_error_message());
    CHECK(!gal_scene_load(&b, "data/scenes/drake_300m.ini", o1, 1, NULL), "%s", gal_error_message());
    CHECK(!gal_record_scene_hash(&a, &ha) && !gal_record_scene_hash(&b, &hb) && ha == hb, "output directory ignored");
    CHECK(!gal_scene_load(&b, "data/scenes/drake_300m.ini", t, 1, NULL), "%s", gal_error_message());
    CHECK(!gal_record_scene_hash(&b, &hc) && hc != ha, "another tension, another hash");
    CHECK(gal_record_fnv1a64("a", 1, GAL_FNV1A64_INIT) == 0xaf63dc4c8601ec8cull, "FNV-1a 64 of \"a\"");
    CHECK(gal_record_fnv1a64("", 0, GAL_FNV1A64_INIT) == 0xcbf29ce484222325ull, "FNV-1a 64 of \"\"");
    CHECK(!strcmp(gal_record_version(), GAL_VERSION) && gal_record_commit()[0], "version and commit");
}

/* issue 14: the output directory is checked before any computation, without making anything;
 * a set freed uncommitted removes the directories it made (no empty directory is left). */
static void test_check_and_no_empty_dir(void)
{
    char *d = fresh_dir(), sub[512], file[256];
    CHECK(gal_outset_check(d) == GAL_OK, "a new directory: %s", gal_error_message());
    struct stat sb;
    CHECK(stat(d, &sb) != 0, "the check made %s", d);
    CHECK(gal_outset_check("") == GAL_EINPUT, "an empty name");
    snprintf(file, sizeof file, "%s_file", d);
    FILE *fp = fopen(file, "w");
    if (fp) fclose(fp);
    CHECK(gal_outset_check(file) == GAL_EIO, "a regular file accepted");
    CHECK(strstr(gal_error_message(), "not a directory") != NULL, "%s", gal_error_message());
    snprintf(sub, sizeof sub, "%s/below", file);
    CHECK(gal_outset_check(sub) == GAL_EIO, "a directory below a regular file accepted");
    /* begin in a new nested directory, free uncommitted: nothing stays */
    snprintf(sub, sizeof sub, "%s/a/b", d);
    gal_outset *o;
    CHECK(gal_outset_begin(&o, sub, "test") == GAL_OK, "%s", gal_error_message());
    CHECK(stat(sub, &sb) == 0, "begin did not make %s", sub);
    gal_outset_free(o);
    CHECK(stat(d, &sb) != 0, "an uncommitted set left %s", d);
    /* an existing directory stays */
    CHECK(mkdir(d, 0777) == 0, "mkdir");
    CHECK(gal_outset_begin(&o, d, "test") == GAL_OK, "%s", gal_error_message());
    gal_outset_free(o);
    CHECK(stat(d, &sb) == 0 && S_ISDIR(sb.st_mode), "the user's directory was removed");
    free(d);
}

int main(void)
{
    snprintf(root, sizeof root, "/tmp/gallop_outset_XXXXXX");
    if (!mkdtemp(root)) return 1;
    RUN(test_commit_replace_remove);
    RUN(test_user_files);
    RUN(test_legacy_summary);
    RUN(test_bad_names);
    RUN(test_killed_before_commit);
    RUN(test_killed_during_commit);
    RUN(test_full_disk);
    RUN(test_stale_leftovers);
    RUN(test_scene_hash);
    RUN(test_check_and_no_empty_dir);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", root);
    if (system(cmd) != 0) printf("  (could not remove %s)\n", root);
    return CHECK_SUMMARY();
}
