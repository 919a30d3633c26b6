/* cli.h: the gallop sub-commands. Each returns the process exit status (0, 1 computation failed,
 * 2 bad input). */
#ifndef GALLOP_CLI_H
#define GALLOP_CLI_H

typedef int (*gal_cli_fn)(int argc, char **argv);

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

/* ---- shared by the sub-commands (src/cli/common.c) ---- */
struct gal_scene;
/* argv[0] is the sub-command; then SCENE, any number of `--set section.key=value`, `-o DIR`.
 * Loads the scene (data/conductors.csv found as gal_scene_load says) and reads the [ice]
 * aero_table it names (gal_model_aero_table), so that a bad table is refused by every command
 * before anything is computed or written; *outdir (may be NULL) is
 * DIR, else the scene's output.directory (which -o also sets). Any other argument is an error.
 * Returns the exit status: 0, or 2 (or 1 when out of memory) with the message on stderr. */
int gal_cli_load_scene(int argc, char **argv, struct gal_scene *sc, const char **outdir);
/* The same, also accepting the command's own value options: opts is a NULL-terminated list
 * ("--model", ...); vals[i] receives the value of opts[i] (NULL when absent). */
int gal_cli_load_scene_opts(int argc, char **argv, struct gal_scene *sc, const char **outdir,
                            const char *const *opts, const char **vals);

#endif
