/* A convex body as a slave of the contact core (rs_body_manifold, which rs_body_query
 * orients): per owning feature of the kind's body operation, its contact manifold: the
 * body's deepest point and the points of its core that can rest on the feature (a box's
 * corners, a cylinder's rims, a capsule's ends), each a contact of its own, as each slave
 * node of a face is in an Abaqus node-to-surface contact (docs/conventions.md, "Convex
 * bodies"). Each point is measured by the kind's own sphere query (closest). */
#include "convex_internal.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { CAND_MAX = 1 + RS_MANIFOLD_IDS };

/* A candidate: body-frame core point, its id (1 .. RS_MANIFOLD_IDS - 1). */
typedef struct cand {
    double p[3];
    int id;
} cand;

/* The core points of b's shape that can touch a wall under it: d is the body-frame
 * direction into the wall (unit). Smooth shapes have none (their deepest point is their
 * only one). A polyhedron gives its cap vertices lowest along d; its vertex i has id
 * 1 + i mod (RS_MANIFOLD_IDS - 1). */
static int core_points(const rs_shape *s, const double d[3], cand *c, int cap)
{
    const double *h = s->dim;
    int n = 0;
    switch (s->kind) {
    case RS_SHAPE_BOX:
        for (int v = 0; v < 8 && n < cap; v++, n++) {
            c[n].p[0] = (v & 1) ? h[0] : -h[0];
            c[n].p[1] = (v & 2) ? h[1] : -h[1];
            c[n].p[2] = (v & 4) ? h[2] : -h[2];
            c[n].id = 1 + v;
        }
        break;
    case RS_SHAPE_POLYHEDRON: {
        /* the cap vertices farthest along d (into the wall), farthest first */
        int idx[RS_HULL_FARTHEST_MAX];
        n = rs_hull_farthest(s, d, cap < RS_HULL_FARTHEST_MAX ? cap : RS_HULL_FARTHEST_MAX,
                             idx);
        for (int k = 0; k < n; k++) {
            memcpy(c[k].p, s->verts + 3 * idx[k], sizeof c[k].p);
            c[k].id = 1 + idx[k] % (RS_MANIFOLD_IDS - 1);
        }
        break;
    }
    case RS_SHAPE_CYLINDER:
    case RS_SHAPE_CONE: {
        /* four rim points from the rim's lowest (the generator under the wall) in
         * quarter turns; a cone's apex; a cylinder's two rims */
        const double rho = hypot(d[0], d[1]);
        const double c0 = rho > 0.0 ? d[0] / rho : 1.0, s0 = rho > 0.0 ? d[1] / rho : 0.0;
        const int cyl = s->kind == RS_SHAPE_CYLINDER;
        for (int e = 0; e < (cyl ? 2 : 1); e++) {
            const double z = cyl ? (e ? -h[1] : h[1]) : -0.25 * h[1] - s->shift[2];
            for (int k = 0; k < 4 && n < cap; k++, n++) {
                const double ck = k == 0 ? c0 : k == 1 ? -s0 : k == 2 ? -c0 : s0;
                const double sk = k == 0 ? s0 : k == 1 ? c0 : k == 2 ? -s0 : -c0;
                c[n].p[0] = h[0] * ck;
                c[n].p[1] = h[0] * sk;
                c[n].p[2] = z;
                c[n].id = 1 + 4 * e + k;
            }
        }
        if (!cyl && n < cap) {
            c[n].p[0] = c[n].p[1] = 0.0;
            c[n].p[2] = 0.75 * h[1] - s->shift[2];
            c[n].id = 5;
            n++;
        }
        break;
    }
    case RS_SHAPE_CAPSULE:
        for (int e = 0; e < 2 && n < cap; e++, n++) {
            c[n].p[0] = c[n].p[1] = 0.0;
            c[n].p[2] = e ? -h[1] : h[1];
            c[n].id = 1 + e;
        }
        break;
    default: /* sphere, ellipsoid, user shape: smooth or unknown, the deepest point */
        break;
    }
    return n;
}

/* Does the shape have core points (core_points gives some)? */
static int core_points_of(const rs_shape *s)
{
    return s->kind == RS_SHAPE_BOX || s->kind == RS_SHAPE_POLYHEDRON ||
           s->kind == RS_SHAPE_CYLINDER || s->kind == RS_SHAPE_CONE ||
           s->kind == RS_SHAPE_CAPSULE;
}

