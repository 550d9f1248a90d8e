/* A convex body against a MESH, the MESH kind's body operation (rs_surface_ops.body,
 * rs_mesh_body; convex.h, rs_body_surface_contacts; docs/conventions.md, "Convex
 * bodies"): the triangles near the body, each against the body by the pair query
 * rs_convex_triangle; each coplanar region answered by the body's support along its
 * normal where the region holds the foot of the body's deepest point, and each triangle
 * by the Voronoi owner of its pair's witness (mesh_body.c); one contact per owning
 * feature and one per coplanar region. */
#include "convex_internal.h"
#include "mesh.h"
#include "mesh_regions.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A contact found on one triangle, before the merge. */
typedef struct found {
    rs_body_contact c;
    int region; /* a face's coplanar region (rs_mesh_flat_regions), -1 otherwise */
    int exact;  /* a face's contact from the body's support along the face's normal */
} found;

/* The contacts found, at most two per candidate (its region's and its witness's), each
 * made in the next slot and kept there or merged (keep). */
typedef struct found_list {
    found *f;
    int n;
} found_list;

/* Does a take b's place: an exact face contact before a pair query's, then the deeper? */
static int better(const found *a, const found *b)
{
    return a->exact != b->exact ? a->exact > b->exact : a->c.depth > b->c.depth;
}

/* Keeps g, the list's next slot l->f[l->n], merged with the contact of its feature or,
 * for a face, of its coplanar region: the better of the two stays. */
static void keep(found_list *l)
{
    const found *g = l->f + l->n;
    for (int j = 0; j < l->n; j++) {
        found *o = &l->f[j];
        if (o->c.feature == g->c.feature ||
            (g->region >= 0 && o->region >= 0 && o->region == g->region)) {
            if (better(g, o))
                *o = *g;
            return;
        }
    }
    l->n++;
}

/* The pose's maps, nothing where it is NULL (the identity: the reference configuration). */
static void to_local(const rs_pose *p, const double x[3], double X[3])
{
    if (p)
        rs_pose_to_local(p, x, X);
    else
        memcpy(X, x, 3 * sizeof *X);
}

static void to_global(const rs_pose *p, const double X[3], double x[3])
{
    if (p)
        rs_pose_to_global(p, X, x);
    else
        memcpy(x, X, 3 * sizeof *x);
}

static void rotate(const rs_pose *p, const double V[3], double v[3])
{
    if (p)
        rs_pose_rotate(p, V, v);
    else
        memcpy(v, V, 3 * sizeof *v);
}

static void unrotate(const rs_pose *p, const double v[3], double V[3])
{
    if (p)
        rs_pose_unrotate(p, v, V);
    else
        memcpy(V, v, 3 * sizeof *V);
}

/* The box about the body in the reference configuration: the corners of its body-frame
 * bounds, placed and taken back through the pose, widened by gap_max. Without a pose each
 * bound is a sum of one product per axis of the body frame, each term largest (least) at
 * its own corner: rounding is monotone, so the bound is the same number as the largest
 * (least) over the eight corners. R is the body's rotation. */
static void body_box(const rs_body *b, const double R[9], const rs_pose *p, double gap_max,
                     double lo[3], double hi[3])
{
    const double *blo = b->shape->box, *bhi = b->shape->box + 3;
    if (!p) {
        for (int d = 0; d < 3; d++) {
            double tl[3], th[3];
            for (int j = 0; j < 3; j++) { /* (blo <= bhi: the sign picks the end) */
                const double r = R[3 * d + j];
                tl[j] = r * (r >= 0.0 ? blo[j] : bhi[j]);
                th[j] = r * (r >= 0.0 ? bhi[j] : blo[j]);
            }
            lo[d] = tl[0] + tl[1] + tl[2] + b->x[d] - gap_max;
            hi[d] = th[0] + th[1] + th[2] + b->x[d] + gap_max;
        }
        return;
    }
    for (int d = 0; d < 3; d++) {
        lo[d] = INFINITY;
        hi[d] = -INFINITY;
    }
    for (int c = 0; c < 8; c++) {
        const double v[3] = {(c & 1) ? bhi[0] : blo[0], (c & 2) ? bhi[1] : blo[1],
                             (c & 4) ? bhi[2] : blo[2]};
        double w[3], X[3];
        rs_matvec3(R, v, w);
        for (int d = 0; d < 3; d++)
            w[d] += b->x[d];
        to_local(p, w, X);
        for (int d = 0; d < 3; d++) {
            lo[d] = X[d] - gap_max < lo[d] ? X[d] - gap_max : lo[d];
            hi[d] = X[d] + gap_max > hi[d] ? X[d] + gap_max : hi[d];
        }
    }
}

