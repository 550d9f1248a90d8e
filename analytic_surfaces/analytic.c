/* The analytic kinds SEGMENTS, CYLINDER and REVOLUTION as surface kinds: their tables of
 * operations, feature adjacency for history hand-over, bounds, spin axis and lifetime.
 * The closest features are in query.c and closest.c, the display triangulation in
 * triangulate.c. */
#include "convex_internal.h"
#include "profile.h"
#include "surface_file.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* History may pass between features whose contact normal is continuous at the
 * junction: two segments across a SMOOTH vertex, and a segment and its own vertex (a
 * vertex contact starts with the normal of the segment it leaves: END and CONVEX in
 * front, CONCAVE behind or from the back side). */
static int analytic_adjacent(const rs_surface *s, int fa, int fb)
{
    if (fa == fb)
        return 1;
    if (fa >= 0 && fb >= 0 && RS_FEATURE_SECTOR(fa) != RS_FEATURE_SECTOR(fb))
        return 0; /* ring sectors of a REVOLUTION hand over within their sector */
    fa = fa < 0 ? fa : RS_FEATURE_BASE(fa);
    fb = fb < 0 ? fb : RS_FEATURE_BASE(fb);
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

/* Bounding box of the profile in its plane, from the segments' boxes in the query data
 * (arcs and parabolas included, grown by the query's tolerance). */
static void profile_box(const rs_surface *s, double box[4])
{
    const rs_pcache *pc = s->impl;
    box[0] = box[2] = INFINITY;
    box[1] = box[3] = -INFINITY;
    if (pc)
        memcpy(box, pc->box, 4 * sizeof(double));
}

static void analytic_bounds(const rs_surface *s, double lo[3], double hi[3])
{
    double box[4];
    profile_box(s, box);
    if (s->kind == RS_SURF_REVOLUTION) {
        /* the discs of radius rmax about the axis at both ends of the profile's z range:
         * along global axis d a disc reaches rmax sqrt(1 - ez_d^2) */
        const double rmax = fmax(box[1], 0.0);
        for (int d = 0; d < 3; d++) {
            const double reach = rmax * sqrt(fmax(0.0, 1.0 - s->ez[d] * s->ez[d]));
            const double z0 = s->a[d] + box[2] * s->ez[d], z1 = s->a[d] + box[3] * s->ez[d];
            lo[d] = fmin(z0, z1) - reach;
            hi[d] = fmax(z0, z1) + reach;
        }
        return;
    }
    /* SEGMENTS and CYLINDER: the corners of the local box; along the generator the
     * extent, or unbounded */
    const int gen_bounded = s->kind == RS_SURF_CYLINDER && s->bounded;
    const double zr[2] = {gen_bounded ? s->zmin : 0.0, gen_bounded ? s->zmax : 0.0};
    for (int d = 0; d < 3; d++) {
        lo[d] = INFINITY;
        hi[d] = -INFINITY;
        for (int c = 0; c < 8; c++) {
            const double u = box[c & 1], v = box[2 + ((c >> 1) & 1)], w = zr[(c >> 2) & 1];
            const double x = s->a[d] + u * s->ex[d] + v * s->ey[d] + w * s->ez[d];
            lo[d] = fmin(lo[d], x);
            hi[d] = fmax(hi[d], x);
        }
        if (!gen_bounded && s->ez[d] != 0.0) {
            lo[d] = -INFINITY;
            hi[d] = INFINITY;
        }
    }
}

static int analytic_spin_axis(const rs_surface *s, double origin[3], double axis[3])
{
    if (s->kind != RS_SURF_REVOLUTION)
        return 0;
    for (int d = 0; d < 3; d++) {
        origin[d] = s->a[d];
        axis[d] = s->ez[d];
    }
    return 1;
}

void rs_analytic_free(rs_surface *s)
{
    free(s->impl); /* the query data, one block */
    free(s->profile.seg);
    free(s->profile.vkind);
    s->impl = NULL;
    s->profile.seg = NULL;
    s->profile.vkind = NULL;
}

/* The analytic kinds search their profile at every query and have no facets: of the
 * optional operations, only an extruded profile's closed form of a point on a flat face
 * (feature_point, analytic_body.c). A convex body meets them through the fixed point over
 * their point query (src/convex_geometry/body_fixed_point.c), its iterates on an extruded
 * profile's flat faces in closed form (analytic_body.c). */
#define ANALYTIC_OPS(kind, nd, conv, sx, fp)                                               \
    {                                                                                      \
        .name = kind, .ndir = nd, .frame = conv, .closest = rs_analytic_closest,           \
        .adjacent = analytic_adjacent, .bounds = analytic_bounds,                          \
        .spin_axis = analytic_spin_axis, .triangulate = rs_analytic_triangulate,           \
        .free = rs_analytic_free, .syntax = sx, .body = rs_analytic_body,                  \
        .body_run = rs_analytic_body_run, .feature_point = fp                              \
    }
static const rs_surface_ops segments_ops = ANALYTIC_OPS(
    "SEGMENTS", 2, RS_FRAME_TRAVEL, &rs_segments_syntax, rs_analytic_feature_point);
static const rs_surface_ops cylinder_ops = ANALYTIC_OPS(
    "CYLINDER", 3, RS_FRAME_GENERATOR, &rs_cylinder_syntax, rs_analytic_feature_point);
static const rs_surface_ops revolution_ops =
    ANALYTIC_OPS("REVOLUTION", 3, RS_FRAME_TRAVEL, &rs_revolution_syntax, NULL);

const rs_surface_ops *rs_analytic_ops(rs_surface_kind kind)
{
    switch (kind) {
    case RS_SURF_SEGMENTS:
        return &segments_ops;
    case RS_SURF_CYLINDER:
        return &cylinder_ops;
    case RS_SURF_REVOLUTION:
        return &revolution_ops;
    default:
        return NULL;
    }
}
