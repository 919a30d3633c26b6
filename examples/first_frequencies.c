/* first_frequencies.c: the first natural frequencies of a span through libgallop: a scene file,
 * the model made from it, the pipeline run up to the modes (equilibrium, then modes), printed.
 * Build with pkg-config:
 *   cc first_frequencies.c $(pkg-config --cflags --libs gallop) -o first_frequencies */
#include <stdio.h>

#include <gallop.h>

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : "data/scenes/drake_300m.ini";
    gal_scene sc;
    int st = gal_scene_load(&sc, path, NULL, 0, NULL);   /* conductor rows from conductors.csv */
    if (st) {
        fprintf(stderr, "%s\n", gal_error_message());
        return 2;
    }
    gal_model *m = gal_model_alloc(&sc, &st);            /* immutable: mesh, tables, modes wanted */
    gal_data *d = m ? gal_data_alloc(m) : NULL;          /* what the stages compute */
    if (m && !d) st = GAL_ENOMEM;
    if (!st) st = gal_forward(m, d, GAL_STAGE_MODES);    /* sagged equilibrium, then the modes */
    if (!st) {
        printf("%s: sag %.3f m, horizontal tension %.0f N\n", sc.name, d->eq.sag, d->eq.horizontal_tension);
        for (int k = 0; k < d->md.n; k++)
            if (d->md.mode[k].selected)
                printf("%-10s %.6f Hz\n", gal_family_names[d->md.mode[k].family], d->md.mode[k].frequency_hz);
    } else {
        fprintf(stderr, "%s: %s\n", path, gal_error_message());
    }
    gal_data_free(d);
    gal_model_free(m);
    return st ? 1 : 0;
}
