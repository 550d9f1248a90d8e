/* An engine's own contact models as a force law of the wall (RS_LAW_SETS_FORCE): each live
 * contact of the law's block described as the engines' walls describe a sphere's contact
 * (the frame in 3D, the master point, the velocity of the wall's material there), and the
 * model's force and torque on the particle written back as the law's outputs, with its
 * stress F in the contact's frame, F = s1 n - s2 t1 - s3 t2 (docs/conventions.md). */
#include "wall_impl.h"

#include <string.h>

void rs_wall_force_begin(rs_law_block *b)
{
    const size_t n = (size_t)b->nSlvNod;
    memset(b->stress, 0, (size_t)b->nDir * n * sizeof *b->stress);
    memset(b->force, 0, 3 * n * sizeof *b->force);
    memset(b->torque, 0, 3 * n * sizeof *b->torque);
    double *zero[] = {b->fluxSlv, b->fluxMst, b->sed, b->sfd, b->scd, b->spd, b->svd};
    for (size_t k = 0; k < sizeof zero / sizeof zero[0]; k++)
        memset(zero[k], 0, n * sizeof *zero[k]);
}

int rs_wall_force_contact(const rs_wall *w, const rs_law_block *b, int e, const double *x,
                          rs_force_contact *c)
{
    const int nd = b->nDir, ns = b->nStateVar;
    const double overlap = b->rdisp[(size_t)e * nd];
    if (overlap >= 0.5 * RS_MAXVAL) /* a leaving contact: nothing */
        return 0;
    const int i = b->slvRow[e];
    c->row = i;
    c->overlap = overlap;
    c->radius = b->radius[e];
    c->mass = b->mass[e];
    c->reff = b->reff ? b->reff[e] : b->radius[e];
    c->curv[0] = b->curv ? b->curv[2 * (size_t)e] : 0.0;
    c->curv[1] = b->curv ? b->curv[2 * (size_t)e + 1] : 0.0;
    /* The frame in 3D: a SEGMENTS profile's plane is z = const, t2 = -ez, and its master
     * point lies at the particle's z. */
    const double *L = b->alocaldir + (size_t)e * nd * nd;
    const double *xm = b->coordMst + (size_t)e * nd;
    if (nd == 3) {
        for (int d = 0; d < 3; d++)
            c->n[d] = L[d], c->t1[d] = L[3 + d], c->t2[d] = L[6 + d], c->xm[d] = xm[d];
    } else {
        c->n[0] = L[0], c->n[1] = L[1], c->n[2] = 0.0;
        c->t1[0] = L[2], c->t1[1] = L[3], c->t1[2] = 0.0;
        c->t2[0] = 0.0, c->t2[1] = 0.0, c->t2[2] = -1.0;
        c->xm[0] = xm[0], c->xm[1] = xm[1], c->xm[2] = x[3 * (size_t)i + 2];
    }
    c->vwall[0] = c->vwall[1] = c->vwall[2] = 0.0;
    const rs_motion *m = w->motion;
    if (w->moving)
        rs_motion_velocity_at(m, c->xm, c->vwall);
    if (m->belt[0] != 0.0 || m->belt[1] != 0.0 || m->belt[2] != 0.0) {
        double u[3];
        rs_motion_belt_at(m, c->n, u);
        for (int d = 0; d < 3; d++)
            c->vwall[d] += u[d];
    }
    c->history = ns ? b->statev + (size_t)e * ns : NULL;
    c->type = b->slv_type ? b->slv_type[e] : 1;
    c->wall_type = b->wall_type;
    c->setup = b->setup;
    return 1;
}

void rs_wall_force_result(rs_law_block *b, int e, const rs_force_contact *c,
                          const double F[3], const double T[3])
{
    double *f = b->force + 3 * (size_t)e, *t = b->torque + 3 * (size_t)e;
    for (int d = 0; d < 3; d++)
        f[d] = F[d], t[d] = T[d];
    double st[3];
    wall_force_stress(F, c->n, c->t1, c->t2, st);
    double *s = b->stress + (size_t)e * b->nDir;
    for (int d = 0; d < b->nDir; d++)
        s[d] = st[d];
}
