/* The closest point of a CIRCL or PARAB segment (rs_pseg_curve): the candidate contact of
 * a curved segment of the profile, for the searches of closest.c. */
#include "profile.h"

#include <float.h>
#include <math.h>

/* f'(xi)/1 = (X(xi) - P).X'(xi) = a3 xi^3 + a2 xi^2 + a1 xi + a0 */
static inline double cubic(const double a[4], double x)
{
    return ((a[3] * x + a[2]) * x + a[1]) * x + a[0];
}

static inline double dcubic(const double a[4], double x)
{
    return (3.0 * a[3] * x + 2.0 * a[2]) * x + a[1];
}

/* Root of the cubic in (lo, hi) with cubic < 0 at lo and > 0 at hi: Newton steps kept
 * inside the bracket, bisection when a step leaves it, to full precision. */
static double cubic_root(const double a[4], double lo, double hi)
{
    double x = 0.5 * (lo + hi);
    for (int it = 0; it < 200; it++) {
        double f = cubic(a, x);
        if (f == 0.0)
            return x;
        if (f < 0.0)
            lo = x;
        else
            hi = x;
        double df = dcubic(a, x), xn = df != 0.0 ? x - f / df : lo;
        if (!(xn > lo && xn < hi))
            xn = 0.5 * (lo + hi);
        if (xn == x || hi - lo <= 2.0 * DBL_EPSILON * fmax(fabs(lo), fabs(hi)) ||
            hi - lo <= DBL_MIN)
            return xn;
        x = xn;
    }
    return x;
}

/* Closest interior point of a PARAB. The signs of the cubic at xi = -1 and xi = 1 come
 * from the vertex tests (in_start: decreasing at -1; in_end: increasing at 1) so that
 * segment and vertex ownership agree exactly. Returns 0 when no interior minimum. */
static int parab_min(const rs_pseg *q, double px, double py, int in_start, int in_end,
                     double *xi_out)
{
    double D[2] = {q->o[0] - px, q->o[1] - py};
    const double *B = q->B, *C = q->C;
    double a[4];
    a[3] = 2.0 * (C[0] * C[0] + C[1] * C[1]);
    a[2] = 3.0 * (B[0] * C[0] + B[1] * C[1]);
    a[1] = (B[0] * B[0] + B[1] * B[1]) + 2.0 * (D[0] * C[0] + D[1] * C[1]);
    a[0] = D[0] * B[0] + D[1] * B[1];
    /* break points where the cubic turns: 3 a3 x^2 + 2 a2 x + a1 = 0 */
    double br[4];
    int nb = 0;
    br[nb++] = -1.0;
    double qa = 3.0 * a[3], qb = 2.0 * a[2], qc = a[1], r[2];
    int nr = 0;
    if (qa == 0.0) {
        if (qb != 0.0)
            r[nr++] = -qc / qb;
    } else {
        double disc = qb * qb - 4.0 * qa * qc;
        if (disc > 0.0) {
            double qq = -0.5 * (qb + copysign(sqrt(disc), qb));
            r[nr++] = qq / qa;
            if (qq != 0.0)
                r[nr++] = qc / qq;
        }
    }
    if (nr == 2 && r[0] > r[1]) {
        double t = r[0];
        r[0] = r[1];
        r[1] = t;
    }
    for (int i = 0; i < nr; i++)
        if (r[i] > -1.0 && r[i] < 1.0)
            br[nb++] = r[i];
    br[nb++] = 1.0;
    double best = INFINITY, bxi = 0.0;
    int found = 0;
    for (int i = 0; i + 1 < nb; i++) {
        double l = br[i], h = br[i + 1];
        double fl = i == 0 ? (in_start ? -1.0 : 1.0) : cubic(a, l);
        double fh = i + 2 == nb ? (in_end ? 1.0 : -1.0) : cubic(a, h);
        if (!(fl < 0.0 && fh > 0.0))
            continue;
        double xi = cubic_root(a, l, h);
        double X0 = D[0] + xi * B[0] + xi * xi * C[0];
        double X1 = D[1] + xi * B[1] + xi * xi * C[1];
        double f = X0 * X0 + X1 * X1;
        if (f < best) {
            best = f;
            bxi = xi;
            found = 1;
        }
    }
    *xi_out = bxi;
    return found;
}

int rs_pseg_curve(const rs_pcache *pc, const rs_pseg *q, double px, double py, rs_hit2 *h)
{
    const int k = q->self;
    int in_start, in_end;
    rs_pseg_owns(q, px, py, &in_start, &in_end);
    switch (q->type) {
    case RS_CIRCL: {
        if (!(in_start && in_end))
            return 0;
        double wx = px - q->o[0], wy = py - q->o[1], rho = sqrt(wx * wx + wy * wy), ux, uy;
        if (rho > 0.0) {
            ux = wx / rho;
            uy = wy / rho;
        } else {
            const rs_segment *g = &pc->seg[k];
            double th = g->ang0 + 0.5 * g->sweep;
            ux = cos(th);
            uy = sin(th);
        }
        h->x[0] = q->o[0] + q->rad * ux;
        h->x[1] = q->o[1] + q->rad * uy;
        /* n points to the centre when the sweep is counter-clockwise */
        h->n[0] = -q->sgn * ux;
        h->n[1] = -q->sgn * uy;
        h->dist = q->sgn * (q->rad - rho);
        h->kappa = -q->sgn / q->rad;
        break;
    }
    default: {
        double xi;
        if (!parab_min(q, px, py, in_start, in_end, &xi))
            return 0;
        double d[2] = {q->B[0] + 2.0 * xi * q->C[0], q->B[1] + 2.0 * xi * q->C[1]};
        double sp = sqrt(d[0] * d[0] + d[1] * d[1]);
        h->x[0] = q->o[0] + xi * q->B[0] + xi * xi * q->C[0];
        h->x[1] = q->o[1] + xi * q->B[1] + xi * xi * q->C[1];
        h->n[0] = -d[1] / sp;
        h->n[1] = d[0] / sp;
        h->dist = (px - h->x[0]) * h->n[0] + (py - h->x[1]) * h->n[1];
        /* signed curvature > 0 turning toward n (a pocket); the wall convention is
         * the opposite sign */
        h->kappa = -2.0 * (d[0] * q->C[1] - d[1] * q->C[0]) / (sp * sp * sp);
        break;
    }
    }
    if (pc->sides == 2 && h->dist < 0.0) {
        h->dist = -h->dist;
        h->n[0] = -h->n[0];
        h->n[1] = -h->n[1];
        h->kappa = -h->kappa;
    }
    h->feature = RS_FEATURE(RS_FEAT_FACE, k);
    return 1;
}