/* One manifold point, before it is appended. */
typedef struct mpoint {
    int id;
    double depth, xs[3], xm[3], n[3], t1[3], t2[3], curv[2];
} mpoint;

static int append(rs_contacts *c, int point, double radius, int feature, const mpoint *m,
                  rs_error *err)
{
    if (c->n >= c->cap || !c->xs[0]) { /* room, and witness points (c->witness) */
        const int rc =
            rs_contacts_reserve(c, c->n < c->cap ? c->n + 1 : 2 * c->n + 64, err);
        if (rc)
            return rc;
    }
    const int k = c->n++;
    c->point[k] = point;
    c->feature[k] = RS_FEATURE_MANIFOLD(feature, m->id);
    for (int d = 0; d < 3; d++) {
        c->xm[d][k] = m->xm[d];
        c->nrm[d][k] = m->n[d];
        c->t1[d][k] = m->t1[d];
        c->t2[d][k] = m->t2[d];
        c->xs[d][k] = m->xs[d];
    }
    c->dist[k] = radius - m->depth;
    c->curv[0][k] = m->curv[0];
    c->curv[1][k] = m->curv[1];
    c->share[k] = 1.0;
    return RS_OK;
}

/* Whether the contact j of a core point lies on the pair's wall: the same owning
 * feature, or on a MESH a face of the pair's plane (a coplanar region of faces, which
 * the pair answers as one). */
static int same_wall(const rs_contacts *pc, int j, const rs_body_contact *o, double reach)
{
    if (RS_FEATURE_BASE(pc->feature[j]) == RS_FEATURE_BASE(o->feature))
        return 1;
    if (RS_FEATURE_TYPE(pc->feature[j]) != RS_FEAT_FACE ||
        RS_FEATURE_TYPE(o->feature) != RS_FEAT_FACE || o->curv[0] != 0.0 ||
        o->curv[1] != 0.0)
        return 0;
    const double n[3] = {pc->nrm[0][j], pc->nrm[1][j], pc->nrm[2][j]};
    const double dx[3] = {pc->xm[0][j] - o->xm[0], pc->xm[1][j] - o->xm[1],
                          pc->xm[2][j] - o->xm[2]};
    return rs_dot3(n, o->normal) >= 1.0 - 1e-12 &&
           fabs(rs_dot3(dx, o->normal)) <= 1e-12 * reach;
}

static int by_depth(const void *a, const void *b)
{
    const double da = ((const mpoint *)a)->depth, db = ((const mpoint *)b)->depth;
    return da < db ? 1 : da > db ? -1 : ((const mpoint *)a)->id - ((const mpoint *)b)->id;
}

/* A core point's query: its body, the feature (index into the body's list) and id, its
 * place among the body's core points (seq), its point in the world and the lift of its
 * ball; where the kind answers it in closed form (rs_surface_ops.feature_point), that
 * answer. */
typedef struct corner {
    int body, f, id, seq;
    double cw[3], lift;
    double dist, xm[3], n[3];
} corner;

typedef struct corners {
    corner *q;
    double *x; /* x, y, z, radius: 4 cap each */
    int n, cap;
} corners;

/* The core points answered in closed form, in the order of the queried ones. */
typedef struct answered {
    corner *q;
    int n, cap;
} answered;

static int answered_add(answered *a, const corner *q)
{
    if (a->n == a->cap) {
        const int cap = a->cap ? 2 * a->cap : 64;
        corner *nq = realloc(a->q, (size_t)cap * sizeof *nq);
        if (!nq)
            return -1;
        a->q = nq, a->cap = cap;
    }
    a->q[a->n++] = *q;
    return 0;
}

/* Room for cap queries in a; 0, -1 when out of memory (a unchanged but a->q, which may
 * have moved). */
static int corners_room(corners *a, int cap)
{
    if (cap > a->cap) {
        corner *nq = realloc(a->q, (size_t)cap * sizeof *nq);
        double *nx = nq ? malloc(4 * (size_t)cap * sizeof *nx) : NULL;
        if (!nx) {
            if (nq)
                a->q = nq;
            return -1;
        }
        for (int k = 0; k < 4; k++)
            if (a->n)
                memcpy(nx + (size_t)k * cap, a->x + (size_t)k * a->cap,
                       (size_t)a->n * sizeof *nx);
        free(a->x);
        a->q = nq, a->x = nx, a->cap = cap;
    }
    return 0;
}

