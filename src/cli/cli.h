/* cli.h: the gallop sub-commands. Each returns the process exit status (0, 1 computation failed,
 * 2 bad input). */
#ifndef GALLOP_CLI_H
#define GALLOP_CLI_H

typedef int (*gal_cli_fn)(int argc, char **argv);
struct gal_scene;

/* One entry per sub-command, in src/cli_<name>.c. */
int gal_cli_version(int argc, char **argv);
int gal_cli_check(int argc, char **argv);
int gal_cli_modes(int argc, char **argv);
int gal_cli_simulate(int argc, char **argv);
int gal_cli_compare(int argc, char **argv);
int gal_cli_spectrum(int argc, char **argv);
int gal_cli_stability(int argc, char **argv);
int gal_cli_wind(int argc, char **argv);
int gal_cli_accuracy(int argc, char **argv);
int gal_cli_sweep(int argc, char **argv);
/* `gallop modes` of an explicit bundle (src/cli/bundle.c) */
int gal_cli_modes_bundle(const struct gal_scene *sc, const char *outdir);
/* `gallop simulate [--model reduced|full]` of an explicit bundle (src/cli/bundle.c) */
int gal_cli_simulate_bundle(const struct gal_scene *sc, const char *outdir, int reduced);
/* A warning on stderr when the explicit bundle's mesh is below its galloping runs' rule
 * (GAL_BUNDLE_SUBSPAN_ELEMENTS in every sub-span); cmd names the command. */
void gal_cli_bundle_mesh_warning(const struct gal_scene *sc, const char *cmd);
/* `gallop compare` of an explicit bundle (src/cli/bundle_compare.c) */
int gal_cli_compare_bundle(const struct gal_scene *sc, const char *outdir);
/* compare's figures on stdout: the headline (each family at its probe) and, with more than one
 * probe, every probe's errors; twist names the twist column ("twist", "rotation") */
struct gal_compare_figures;
void gal_cli_print_compare(const struct gal_compare_figures *c, const char *twist, double setup_s);

/* ---- the commands and their options (src/cli/usage.c) ---- */
#include <stdio.h>

#define GAL_CLI_MAX_OPTS 8    /* options per command */
#define GAL_CLI_MAX_VALS 256  /* values of one repeatable option */

typedef struct {
    const char *name;     /* long name without "--"; NULL ends the list */
    char shortopt;        /* 'o' or 0 */
    const char *arg;      /* the value's name ("DIR"); NULL: a flag */
    int repeat;           /* may be given more than once (every value kept) */
    const char *help;
} gal_cli_optdoc;

typedef struct {
    const char *name;
    gal_cli_fn fn;
    const char *operand;  /* "SCENE", "TRACE.csv" or NULL (no operand) */
    const char *what;     /* the operand in messages ("scene") */
    const char *summary;  /* one line */
    const char *details;  /* lines after the options, or NULL */
    gal_cli_optdoc opt[GAL_CLI_MAX_OPTS];
} gal_cli_command;

extern const gal_cli_command gal_cli_commands[];
extern const int gal_cli_ncommands;
const gal_cli_command *gal_cli_command_find(const char *name);
void gal_cli_synopsis(FILE *fp, const gal_cli_command *c);
void gal_cli_usage(FILE *fp, const gal_cli_command *c);   /* `gallop COMMAND --help` */
void gal_cli_usage_all(FILE *fp);                         /* `gallop --help` */

/* ---- the option parser, getopt_long (src/cli/common.c) ---- */
typedef struct {
    const char *operand;                                  /* SCENE or TRACE.csv, or NULL */
    int help;                                             /* -h or --help was given */
    int nval[GAL_CLI_MAX_OPTS];                           /* per option of the command's table */
    const char *val[GAL_CLI_MAX_OPTS][GAL_CLI_MAX_VALS];  /* its values in order (pointers into argv) */
} gal_cli_args;

/* Parse argv (argv[0] is the command) against the command's options with getopt_long: options
 * and the operand in any order, "--name value", "--name=value", "-o DIR", "--" ends the options.
 * Returns 0, or 2 with "gallop COMMAND: what is wrong" and the synopsis on stderr. */
int gal_cli_parse(const gal_cli_command *c, int argc, char **argv, gal_cli_args *a);
/* The values of option `name` (without "--") and their count; the last one, or NULL. */
int gal_cli_values(const gal_cli_command *c, const gal_cli_args *a, const char *name, const char *const **vals);
const char *gal_cli_value(const gal_cli_command *c, const gal_cli_args *a, const char *name);
/* The scene of parsed arguments: SCENE with the --set values, -o DIR; as gal_cli_load_scene. */
int gal_cli_scene(const gal_cli_command *c, const gal_cli_args *a, struct gal_scene *sc, const char **outdir);

/* ---- the BLAS threads (src/cli/blas.c): one unless GALLOP_BLAS_THREADS says otherwise; may
 * re-execute gallop with OPENBLAS_NUM_THREADS set (argv: main's). ---- */
void gal_cli_blas_threads(char **argv);
/* Under an address-space limit: 1 (a message on stderr) when it leaves no room for the BLAS
 * buffer, else the buffer taken at once so that the BLAS never waits for memory later; 0. */
int gal_cli_blas_reserve(void);

/* ---- shared by the sub-commands (src/cli/common.c) ---- */
/* argv[0] is the sub-command; then SCENE, any number of `--set section.key=value`, `-o DIR`
 * (parsed by gal_cli_parse against the command's table in usage.c).
 * Loads the scene (data/conductors.csv found as gal_scene_load says) and reads the [ice]
 * aero_table it names (gal_model_aero_table), so that a bad table is refused by every command
 * before anything is computed or written; *outdir (may be NULL) is
 * DIR, else the scene's output.directory (which -o also sets). Any other argument is an error.
 * Returns the exit status: 0, or 2 (or 1 when out of memory) with the message on stderr. */
int gal_cli_load_scene(int argc, char **argv, struct gal_scene *sc, const char **outdir);
/* The same, also accepting the command's own value options: opts is a NULL-terminated list
 * ("--model", ...: options of the command's table); vals[i] receives the (last) value of opts[i]
 * (NULL when absent). */
int gal_cli_load_scene_opts(int argc, char **argv, struct gal_scene *sc, const char **outdir,
                            const char *const *opts, const char **vals);

#endif
