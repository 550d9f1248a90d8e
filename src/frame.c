/* Local contact frames {n, t1, t2} by surface kind (ARCHITECTURE.md, "Profiles and
 * surfaces"), feature adjacency for history hand-over, contact lists and surface
 * lifetime. */
#include "rigidsurf/surface.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void rs_frame_segments(const double n[3], double t1[3], double t2[3])
{
    /* t1 = (0,0,-1) x n, which is the travel direction for n in the x-y plane */
    t1[0] = n[1];
    t1[1] = -n[0];
    t1[2] = 0.0;
    t2[0] = 0.0;
    t2[1] = 0.0;
    t2[2] = -1.0;
}

void rs_frame_cylinder(const double n[3], const double gen[3], double t1[3], double t2[3])
{
    t1[0] = gen[0];
    t1[1] = gen[1];
    t1[2] = gen[2];
    rs_cross3(n, gen, t2);
}

void rs_frame_revolution(const double n[3], const double hoop[3], double t1[3],
                         double t2[3])
{
    t2[0] = hoop[0];
    t2[1] = hoop[1];
    t2[2] = hoop[2];
    rs_cross3(hoop, n, t1);
}

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
    double gn = g[0] * n[0] + g[1] * n[1] + g[2] * n[2];
    double p[3] = {g[0] - gn * n[0], g[1] - gn * n[1], g[2] - gn * n[2]};
    double l = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    t1[0] = p[0] / l;
    t1[1] = p[1] / l;
    t1[2] = p[2] / l;
    rs_cross3(n, t1, t2);
}

int rs_surface_ndir(const rs_surface *s)
{
    return s->kind == RS_SURF_SEGMENTS ? 2 : 3;
}

/* History may pass between features whose contact normal is continuous at the
 * junction: two segments across a SMOOTH vertex, and a segment and its own vertex (a
 * vertex contact starts with the normal of the segment it leaves: END and CONVEX in
 * front, CONCAVE behind or from the back side). */
int rs_surface_adjacent(const rs_surface *s, int fa, int fb)
{
    if (s->klass)
        return s->klass->adjacent ? s->klass->adjacent(s, fa, fb) : 0;
    if (fa == fb)
        return 1;
    const rs_profile *p = &s->profile;
    int n = p->nseg, nv = p->nvert;
    if (n < 1 || !p->vkind || fa < 0 || fb < 0)
        return 0;
    int ta = RS_FEATURE_TYPE(fa), tb = RS_FEATURE_TYPE(fb);
    int ia = RS_FEATURE_INDEX(fa), ib = RS_FEATURE_INDEX(fb);
    if (ta == RS_FEAT_FACE && tb == RS_FEAT_FACE) {
        if (ia >= n || ib >= n)
            return 0;
        /* the vertex between them: the start of the later one */
        int j = -1;
        if (ib == ia + 1 || (p->closed && ia == n - 1 && ib == 0))
            j = ib;
        else if (ia == ib + 1 || (p->closed && ib == n - 1 && ia == 0))
            j = ia;
        if (n == 2 && p->closed)
            return p->vkind[0] == RS_VTX_SMOOTH || p->vkind[1] == RS_VTX_SMOOTH;
        return j >= 0 && p->vkind[j] == RS_VTX_SMOOTH;
    }
    if (ta == RS_FEAT_VERTEX && tb == RS_FEAT_FACE) {
        int t = ia;
        ia = ib;
        ib = t;
        ta = RS_FEAT_FACE;
        tb = RS_FEAT_VERTEX;
    }
    if (ta == RS_FEAT_FACE && tb == RS_FEAT_VERTEX) {
        if (ia >= n || ib >= nv)
            return 0;
        int jend = ia + 1 == nv ? 0 : ia + 1;
        if (ib != ia && ib != jend)
            return 0;
        return p->vkind[ib] != RS_VTX_SMOOTH;
    }
    return 0;
}

int rs_contacts_reserve(rs_contacts *c, int cap, rs_error *err)
{
    if (cap < 1)
        cap = 1;
    if (cap <= c->cap)
        return RS_OK;
    size_t nd = (size_t)cap * sizeof(double), ni = (size_t)cap * sizeof(int);
    size_t keep_d = (size_t)c->n * sizeof(double), keep_i = (size_t)c->n * sizeof(int);
    double **dv[15] = {&c->xm[0],  &c->xm[1], &c->xm[2], &c->nrm[0],  &c->nrm[1],
                       &c->nrm[2], &c->t1[0], &c->t1[1], &c->t1[2],   &c->t2[0],
                       &c->t2[1],  &c->t2[2], &c->dist,  &c->curv[0], &c->curv[1]};
    double *nd_[15] = {0};
    int *np = malloc(ni), *nf = malloc(ni);
    int ok = np && nf;
    for (int i = 0; i < 15 && ok; i++)
        ok = (nd_[i] = malloc(nd)) != NULL;
    if (!ok) {
        free(np);
        free(nf);
        for (int i = 0; i < 15; i++)
            free(nd_[i]);
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory for %d contacts", cap);
    }
    if (c->n > 0) {
        memcpy(np, c->point, keep_i);
        memcpy(nf, c->feature, keep_i);
        for (int i = 0; i < 15; i++)
            memcpy(nd_[i], *dv[i], keep_d);
    }
    free(c->point);
    free(c->feature);
    c->point = np;
    c->feature = nf;
    for (int i = 0; i < 15; i++) {
        free(*dv[i]);
        *dv[i] = nd_[i];
    }
    c->cap = cap;
    return RS_OK;
}

void rs_contacts_free(rs_contacts *c)
{
    free(c->point);
    free(c->feature);
    for (int d = 0; d < 3; d++) {
        free(c->xm[d]);
        free(c->nrm[d]);
        free(c->t1[d]);
        free(c->t2[d]);
    }
    free(c->dist);
    free(c->curv[0]);
    free(c->curv[1]);
    memset(c, 0, sizeof *c);
}

void rs_surface_free(rs_surface *s)
{
    if (!s)
        return;
    if (s->klass) {
        if (s->klass->destroy)
            s->klass->destroy(s);
    } else {
        free(s->impl); /* the analytic query data, one block */
    }
    free(s->profile.seg);
    free(s->profile.vkind);
    memset(s, 0, sizeof *s);
}
