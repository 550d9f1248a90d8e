/* A LINE face of an extruded profile set up for a query's points (flat_face.h). */
#include "flat_face.h"

int rs_flat_face_init(rs_flat_face *kit, const rs_surface *s, const double F[12], int k)
{
    const rs_pcache *pc = s->impl;
    if (!pc || !pc->ps || (s->kind != RS_SURF_CYLINDER && s->kind != RS_SURF_SEGMENTS) ||
        k < 0 || k >= pc->nseg || pc->ps[k].type != RS_LINE)
        return 0;
    const rs_pseg *q = &pc->ps[k];
    const int j1 = k + 1 == pc->nvert ? 0 : k + 1;
    kit->q = q;
    kit->k = k;
    kit->two = pc->sides == 2;
    kit->drop =
        pc->sides == 1 && (pc->vk[k] == RS_VTX_CONVEX || pc->vk[j1] == RS_VTX_CONVEX);
    kit->bounded = s->kind == RS_SURF_CYLINDER && s->bounded;
    kit->zmin = s->zmin, kit->zmax = s->zmax;
    for (int j = 0; j < 12; j++)
        kit->F[j] = F[j];
    /* the profile's normal (n_x, n_y) = (-t_y, t_x), flipped behind a two-sided face, and
     * its frame mapped as face_at maps them */
    for (int flip = 0; flip < 2; flip++) {
        const double nx = flip ? q->t[1] : -q->t[1], ny = flip ? -q->t[0] : q->t[0];
        for (int j = 0; j < 3; j++) {
            kit->n[flip][j] = nx * F[F_X + j] + ny * F[F_Y + j];
            kit->t1[flip][j] = ny * F[F_X + j] - nx * F[F_Y + j];
        }
    }
    for (int j = 0; j < 3; j++)
        kit->t2[j] = -F[F_Z + j];
    return 1;
}