/* A body with its rotation and its last support (one query asks the same direction of
 * each triangle of a coplanar region and of the region): the support is a function of
 * the direction, so a repeated direction takes the last answer. */
typedef struct sbody {
    const rs_body *b;
    const double *R; /* the caller's, or Rm */
    double dir[3], xs[3];
    int have;
    double Rm[9];
} sbody;

static void support(sbody *sb, const double dir[3], double xs[3])
{
    if (!(sb->have && sb->dir[0] == dir[0] && sb->dir[1] == dir[1] &&
          sb->dir[2] == dir[2])) {
        rs_body_support_at(sb->b, sb->R, dir, sb->xs);
        memcpy(sb->dir, dir, sizeof sb->dir);
        sb->have = 1;
    }
    memcpy(xs, sb->xs, sizeof sb->xs);
}

static void set_contact(found *g, int feature, double depth, const double n[3],
                        const double xm[3], const double xs[3], int region, int exact)
{
    for (int d = 0; d < 3; d++)
        g->c.t1[d] = g->c.t2[d] = 0.0;
    g->c.curv[0] = g->c.curv[1] = 0.0;
    g->c.iterations = 0;
    g->c.feature = feature;
    g->c.depth = depth;
    memcpy(g->c.normal, n, sizeof g->c.normal);
    memcpy(g->c.xm, xm, sizeof g->c.xm);
    memcpy(g->c.xs, xs, sizeof g->c.xs); /* t1, t2 follow from n (FACETED); curvatures 0 */
    g->region = region;
    g->exact = exact;
}

/* A candidate triangle in the world (its first node, its normal; its other nodes where
 * the pair query asks them), its coplanar region and the pair query's answer; of a plain
 * one, the body's centre's height h over its plane, the plane's normal ns toward the body
 * and the foot of the pair's witness in the reference configuration F. */
typedef struct cand {
    int t, face, region;
    int reach; /* the body within gap_max of the triangle (-1: a plain one not yet asked) */
    int plain; /* the body meets it at its face only: its plane answers for it */
    double tri[9], nf[3];
    double h, ns[3], F[3];
    rs_convex_contact cc;
} cand;

/* A candidate's place in its region's run: sorted by region, then by candidate. */
typedef struct member {
    int region, k;
} member;

/* Bytes a candidate takes in a query's work block: its record, two found contacts, its
 * place, its region label and the regions' scratch (candidates' ids apart). The first
 * WORK_SMALL candidates of a query need no heap. */
#define WORK_BYTES (sizeof(cand) + 2 * sizeof(found) + sizeof(member) + 3 * sizeof(int))
enum { WORK_SMALL = 32 };

static int cmp_member(const void *pa, const void *pb)
{
    const member *a = pa, *b = pb;
    if (a->region != b->region)
        return (a->region > b->region) - (a->region < b->region);
    return (a->k > b->k) - (a->k < b->k);
}

/* The cosine of the largest angle between the pair's normal on a triangle of a region
 * and the region's normal for which the region may answer a body whose centre lies
 * beyond it. */
#define RS_BODY_FACE_COS 0.5

