/* first_frequencies.c: the first natural frequencies of a span through libgallop: a scene file,
 * its sagged equilibrium, the lowest modes of each family. Build with pkg-config:
 *   cc first_frequencies.c $(pkg-config --cflags --libs gallop) -o first_frequencies */
#include <stdio.h>

#include <gallop.h>

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : "data/scenes/drake_300m.ini";
    gal_scene sc;
    gal_rod_params p;
    gal_statics_spec spec;
    double value;
    gal_equilibrium eq;
    gal_modes md;
    int want[GAL_FAMILY_COUNT] = {2, 2, 1, 0};   /* vertical, horizontal, torsional, axial */
    if (gal_scene_load(&sc, path, NULL, 0, NULL) || gal_model_rod_params(&sc, &p, &spec, &value)) {
        fprintf(stderr, "%s\n", gal_error_message());
        return 2;
    }
    if (gal_statics_solve(&p, spec, value, NULL, &eq)) {
        fprintf(stderr, "no equilibrium: %s\n", gal_error_message());
        return 1;
    }
    int st = gal_modes_find(eq.rod, eq.q, want, 100, &md);
    if (st == GAL_OK) {
        printf("%s: sag %.3f m, horizontal tension %.0f N\n", sc.name, eq.sag, eq.horizontal_tension);
        for (int k = 0; k < md.n; k++)
            if (md.mode[k].selected)
                printf("%-10s %.6f Hz\n", gal_family_names[md.mode[k].family], md.mode[k].frequency_hz);
        gal_modes_clear(&md);
    } else {
        fprintf(stderr, "modes: %s\n", gal_error_message());
    }
    gal_equilibrium_clear(&eq);
    return st ? 1 : 0;
}
