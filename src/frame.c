/* Local contact frames {n, t1, t2} by the kind's convention (docs/conventions.md, "Profiles
 * and surfaces"): a kind's closest-feature operation writes the principal frame, and
 * this is the one place that turns it into t1 and t2. */
#include "rigidsurf/surface.h"
#include "rigidsurf/vec.h"
#include "rs_compiler.h"

#include <math.h>

/* The FACETED t1 and t2 of unit normal (nx, ny, nz): global x projected on the tangent
 * plane, global z when x is within 0.1 degree of the normal (|n.x| >= cos 0.1 deg); t2 =
 * n x t1. Branch-free, so that rs_frame_orient's loop vectorizes. */
#define RS_COS_01DEG 0.99999847691328769880
RS_INLINE void faceted(double nx, double ny, double nz, double t1[3], double t2[3])
{
    const int z = fabs(nx) >= RS_COS_01DEG;
    const double gx = z ? 0.0 : 1.0, gz = z ? 1.0 : 0.0;
    const double gn = gx * nx + 0.0 * ny + gz * nz;
    const double px = gx - gn * nx, py = 0.0 - gn * ny, pz = gz - gn * nz;
    const double l = sqrt(px * px + py * py + pz * pz);
    t1[0] = px / l;
    t1[1] = py / l;
    t1[2] = pz / l;
    t2[0] = ny * t1[2] - nz * t1[1];
    t2[1] = nz * t1[0] - nx * t1[2];
    t2[2] = nx * t1[1] - ny * t1[0];
}

void rs_frame_faceted(const double n[3], double t1[3], double t2[3])
{
    faceted(n[0], n[1], n[2], t1, t2);
}

void rs_frame_orient_one(rs_frame_convention conv, const double n[3], double t1[3],
                         double t2[3], double curv[2])
{
    switch (conv) {
    case RS_FRAME_TRAVEL:
        break;
    case RS_FRAME_GENERATOR: { /* t1 = -d2, t2 = d1, curvatures swapped */
        for (int d = 0; d < 3; d++) {
            const double d1 = t1[d];
            t1[d] = -t2[d];
            t2[d] = d1;
        }
        const double k1 = curv[0];
        curv[0] = curv[1];
        curv[1] = k1;
        break;
    }
    case RS_FRAME_GLOBAL_X:
        faceted(n[0], n[1], n[2], t1, t2);
        break;
    }
}

/* faceted for n contacts: t1 = (a0, a1, a2), t2 = (b0, b1, b2) of n = (n0, n1, n2). */
RS_INLINE void faceted_block(int n, const double *restrict n0, const double *restrict n1,
                             const double *restrict n2, double *restrict a0,
                             double *restrict a1, double *restrict a2, double *restrict b0,
                             double *restrict b1, double *restrict b2)
{
    for (int k = 0; k < n; k++) {
        double t1[3], t2[3];
        faceted(n0[k], n1[k], n2[k], t1, t2);
        a0[k] = t1[0], a1[k] = t1[1], a2[k] = t1[2];
        b0[k] = t2[0], b1[k] = t2[1], b2[k] = t2[2];
    }
}

RS_MULTIVERSION
void rs_frame_orient(rs_frame_convention conv, rs_contacts *c, int k0, int k1)
{
    if (k1 <= k0) /* nothing to turn; a list never grown has no arrays */
        return;
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
        for (int k = k0; c->curv[0] && k < k1; k++) {
            const double k1v = c->curv[0][k];
            c->curv[0][k] = c->curv[1][k];
            c->curv[1][k] = k1v;
        }
        break;
    case RS_FRAME_GLOBAL_X: /* the curvatures stay the principal ones */
        faceted_block(k1 - k0, c->nrm[0] + k0, c->nrm[1] + k0, c->nrm[2] + k0,
                      c->t1[0] + k0, c->t1[1] + k0, c->t1[2] + k0, c->t2[0] + k0,
                      c->t2[1] + k0, c->t2[2] + k0);
        break;
    }
}
