/* Local contact frames {n, t1, t2} by the kind's convention (docs/conventions.md, "Profiles
 * and surfaces"): a kind's closest-feature operation writes the principal frame, and
 * this is the one place that turns it into t1 and t2. */
#include "rigidsurf/surface.h"
#include "rigidsurf/vec.h"

#include <math.h>

void rs_frame_faceted(const double n[3], double t1[3], double t2[3])
{
    /* global x projected on the tangent plane; global z when x is within 0.1 degree of
     * the normal (|n.x| >= cos 0.1 deg) */
    static const double cos_01deg = 0.99999847691328769880;
    double g[3] = {1.0, 0.0, 0.0};
    if (fabs(n[0]) >= cos_01deg) {
        g[0] = 0.0;
        g[2] = 1.0;
    }
    double gn = rs_dot3(g, n);
    double p[3] = {g[0] - gn * n[0], g[1] - gn * n[1], g[2] - gn * n[2]};
    double l = rs_norm3(p);
    t1[0] = p[0] / l;
    t1[1] = p[1] / l;
    t1[2] = p[2] / l;
    rs_cross3(n, t1, t2);
}

void rs_frame_orient(rs_frame_convention conv, rs_contacts *c, int k0, int k1)
{
    switch (conv) {
    case RS_FRAME_TRAVEL: /* the principal frame is the contact frame */
        break;
    case RS_FRAME_GENERATOR: /* t1 = -d2, t2 = d1, curvatures swapped */
        for (int d = 0; d < 3; d++) {
            double *restrict t1 = c->t1[d], *restrict t2 = c->t2[d];
            for (int k = k0; k < k1; k++) {
                const double d1 = t1[k];
                t1[k] = -t2[k];
                t2[k] = d1;
            }
        }
        for (int k = k0; k < k1; k++) {
            const double k1v = c->curv[0][k];
            c->curv[0][k] = c->curv[1][k];
            c->curv[1][k] = k1v;
        }
        break;
    case RS_FRAME_GLOBAL_X: /* the curvatures stay the principal ones */
        for (int k = k0; k < k1; k++) {
            const double n[3] = {c->nrm[0][k], c->nrm[1][k], c->nrm[2][k]};
            double t1[3], t2[3];
            rs_frame_faceted(n, t1, t2);
            for (int d = 0; d < 3; d++) {
                c->t1[d][k] = t1[d];
                c->t2[d][k] = t2[d];
            }
        }
        break;
    }
}