static int corners_add(corners *a, const corner *q, const double cl[3], double r)
{
    if (a->n == a->cap && corners_room(a, 2 * a->cap))
        return -1;
    a->q[a->n] = *q;
    a->x[a->n] = cl[0], a->x[a->cap + a->n] = cl[1], a->x[2 * a->cap + a->n] = cl[2];
    a->x[3 * a->cap + a->n] = r;
    a->n++;
    return 0;
}

/* A polyhedron's first cap vertices asked (core_points), before the rest. */
enum { CORE_FIRST = 8 };

/* The core points of one feature answered in closed form so far, as the manifold will
 * read them: their depths and ids where within the gap, and whether one went to the
 * query (its depth unknown here). */
typedef struct known_points {
    int n, asked;
    double depth[CAND_MAX], key[CAND_MAX];
    int id[CAND_MAX];
} known_points;

static void kp_note(known_points *kp, int known, const corner *q, double rr, double gap_max,
                    double key)
{
    if (!known) {
        kp->asked = 1;
        return;
    }
    const double depth = rr + q->lift - q->dist;
    if (!(-depth <= gap_max))
        return;
    kp->depth[kp->n] = depth, kp->key[kp->n] = key, kp->id[kp->n] = q->id;
    kp->n++;
}

/* Do the core points so far, all answered in closed form on the pair's feature (a plane),
 * settle the manifold of pair o: are RS_MANIFOLD_MAX of the points it keeps (the deepest
 * point among them unless a core point stands for it) deeper than any later point can
 * be (or is none within the gap), and is whether a core point stands for it decided?
 * Later points lie no farther
 * along d than key_last: on the plane, no deeper than the last known point by more than
 * dn times the keys' difference, and a margin for the rounding and for the faces a later
 * point may rest on (the feature's own, or a coplanar one: same_wall). */
static int settled(const known_points *kp, const rs_body_contact *o, double dn,
                   double key_last, double reach, const double x[3], double nxs,
                   double gap_max)
{
    if (kp->asked || kp->n == 0 || RS_FEATURE_TYPE(o->feature) != RS_FEAT_FACE)
        return 0;
    const int j = kp->n - 1;
    const double margin =
        1e-6 * reach + 1e-12 * (fabs(x[0]) + fabs(x[1]) + fabs(x[2]) + fabs(nxs));
    const double bound = kp->depth[j] - dn * (kp->key[j] - key_last) + margin;
    if (bound < -gap_max && bound < o->depth - 1e-12 * reach)
        return 1; /* no later point is within the gap */
    int core = o->iterations < 0; /* a core point stands for the deepest point (as the
                                   * manifold decides) */
    for (int k = 0; k < kp->n; k++)
        core |= kp->depth[k] >= o->depth - 1e-12 * reach;
    if (!core && !(bound < o->depth - 1e-12 * reach))
        return 0; /* a later point may still stand for it */
    int ids[RS_MANIFOLD_MAX], nid = 0;
    if (!core && o->depth > bound)
        ids[nid++] = 0;
    for (int k = 0; k < kp->n && nid < RS_MANIFOLD_MAX; k++) {
        if (!(kp->depth[k] > bound))
            continue;
        int dup = 0;
        for (int q = 0; q < nid; q++)
            dup |= ids[q] == kp->id[k];
        if (!dup)
            ids[nid++] = kp->id[k];
    }
    return nid >= RS_MANIFOLD_MAX;
}