/* The body's deepest point xs along -n below the plane through a0 with unit normal n
 * (toward the body): its depth (a0 - xs).n, its foot on the plane, and the foot in the
 * mesh's reference configuration F. */
static double deepest_along(sbody *b, const rs_pose *p, const double n[3],
                            const double a0[3], double xs[3], double foot[3], double F[3])
{
    const double down[3] = {-n[0], -n[1], -n[2]};
    support(b, down, xs);
    const double depth =
        (a0[0] - xs[0]) * n[0] + (a0[1] - xs[1]) * n[1] + (a0[2] - xs[2]) * n[2];
    for (int d = 0; d < 3; d++)
        foot[d] = xs[d] + depth * n[d];
    to_local(p, foot, F);
    return depth;
}

/* The pair of body b and candidate ck's plane, as the pair query answers a flat contact:
 * the body's deepest point along the plane's normal (on the side of its centre; the front
 * of a one-sided mesh), its depth, the normal from the body toward the plane; apart when
 * the foot of that point lies off the triangle (the body meets the plane elsewhere: its
 * own triangle answers there). */
static void plane_pair(const rs_surface *s, const rs_pose *p, sbody *sb, cand *ck,
                       double gap_max)
{
    const rs_body *b = sb->b;
    const double *a0 = ck->tri, *nf = ck->nf;
    const double h =
        (b->x[0] - a0[0]) * nf[0] + (b->x[1] - a0[1]) * nf[1] + (b->x[2] - a0[2]) * nf[2];
    const double side = s->sides != 2 || h >= 0.0 ? 1.0 : -1.0;
    double *ns = ck->ns, *F = ck->F;
    ck->h = h;
    ns[0] = side * nf[0], ns[1] = side * nf[1], ns[2] = side * nf[2];
    const double down[3] = {-ns[0], -ns[1], -ns[2]};
    rs_convex_contact *cc = &ck->cc;
    support(sb, down, cc->pa);
    cc->depth = (a0[0] - cc->pa[0]) * ns[0] + (a0[1] - cc->pa[1]) * ns[1] +
                (a0[2] - cc->pa[2]) * ns[2];
    for (int d = 0; d < 3; d++) {
        cc->normal[d] = down[d];
        cc->pb[d] = cc->pa[d] + cc->depth * ns[d];
    }
    to_local(p, cc->pb, F);
    cc->state = !tri_holds(s->impl, ck->t, F) ? RS_CONVEX_APART
                : cc->depth > 0.0             ? RS_CONVEX_OVERLAP
                : -cc->depth <= gap_max       ? RS_CONVEX_NEAR
                                              : RS_CONVEX_APART;
    ck->reach = cc->state != RS_CONVEX_APART && cc->depth >= -gap_max;
}

/* The candidate of the region (candidates ru[0 .. nr)) whose triangle holds the reference
 * point X, the least face where several do (X on their borders; of one face, a candidate
 * of it); -1 for none. k0: a candidate known to hold X, or -1. */
static int region_holds(const rs_surface *s, const cand *c, const member *ru, int nr,
                        const double X[3], int k0)
{
    const rs_mesh *m = s->impl;
    int k = k0;
    for (int i = 0; i < nr; i++)
        if ((k < 0 || c[ru[i].k].face < c[k].face) && tri_holds(m, c[ru[i].k].t, X))
            k = ru[i].k;
    return k;
}

/* The contact of a coplanar region (candidates ru[0 .. nr)), if any: the body's deepest
 * point along the region's normal (on the side of the body's centre; the front of a
 * one-sided mesh, whose faces take a body pushed through from behind as a
 * penetration), when the foot of it lies on a triangle of the region, and so does the
 * foot of the body's centre or the pair's normal on one of its triangles is within 60
 * degrees of the region's (else a body beside the region, reaching across its plane
 * beyond a convex edge, would take the plane for a face). Its feature is the face under
 * the foot of the body's centre where the region holds it (a face's corners tie as the
 * deepest point; the centre's foot moves with the body), else under the deepest
 * point's. */
