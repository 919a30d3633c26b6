/* select.c: which of the computed modes a reduced model takes (modes.h, gal_modes_select): the
 * lowest asked of each family, and each selected vertical mode's torsional partner (the torsional
 * mode of its parity nearest it in frequency), for the single rod and the explicit bundle alike. */
#include "gallop/modes/modes.h"

#include <math.h>

double gal_modes_partner_top(const gal_modes *md, const int want[GAL_FAMILY_COUNT])
{
    int nv = 0;
    double top = 0;
    if (want[GAL_FAMILY_TORSIONAL] < 1) return 0;
    for (int k = 0; k < md->n && nv < want[GAL_FAMILY_VERTICAL]; k++)
        if (md->mode[k].family == GAL_FAMILY_VERTICAL) top = md->mode[k].frequency_hz, nv++;
    return (1 + GAL_PARTNER_BAND) * top;
}

/* The torsional mode of vertical mode v's parity nearest it in frequency within the band, or -1. */
static int partner_of(const gal_modes *md, int v)
{
    const gal_mode *mv = md->mode + v;
    int best = -1;
    for (int k = 0; k < md->n; k++) {
        const gal_mode *m = md->mode + k;
        double d = fabs(m->frequency_hz - mv->frequency_hz);
        if (m->family != GAL_FAMILY_TORSIONAL || m->parity != mv->parity || d > GAL_PARTNER_BAND * mv->frequency_hz)
            continue;
        if (best < 0 || d < fabs(md->mode[best].frequency_hz - mv->frequency_hz)) best = k;
    }
    return best;
}

void gal_modes_select(gal_modes *md, const int want[GAL_FAMILY_COUNT])
{
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) md->selected[f] = 0;
    for (int k = 0; k < md->n; k++) {
        gal_mode *m = md->mode + k;
        m->selected = 0, m->partner = 0;
        if (m->family < GAL_FAMILY_AXIAL && md->selected[m->family] < want[m->family])
            m->selected = 1, md->selected[m->family]++;
    }
    if (want[GAL_FAMILY_TORSIONAL] < 1) return;
    for (int k = 0; k < md->n; k++) {
        const gal_mode *v = md->mode + k;
        if (v->family != GAL_FAMILY_VERTICAL || !v->selected) continue;
        int p = partner_of(md, k);
        if (p < 0 || md->mode[p].selected) continue;
        md->mode[p].selected = 1, md->mode[p].partner = v->index;
        md->selected[GAL_FAMILY_TORSIONAL]++;
    }
}

int gal_modes_partner_near(const gal_modes *md, double f, int *v, double *rel)
{
    *v = -1, *rel = INFINITY;
    for (int k = 0; k < md->n; k++) {
        const gal_mode *m = md->mode + k;
        if (m->family == GAL_FAMILY_VERTICAL && m->selected && m->frequency_hz > 0 &&
            (*v < 0 || fabs(m->frequency_hz - f) < fabs(md->mode[*v].frequency_hz - f)))
            *v = k;
    }
    int p = *v >= 0 ? partner_of(md, *v) : -1;
    if (p >= 0) *rel = fabs(md->mode[p].frequency_hz / md->mode[*v].frequency_hz - 1);
    return p;
}
