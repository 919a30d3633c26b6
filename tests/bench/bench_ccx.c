/* bench_ccx.c: statics + 30 modes of a 300 m ACSR Drake span at 1000 elements (H = 28 kN), gallop
 * against CalculiX (ccx, issue 16: at least 1000x faster). The CalculiX deck, written here to
 * build/bench/ccx/span.inp, is the same span as B31 beams of a square section with the conductor's EA,
 * EI and mass (GJ and the polar inertia are the square's: gallop is given the same), its nodes on
 * the catenary's shape; the tension comes from a nonlinear static step (NLGEOM) that applies
 * gravity and, as nodal temperatures, the thermal strain -T/EA of the catenary's tension at
 * H = 28 kN; then *FREQUENCY, 30 modes. The frequencies are compared (the same
 * problem) and both are timed in CPU time (gallop: median of 5 in a child; ccx: the child's user +
 * system time of one run) with each one's peak memory. Without ccx on the PATH: says so, skips. */
#include "bench_util.h"

#include <math.h>
#include <sys/stat.h>

#include "gallop/modes/modes.h"
#include "gallop/statics/statics.h"

#define NEL 1000
#define NMODES 30
#define ALPHA 1e-5 /* 1/K, the deck's expansion coefficient (any: only the strain counts) */

static gal_rod_params span(void)
{
    double EA = 3.73e7, EI = 44.1, m = 1.628, a = sqrt(12 * EI / EA); /* square a x a: EI/EA = a^2/12 */
    double G = EA / (a * a) / (2 * 1.3), J = 0.1406 * a * a * a * a; /* nu = 0.3; St-Venant's square */
    gal_rod_params p = {.length = 300, .elements = NEL, .EA = EA, .EI = EI, .GJ = G * J, .mass = m,
                        .polar_inertia = m * a * a / 6, .gravity = 9.80665, .torsion = 1, .twist_clamped = 1};
    return p;
}

/* gallop: out[0] CPU s (median of 5), out[1..30] the frequencies (Hz) */
static int run_gallop(void *arg, double *out)
{
    (void)arg;
    gal_rod_params p = span();
    double t[5];
    for (int r = 0; r < 5; r++) {
        gal_equilibrium eq;
        gal_modes md;
        double t0 = bench_cpu();
        if (gal_statics_solve(&p, GAL_BY_TENSION, 28000, NULL, &eq) || gal_modes_solve_eq(&eq, NMODES, &md)) {
            fprintf(stderr, "bench_ccx: %s\n", gal_error_message());
            return 1;
        }
        t[r] = bench_cpu() - t0;
        for (int k = 0; k < NMODES; k++) out[1 + k] = md.mode[k].frequency_hz;
        gal_modes_clear(&md);
        gal_equilibrium_clear(&eq);
    }
    out[0] = bench_median(t, 5);
    return 0;
}

/* The deck (see the file's comment): nodes on the elastic catenary's shape for H = 28 kN
 * (z = (H/w)(cosh(w(x - L/2)/H) - cosh(w L/2H)), w = m g), nodal temperatures for the strain
 * -T(x)/EA, T = H cosh(w(x - L/2)/H): CalculiX starts where gallop's own first guess does, and
 * finds its equilibrium itself. */
static int write_deck(const char *path)
{
    gal_rod_params p = span();
    double a = sqrt(12 * p.EI / p.EA), E = p.EA / (a * a), H = 28000, w = p.mass * p.gravity, L = p.length;
    FILE *f = fopen(path, "w");
    if (!f) return 1;
    fprintf(f, "*HEADING\ngallop bench: 300 m Drake span at H = 28 kN, B31, tension by nodal temperatures\n");
    fprintf(f, "*NODE,NSET=NALL\n");
    for (int i = 0; i <= NEL; i++) {
        double x = L * i / NEL, z = (H / w) * (cosh(w * (x - L / 2) / H) - cosh(w * L / (2 * H)));
        fprintf(f, "%d,%.12g,0,%.12g\n", i + 1, x, z);
    }
    fprintf(f, "*ELEMENT,TYPE=B31,ELSET=EALL\n");
    for (int j = 0; j < NEL; j++) fprintf(f, "%d,%d,%d\n", j + 1, j + 1, j + 2);
    fprintf(f, "*NSET,NSET=ENDS\n1,%d\n*BOUNDARY\nENDS,1,4,0\n", NEL + 1);
    fprintf(f, "*MATERIAL,NAME=M\n*ELASTIC\n%.12g,0.3\n*DENSITY\n%.12g\n*EXPANSION\n%g\n", E, p.mass / (a * a), ALPHA);
    fprintf(f, "*BEAM SECTION,ELSET=EALL,MATERIAL=M,SECTION=RECT\n%.12g,%.12g\n0.,1.,0.\n", a, a);
    fprintf(f, "*INITIAL CONDITIONS,TYPE=TEMPERATURE\nNALL,0.\n*STEP,NLGEOM,INC=1000\n*STATIC\n0.25,1.\n*TEMPERATURE\n");
    for (int i = 0; i <= NEL; i++) {
        double x = L * i / NEL, t = H * cosh(w * (x - L / 2) / H);
        fprintf(f, "%d,%.12g\n", i + 1, -t / p.EA / ALPHA);
    }
    fprintf(f, "*DLOAD\nEALL,GRAV,%.12g,0.,0.,-1.\n*NODE PRINT,NSET=ENDS\nRF\n*END STEP\n", p.gravity);
    fprintf(f, "*STEP,PERTURBATION\n*FREQUENCY\n%d\n*END STEP\n", NMODES);
    fclose(f);
    return 0;
}