static int region_face(const rs_surface *s, const rs_pose *p, sbody *sb, double gap_max,
                       cand *c, const member *ru, int nr, found *g)
{
    const rs_body *b = sb->b;
    int best = -1;
    double ba = -1.0;
    for (int i = 0; i < nr; i++) {
        cand *ci = c + ru[i].k;
        /* a plain triangle's pair normal is its own normal (either way), so it is asked
         * only where its normal is nearer the region's than the best's so far */
        const double along =
            ci->plain ? rs_dot3(ci->nf, ci->nf) : fabs(rs_dot3(ci->cc.normal, ci->nf));
        if (!(along > ba))
            continue;
        if (ci->reach < 0)
            plane_pair(s, p, sb, ci, gap_max);
        if (ci->reach)
            best = ru[i].k, ba = along;
    }
    if (best < 0)
        return 0;
    const cand *cb = c + best;
    const double *a0 = cb->tri, *nf = cb->nf;
    double h, ns[3], xs[3], foot[3], F[3], depth;
    if (cb->plain) { /* plane_pair's answer is the same: its plane, along the same ns */
        h = cb->h, depth = cb->cc.depth;
        for (int d = 0; d < 3; d++)
            ns[d] = cb->ns[d], xs[d] = cb->cc.pa[d], foot[d] = cb->cc.pb[d],
            F[d] = cb->F[d];
    } else {
        h = (b->x[0] - a0[0]) * nf[0] + (b->x[1] - a0[1]) * nf[1] +
            (b->x[2] - a0[2]) * nf[2];
        const double side = s->sides != 2 || h >= 0.0 ? 1.0 : -1.0;
        for (int d = 0; d < 3; d++)
            ns[d] = side * nf[d];
        depth = deepest_along(sb, p, ns, a0, xs, foot, F);
    }
    if (!(depth >= -gap_max))
        return 0;
    /* (a plain triangle's reach: its triangle holds F) */
    int k = region_holds(s, c, ru, nr, F, cb->plain ? best : -1);
    if (k < 0)
        return 0;
    double xc[3], C[3];
    for (int d = 0; d < 3; d++)
        xc[d] = b->x[d] - h * nf[d];
    to_local(p, xc, C);
    const int kc = region_holds(s, c, ru, nr, C, -1);
    if (kc < 0 && ba < RS_BODY_FACE_COS)
        return 0;
    if (kc >= 0)
        k = kc;
    set_contact(g, c[k].face, depth, ns, foot, xs, c[k].region, 1);
    return 1;
}

/* How far outside the body, relative to the overlap's depth, an overlap's witness on the
 * mesh may lie (the pair query's rounding): it lies depth inside a face of the body
 * pressed on an edge. */
#define RS_BODY_HOLD_REL 0.1

/* How much shallower than the body's deepest point along a face's normal the pair's
 * witness may be and still be one of the deepest (a flat side of the body on the face),
 * relative to the body's reach. */
#define RS_BODY_TIE_REL 1e-9

/* Is candidate k's face, whose pair's witness is not the body's deepest point along its
 * normal n, one that the body meets only across a concave fold: the foot of the body's
 * deepest point lies beyond a CONCAVE edge of the face's region? A sphere there has no
 * contact with the face until its centre crosses the fold (docs/conventions.md, "Shares
 * at concave folds"); nor has a body until its deepest point does, when region_face
 * answers for the face. */
