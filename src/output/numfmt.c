/* numfmt.c: "%.9g" by scaling with an exact power of ten and rounding once (one correctly rounded
 * multiplication or division), falling back on snprintf where that could round otherwise than
 * the exact decimal value does (a scaled value within a millionth of a half) and outside the
 * exactly representable powers of ten. */
#include "output/numfmt.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const double pow10_exact[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                       1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

int gal_fmt_int(char *buf, int i)
{
    char tmp[12];
    int n = 0, len = 0;
    unsigned u = i < 0 ? 0u - (unsigned)i : (unsigned)i;
    do tmp[n++] = (char)('0' + u % 10); while (u /= 10);
    if (i < 0) buf[len++] = '-';
    while (n) buf[len++] = tmp[--n];
    return len;
}

/* r (9 digits, 10^8 <= r < 10^9) times 10^(e - 8) in %g's style: fixed for -4 <= e < 9, else
 * d.ddddddddde+XX; trailing zeros (and a bare point) dropped. */
static int layout(char *buf, int neg, unsigned r, int e)
{
    char d[9];
    for (int k = 8; k >= 0; k--) d[k] = (char)('0' + r % 10), r /= 10;
    int nd = 9, len = 0;
    while (nd > 1 && d[nd - 1] == '0') nd--;
    if (neg) buf[len++] = '-';
    if (e < -4 || e >= 9) {
        buf[len++] = d[0];
        if (nd > 1) {
            buf[len++] = '.';
            memcpy(buf + len, d + 1, (size_t)(nd - 1));
            len += nd - 1;
        }
        buf[len++] = 'e';
        buf[len++] = e < 0 ? '-' : '+';
        int a = e < 0 ? -e : e;
        if (a >= 100) buf[len++] = (char)('0' + a / 100);
        buf[len++] = (char)('0' + a / 10 % 10);
        buf[len++] = (char)('0' + a % 10);
    } else if (e >= 0) {
        memcpy(buf + len, d, (size_t)(e + 1)); /* e + 1 <= 9 integer digits */
        len += e + 1;
        if (nd > e + 1) {
            buf[len++] = '.';
            memcpy(buf + len, d + e + 1, (size_t)(nd - e - 1));
            len += nd - e - 1;
        }
    } else {
        buf[len++] = '0', buf[len++] = '.';
        for (int k = 0; k < -e - 1; k++) buf[len++] = '0';
        memcpy(buf + len, d, (size_t)nd);
        len += nd;
    }
    return len;
}

int gal_fmt_g9(char *buf, double x)
{
    double a = fabs(x);
    if (x == 0 || !isfinite(x)) goto slow;
    int e = (int)floor(log10(a));
    for (int pass = 0; pass < 2; pass++) {
        int k = 8 - e; /* a 10^k in [1e8, 1e9) */
        if (k > 22 || k < -22) goto slow;
        double m = k >= 0 ? a * pow10_exact[k] : a / pow10_exact[-k];
        if (m < 1e8) { e--; continue; }     /* log10 rounded up across a power of ten */
        if (m >= 1e9) { e++; continue; }
        double f = floor(m), frac = m - f;
        if (fabs(frac - 0.5) < 1e-6) goto slow; /* near a tie: the exact value decides */
        double r = frac > 0.5 ? f + 1 : f;
        if (r >= 1e9) r = 1e8, e++;
        return layout(buf, x < 0, (unsigned)r, e);
    }
slow:;
    char tmp[32];
    int n = snprintf(tmp, sizeof tmp, "%.9g", x);
    memcpy(buf, tmp, (size_t)n);
    return n;
}