/* ccx's frequencies (the cycles/time column of span.dat's eigenvalue output) */
static int read_ccx(const char *path, double *hz)
{
    FILE *f = fopen(path, "r");
    char line[512];
    int k = 0, on = 0;
    if (!f) return 1;
    while (k < NMODES && fgets(line, sizeof line, f)) {
        int mode;
        double ev, rad, cyc;
        if (strstr(line, "E I G E N V A L U E   O U T P U T")) on = 1;
        else if (on && sscanf(line, "%d %lf %lf %lf", &mode, &ev, &rad, &cyc) == 4 && mode == k + 1) hz[k++] = cyc;
    }
    fclose(f);
    return k != NMODES;
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "build/bench/ccx";
    if (system("command -v ccx >/dev/null 2>&1")) {
        printf("BENCH|CalculiX comparison|skipped|-|ccx (Debian calculix-ccx) is not installed\n");
        return 0;
    }
    double g[1 + NMODES], mb_g, c[NMODES], dummy[1], mb_c;
    if (bench_fork(run_gallop, NULL, g, 1 + NMODES, &mb_g)) return 1;
    char deck[512], cmd[1100], dat[512];
    mkdir(dir, 0755);
    snprintf(deck, sizeof deck, "%s/span.inp", dir);
    snprintf(dat, sizeof dat, "%s/span.dat", dir);
    if (write_deck(deck)) return 1;
    snprintf(cmd, sizeof cmd, "cd '%s' && OMP_NUM_THREADS=1 ccx -i span >ccx.log 2>&1", dir);
    struct rusage r0, r1;
    getrusage(RUSAGE_CHILDREN, &r0);
    int st = system(cmd);
    getrusage(RUSAGE_CHILDREN, &r1);
    (void)dummy;
    mb_c = r1.ru_maxrss / 1024.0; /* the largest child so far: ccx's (far above the gallop child's) */
    double tc = (double)(r1.ru_utime.tv_sec - r0.ru_utime.tv_sec + r1.ru_stime.tv_sec - r0.ru_stime.tv_sec) +
                1e-6 * (double)(r1.ru_utime.tv_usec - r0.ru_utime.tv_usec + r1.ru_stime.tv_usec - r0.ru_stime.tv_usec);
    if (st || read_ccx(dat, c)) {
        printf("BENCH|CalculiX comparison|failed|-|ccx did not finish (%s/ccx.log)\n", dir);
        return 1;
    }
    double worst = 0;
    for (int k = 0; k < NMODES; k++) worst = fmax(worst, fabs(g[1 + k] / c[k] - 1));
    printf("BENCH|statics + %d modes, %d elements, gallop|%.2f|ms|CPU, median of 5; peak memory %.1f MB\n", NMODES, NEL,
           1e3 * g[0], mb_g);
    printf("BENCH|statics + %d modes, %d elements, CalculiX %s|%.2f|s|CPU of one run (B31, NLGEOM static + *FREQUENCY); "
           "peak memory %.1f MB; deck %s\n", NMODES, NEL, "ccx", tc, mb_c, deck);
    printf("BENCH|gallop speedup over CalculiX|%.0f|x|same span: the %d frequencies agree within %.2f%% (f1 %.6f vs "
           "%.6f Hz, f%d %.6f vs %.6f Hz)\n", tc / g[0], NMODES, 100 * worst, g[1], c[0], NMODES, g[NMODES], c[NMODES - 1]);
    return 0;
}