static int over_a_fold(const rs_surface *s, const rs_pose *p, sbody *b, const cand *c,
                       int nc, int k, const double n[3])
{
    const cand *ck = c + k;
    double xs[3], foot[3], F[3];
    const double depth = deepest_along(b, p, n, ck->tri, xs, foot, F);
    if (!(depth > ck->cc.depth + RS_BODY_TIE_REL * rs_body_reach(b->b)))
        return 0;
    int beyond = 0;
    for (int j = 0; j < nc; j++) {
        if (c[j].region != ck->region)
            continue;
        if (rs_mesh_triangle_holds(s, c[j].t, F))
            return 0;
        beyond |= rs_mesh_beyond_concave(s, c[j].t, F);
    }
    return beyond;
}

/* The contact of candidate k from the pair's witness on its triangle, owned by the
 * feature whose cone holds the pair's normal there, if any. */
static int witness_contact(const rs_surface *s, const rs_pose *p, sbody *sb, const cand *c,
                           int nc, int k, found *g)
{
    const rs_body *b = sb->b;
    const cand *ck = c + k;
    const rs_convex_contact *cc = &ck->cc;
    /* an overlap's witness on the mesh lies in the body (the pair's way out through a far
     * border of the triangle leaves it outside: no contact of the mesh's there) */
    if (cc->depth > 0.0 && !rs_body_holds(b, cc->pb, RS_BODY_HOLD_REL * cc->depth))
        return 0;
    const double nm[3] = {-cc->normal[0], -cc->normal[1], -cc->normal[2]};
    double P[3], N[3];
    int ft;
    to_local(p, cc->pb, P);
    unrotate(p, nm, N);
    const int f = rs_mesh_direction_owner(s, ck->t, P, N, &ft);
    if (f == RS_FEATURE_NONE)
        return 0;
    if (ft != ck->t) { /* an edge, a vertex, or the other face of an edge (normal nm) */
        int region = -1;
        for (int j = 0; ft >= 0 && j < nc; j++)
            if (c[j].t == ft)
                region = c[j].region;
        set_contact(g, f, cc->depth, nm, cc->pb, cc->pa, region, 0);
        return 1;
    }
    const double along = rs_dot3(nm, ck->nf);
    if (s->sides != 2 && along < 0.0)
        return 0; /* behind a one-sided face, along no face's normal */
    const double sg = along < 0.0 ? -1.0 : 1.0;
    const double n[3] = {sg * ck->nf[0], sg * ck->nf[1], sg * ck->nf[2]};
    if (over_a_fold(s, p, sb, c, nc, k, n))
        return 0;
    set_contact(g, f, cc->depth, n, cc->pb, cc->pa, ck->region, 0);
    return 1;
}

/* One body's contacts (rs_mesh_body), its rotation R (NULL: made here), the pose as
 * pose_moved gives it, the mesh's data there (rs_mesh_body_run checks). */