int rs_body_manifold(const rs_surface *s, const rs_pose *pose, const rs_body *body, int n,
                     int point0, const double *radius, double gap_max, rs_contacts *c,
                     rs_error *err)
{
    if (!c || !c->witness)
        return rs_error_set(err, RS_ERR_ARG,
                            "body query: the contact list must keep witness points "
                            "(rs_contacts.witness)");
    for (int i = 0; i < n; i++)
        if (!(radius[i] >= 0.0) || !isfinite(radius[i]))
            return rs_error_set(err, RS_ERR_ARG,
                                "body query: radius = %g (expected a finite number >= 0)",
                                radius[i]);
    if (n < 1)
        return RS_OK;
    /* each body's features in a list of its own, on a shared array while they fit */
    enum { FEATURES = 4 };
    rs_body *b = malloc((size_t)n * sizeof *b);
    rs_body_contacts *fl = malloc((size_t)n * sizeof *fl);
    rs_body_contact *pool = malloc((size_t)n * FEATURES * sizeof *pool);
    if (!b || !fl || !pool) {
        free(b);
        free(fl);
        free(pool);
        return rs_error_set(err, RS_ERR_NOMEM, "body query: out of memory for %d bodies",
                            n);
    }
    for (int i = 0; i < n; i++) {
        const rs_body_contacts l = {0, FEATURES, pool + (size_t)i * FEATURES, 1};
        fl[i] = l;
    }
    int rc = RS_OK;
    for (int i = 0; i < n && rc == RS_OK; i++)
        rc = rs_body_check(s, body + i, gap_max, b + i, err);
    if (rc == RS_OK && !s->ops->body)
        rc = rs_error_set(err, RS_ERR_ARG, "body query: surface '%s' (%s) takes no bodies",
                          s->name, s->ops->name);
    if (rc == RS_OK)
        rc = s->ops->body(s, pose, b, n, gap_max, 1, fl, err);

    /* Every body's core points that may reach the wall, each rounded toward it, asked in
     * one query: its own contact with the feature (the same owning feature, else it rests
     * on another one). flat facets (the FACETED convention): a ball moved along the
     * normal has the same depth on their planes. */
    const int mesh = s->ops->frame == RS_FRAME_GLOBAL_X;
    corners cq = {NULL, NULL, 0, 0};
    answered ca = {NULL, 0, 0};
    if (rc == RS_OK && corners_room(&cq, n + 64))
        rc = rs_error_set(err, RS_ERR_NOMEM, "body query: out of memory");
    double gap = 0.0; /* the query's gap and depth limit */
    for (int i = 0; i < n; i++)
        gap = fmax(gap, 2.0 * rs_body_reach(b + i) + gap_max);
    for (int i = 0; i < n && rc == RS_OK; i++) {
        const double rr = rs_shape_core_radius(b[i].shape), reach = rs_body_reach(b + i);
        for (int f = 0; f < fl[i].n && rc == RS_OK; f++)
            if (fl[i].c[f].feature >= RS_MANIFOLD_STRIDE)
                rc = rs_error_set(err, RS_ERR_CAPACITY,
                                  "body query: feature %d of '%s' is beyond the manifold's "
                                  "ids (%d)",
                                  fl[i].c[f].feature, s->name, RS_MANIFOLD_STRIDE);
        if (rc != RS_OK || !core_points_of(b[i].shape))
            continue; /* a smooth body: its deepest point only */
        double R[9];
        rs_body_rotation(b + i, R);
        for (int f = 0; f < fl[i].n && rc == RS_OK; f++) {
            const rs_body_contact *o = &fl[i].c[f];
            double d[3];
            for (int k = 0; k < 3; k++)
                d[k] = -(R[k] * o->normal[0] + R[3 + k] * o->normal[1] +
                         R[6 + k] * o->normal[2]);
            const double dn = rs_norm3(d);
            for (int k = 0; k < 3; k++)
                d[k] /= dn;
            cand cp[CAND_MAX];
            /* a polyhedron's cap vertices, farthest first: on a kind with closed forms
             * the first few, the rest where those do not settle the manifold (settled) */
            const int poly =
                b[i].shape->kind == RS_SHAPE_POLYHEDRON && s->ops->feature_point != NULL;
            int ncp = core_points(b[i].shape, d, cp, poly ? CORE_FIRST : CAND_MAX - 1);
            known_points kp;
            kp.n = kp.asked = 0;
            /* a wall flat or convex toward the body lies below the tangent plane at the
             * deepest point: a point higher above it than the depth plus the gap does not
             * reach it; elsewhere the body's reach bounds it */
            const double above =
                o->depth + gap_max +
                (o->curv[0] >= 0.0 && o->curv[1] >= 0.0 ? 1e-9 : 1.0) * reach;
            const int flat = mesh || (o->curv[0] == 0.0 && o->curv[1] == 0.0);
            const double lift = flat ? fmax(o->depth, 0.0) + 1e-9 * reach : 0.0;
            /* a core point's height in the body frame, n.(R p) = -dn d.p, passes over the
             * points clearly too high at three products each (its rounding is far below
             * the margin); the rest are measured in the world as below */
            const double nx = rs_dot3(o->normal, b[i].x), nxs = rs_dot3(o->normal, o->xs);
            const double clear = above + 1e-12 * (reach + fabs(nx) + fabs(nxs));
            for (int k = 0;; k++) {
                /* the rest, unless the last is passed over as too high (so is every
                 * later one: its height is monotone in its place along d) or those so far
                 * settle the manifold */
                if (k == ncp && poly && ncp == CORE_FIRST &&
                    !(-dn * rs_dot3(d, cp[k - 1].p) + nx - rr - nxs > clear) &&
                    !settled(&kp, o, dn, rs_dot3(d, cp[k - 1].p), reach, b[i].x, nxs,
                             gap_max))
                    ncp = core_points(b[i].shape, d, cp, CAND_MAX - 1); /* the same first */
                if (k == ncp)
                    break;
                if (-dn * rs_dot3(d, cp[k].p) + nx - rr - nxs > clear)
                    continue;
                corner q = {.body = i, .f = f, .id = cp[k].id, .seq = k, .lift = lift};
                rs_matvec3(R, cp[k].p, q.cw);
                for (int j = 0; j < 3; j++)
                    q.cw[j] += b[i].x[j];
                const double h = rs_dot3(o->normal, q.cw) - rr - rs_dot3(o->normal, o->xs);
                if (h > above)
                    continue; /* too high above the deepest point to reach the wall */
                /* the core point's rounding ball, as a sphere meets the wall; on a MESH,
                 * whose two sides answer a point by the side it is on, the ball grown by
                 * lift about its point moved as far out along the pair's normal, so that
                 * its centre is on the body's side (the same depth on the facets' planes)
                 */
                const double cl[3] = {q.cw[0] + lift * o->normal[0],
                                      q.cw[1] + lift * o->normal[1],
                                      q.cw[2] + lift * o->normal[2]};
                /* the kind's closed form where it has one, else the query */
                const int known = s->ops->feature_point &&
                                  s->ops->feature_point(s, pose, RS_FEATURE_BASE(o->feature),
                                                        cl, rr + lift, gap, gap, &q.dist,
                                                        q.xm, q.n);
                if (known ? answered_add(&ca, &q) : corners_add(&cq, &q, cl, rr + lift))
                    rc = rs_error_set(err, RS_ERR_NOMEM, "body query: out of memory");
                kp_note(&kp, known, &q, rr, gap_max, rs_dot3(d, cp[k].p));
            }
        }
    }
    rs_contacts pc;
    memset(&pc, 0, sizeof pc);
    int *off = NULL;
    if (rc == RS_OK && cq.n > 0) {
        off = malloc(((size_t)cq.n + 1) * sizeof *off);
        rc = off ? rs_contacts_reserve(&pc, 2 * cq.n + 64, err)
                 : rs_error_set(err, RS_ERR_NOMEM, "body query: out of memory");
        if (rc == RS_OK)
            rc = rs_body_closest(s, pose, cq.n, cq.x, cq.x + cq.cap, cq.x + 2 * cq.cap,
                                 cq.x + 3 * cq.cap, gap, gap, &pc, err);
        if (rc == RS_OK)
            rs_contacts_offsets(&pc, cq.n, off);
    }

    /* Each body's manifold per feature, in order: the deepest point and the core points
     * that rest on the feature's wall. */
    for (int i = 0, a = 0, e = 0; i < n && rc == RS_OK; i++) {
        const int k0 = c->n;
        const double rr = rs_shape_core_radius(b[i].shape), reach = rs_body_reach(b + i);
        for (int f = 0; f < fl[i].n && rc == RS_OK; f++) {
            const rs_body_contact *o = &fl[i].c[f];
            mpoint m[CAND_MAX];
            int nm = 1;
            m[0].id = 0;
            m[0].depth = o->depth;
            memcpy(m[0].xs, o->xs, sizeof m[0].xs);
            memcpy(m[0].xm, o->xm, sizeof m[0].xm);
            memcpy(m[0].n, o->normal, sizeof m[0].n);
            memcpy(m[0].t1, o->t1, sizeof m[0].t1);
            memcpy(m[0].t2, o->t2, sizeof m[0].t2);
            memcpy(m[0].curv, o->curv, sizeof m[0].curv);
            int deep_is_core = 0;
            /* the core points in their order, each from the query or the closed form */
            for (;;) {
                const int qa = a < cq.n && cq.q[a].body == i && cq.q[a].f == f;
                const int qe = e < ca.n && ca.q[e].body == i && ca.q[e].f == f;
                if (!qa && !qe)
                    break;
                const int from_query = qa && (!qe || cq.q[a].seq < ca.q[e].seq);
                const corner *q = from_query ? cq.q + a++ : ca.q + e++;
                double dist, xm[3], nw[3], t1[3] = {0.0, 0.0, 0.0}, t2[3] = {0.0, 0.0, 0.0};
                double curv[2] = {0.0, 0.0};
                if (from_query) {
                    const int j = rs_contacts_pick(&pc, off[a - 1], off[a],
                                                   RS_FEATURE_BASE(o->feature));
                    if (j < 0 || !same_wall(&pc, j, o, reach))
                        continue;
                    dist = pc.dist[j];
                    for (int k = 0; k < 3; k++) {
                        xm[k] = pc.xm[k][j];
                        nw[k] = pc.nrm[k][j];
                        t1[k] = pc.t1[k][j];
                        t2[k] = pc.t2[k][j];
                    }
                    curv[0] = pc.curv[0][j];
                    curv[1] = pc.curv[1][j];
                } else { /* on the pair's own feature: on its wall */
                    dist = q->dist;
                    memcpy(xm, q->xm, sizeof xm);
                    memcpy(nw, q->n, sizeof nw);
                }
                const double depth = rr + q->lift - dist;
                if (!(-depth <= gap_max))
                    continue;
                if (depth >= o->depth - 1e-12 * reach)
                    deep_is_core = 1; /* as deep as the deepest point: it stands for it */
                mpoint *p = &m[nm++];
                p->id = q->id;
                p->depth = depth;
                for (int k = 0; k < 3; k++) {
                    p->xs[k] = q->cw[k] - rr * nw[k];
                    p->xm[k] = xm[k];
                    p->n[k] = nw[k];
                    p->t1[k] = t1[k];
                    p->t2[k] = t2[k];
                }
                p->curv[0] = curv[0];
                p->curv[1] = curv[1];
            }
            /* the deepest point stands for itself unless a core point is as deep (is it, or
             * rests on the wall beside it: a face, a rim); where it did not settle (a fold
             * sharper than the body) the core points stand for it, and a smooth body keeps
             * its deepest iterate */
            if (o->iterations < 0 && core_points_of(b[i].shape))
                deep_is_core = 1;
            mpoint *keep = deep_is_core ? m + 1 : m;
            const int count = deep_is_core ? nm - 1 : nm;
            /* the deepest first (ties: the lower id, then the earlier point), one point
             * an id (a polyhedron's vertices i and i + 30: the deeper), at most
             * RS_MANIFOLD_MAX: the next in that order picked from those left, so that
             * only the kept and the skipped are ordered */
            unsigned char taken[CAND_MAX] = {0};
            int nk = 0, kept[RS_MANIFOLD_MAX];
            for (int round = 0; round < count && nk < RS_MANIFOLD_MAX; round++) {
                int next = -1;
                for (int k = 0; k < count; k++)
                    if (!taken[k] && (next < 0 || by_depth(keep + k, keep + next) < 0))
                        next = k;
                taken[next] = 1;
                int dup = 0;
                for (int q = 0; q < nk; q++)
                    dup |= keep[kept[q]].id == keep[next].id;
                if (!dup)
                    kept[nk++] = next;
            }
            for (int k = 0; k < nk && rc == RS_OK; k++)
                rc = append(c, point0 + i, radius[i], o->feature, &keep[kept[k]], err);
        }
        /* Contacts on features that fold concavely under the body (two facets of a drum)
         * overlap one patch of it: their shares, as a sphere's of radius R on each
         * witness point (docs/conventions.md, "Shares at concave folds"): weights a^2, a
         * = sqrt(R^2 - dist^2), cut to 0 where a contact's foot is on the fold line it
         * begins or ends at. Corners apart by more than their patches keep 1. */
        if (rc == RS_OK && c->n - k0 > 1)
            rs_contacts_body_shares(c, k0, c->n - k0, radius[i]);
    }
    rs_contacts_free(&pc);
    free(off);
    free(cq.q);
    free(cq.x);
    free(ca.q);
    for (int i = 0; i < n; i++)
        rs_body_contacts_free(fl + i);
    free(fl);
    free(pool);
    free(b);
    return rc;
}