static int body_contacts(const rs_surface *s, const rs_pose *pose, const rs_body *b,
                         const double *R, double gap_max, rs_body_contacts *out,
                         rs_error *err)
{
    int rc = RS_OK;
    sbody sb;
    sb.b = b;
    sb.have = 0;
    if (R) {
        sb.R = R;
    } else {
        rs_body_rotation(b, sb.Rm);
        sb.R = sb.Rm;
    }
    double lo[3], hi[3];
    body_box(b, sb.R, pose, gap_max, lo, hi);
    /* the candidates' arrays in one block: on the stack for a few, else the heap */
    int small_ids[WORK_SMALL];
    _Alignas(64) unsigned char small[WORK_SMALL * WORK_BYTES];
    int nt = rs_mesh_box_candidates(s, lo, hi, small_ids, WORK_SMALL);
    if (nt < 0)
        return rs_error_set(err, RS_ERR_NOMEM, "body contacts: out of memory in the tree");
    void *heap = NULL;
    int *ids = small_ids;
    unsigned char *w = small;
    if (nt > WORK_SMALL) {
        heap = malloc((size_t)nt * (WORK_BYTES + sizeof(int)));
        if (!heap)
            return rs_error_set(err, RS_ERR_NOMEM,
                                "body contacts: out of memory for %d "
                                "triangles",
                                nt);
        w = heap;
        ids = (int *)(w + (size_t)nt * WORK_BYTES);
        nt = rs_mesh_box_candidates(s, lo, hi, ids, nt);
    }
    cand *c = (cand *)w;
    found_list l = {(found *)(c + nt), 0};
    member *ru = (member *)(l.f + 2 * nt);
    int *label = (int *)(ru + nt), *scratch = label + nt;
    rs_mesh_flat_regions(s, ids, nt, label, scratch);
    double C[3]; /* the body's centre in the reference configuration */
    to_local(pose, b->x, C);
    const double near = rs_body_reach(b) + gap_max;
    const rs_mesh *m = s->impl;
    for (int k = 0; k < nt; k++) {
        cand *ck = c + k;
        const rs_mtri *rec = m->rec + ids[k];
        ck->t = ids[k];
        ck->region = label[k];
        ck->face = RS_FEATURE(RS_FEAT_FACE, rec->el);
        to_global(pose, rec->a0, ck->tri);
        rotate(pose, rec->n, ck->nf);
        /* a triangle the body meets at its face only: the pair's answer would be its
         * plane's (a flat contact, its witness owned by the face), which its region's
         * closed form gives; no pair query */
        ck->plain = rs_mesh_triangle_plain(s, ck->t, C, near);
        if (ck->plain) {
            ck->reach = -1; /* its plane, where its region asks it (region_face) */
        } else {
            for (int i = 1; i < 3; i++)
                to_global(pose, m->xyz + 3 * rec->v[i], ck->tri + 3 * i);
            if ((rc = rs_convex_triangle(b, ck->tri, gap_max, &ck->cc, err)) != RS_OK)
                goto done;
            ck->reach = ck->cc.state != RS_CONVEX_APART && ck->cc.depth >= -gap_max;
        }
        ru[k].region = label[k];
        ru[k].k = k;
    }
    /* each coplanar region by the body's support, then each triangle by its witness */
    for (int i = 1; i < nt; i++) /* few: by insertion */
        for (int j = i; j > 0 && cmp_member(ru + j - 1, ru + j) > 0; j--) {
            const member t = ru[j];
            ru[j] = ru[j - 1];
            ru[j - 1] = t;
        }
    for (int i = 0, j; i < nt; i = j) {
        for (j = i + 1; j < nt && ru[j].region == ru[i].region;)
            j++;
        if (region_face(s, pose, &sb, gap_max, c, ru + i, j - i, l.f + l.n))
            keep(&l);
    }
    for (int k = 0; k < nt; k++) {
        if (c[k].reach && !c[k].plain && witness_contact(s, pose, &sb, c, nt, k, l.f + l.n))
            keep(&l);
    }
    for (int k = 0; k < l.n && rc == RS_OK; k++)
        rc = rs_body_contacts_push(out, &l.f[k].c, err);
done:
    free(heap);
    return rc;
}

int rs_mesh_body(const rs_surface *s, const rs_pose *pose, const rs_body *b, int n,
                 double gap_max, int lenient, rs_body_contacts *out, rs_error *err)
{
    return rs_mesh_body_run(s, pose, b, NULL, n, gap_max, lenient, out, NULL, err);
}

int rs_mesh_body_run(const rs_surface *s, const rs_pose *pose, const rs_body *b,
                     const double *R, int n, double gap_max, int lenient,
                     rs_body_contacts *out, struct rs_body_work *w, rs_error *err)
{
    (void)lenient, (void)w; /* no fixed point to settle, no work kept */
    if (!s->impl)
        return rs_error_set(err, RS_ERR_ARG, "body contacts: mesh '%s' has no data",
                            s->name);
    pose = pose_moved(pose);
    int rc = RS_OK;
    for (int i = 0; i < n && rc == RS_OK; i++)
        rc = body_contacts(s, pose, b + i, R ? R + 9 * i : NULL, gap_max, out + i, err);
    return rc;
}
