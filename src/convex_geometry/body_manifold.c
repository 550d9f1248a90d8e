/* A convex body as a slave of the contact core (rs_body_manifold, which rs_body_query
 * orients): per owning feature of the kind's body operation, its contact manifold: the
 * body's deepest point and the points of its core that can rest on the feature (a box's
 * corners, a cylinder's rims, a capsule's ends), each a contact of its own, as each slave
 * node of a face is in an Abaqus node-to-surface contact (docs/conventions.md, "Convex
 * bodies"). Each point is measured by the kind's own sphere query (closest). */
#include "convex_internal.h"
#include "rigidsurf/vec.h"
#include "rs_compiler.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { CAND_MAX = RS_CORE_CANDS };

typedef rs_core_cand cand;

/* The direction (c0, s0) of d's part in the body's x-y plane (unit; (1, 0) along z). */
static void rim_turn(const double d[3], double *c0, double *s0)
{
    const double rho = rs_norm2(d[0], d[1]);
    *c0 = rho > 0.0 ? d[0] / rho : 1.0, *s0 = rho > 0.0 ? d[1] / rho : 0.0;
}

/* Core point j of a cylinder or a cone (s) for the turn (c0, s0) of rim_turn: four rim
 * points from the rim's lowest (the generator under the wall) in quarter turns, a
 * cylinder's top rim (j < 4) then its bottom one (4 <= j < 8); a cone's one rim (j < 4)
 * and its apex (j = 4). */
static void rim_point(const rs_shape *s, double c0, double s0, int j, cand *c)
{
    const double *h = s->dim;
    const int cyl = s->kind == RS_SHAPE_CYLINDER;
    if (!cyl && j == 4) {
        c->p[0] = c->p[1] = 0.0;
        c->p[2] = 0.75 * h[1] - s->shift[2];
        c->id = 5;
        return;
    }
    const int e = j / 4, k = j % 4;
    const double z = cyl ? (e ? -h[1] : h[1]) : -0.25 * h[1] - s->shift[2];
    const double ck = k == 0 ? c0 : k == 1 ? -s0 : k == 2 ? -c0 : s0;
    const double sk = k == 0 ? s0 : k == 1 ? c0 : k == 2 ? -s0 : -c0;
    c->p[0] = h[0] * ck;
    c->p[1] = h[0] * sk;
    c->p[2] = z;
    c->id = 1 + 4 * e + k;
}

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
        double c0, s0;
        rim_turn(d, &c0, &s0);
        for (int j = 0; j < (s->kind == RS_SHAPE_CYLINDER ? 8 : 5) && n < cap; j++)
            rim_point(s, c0, s0, j, c + n++);
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

/* The core points of core_points(s, d) whose height above the deepest point, -dn d.p +
 * nx - rr - nxs (d unit, the body frame), is at most clear, in its order. A box's corner
 * v has d.p = sum of +-a_k, a_k = d_k h_k (bit for bit its dot product); the corner
 * along d (a_k > 0 on its + sides) is the lowest and each other one lies higher by at
 * least 2 dn min |a_k|: when that clears the lowest corner's height past clear by far
 * more than rounding, the lowest is the only one. A cylinder's and a cone's points are
 * made only where their height about is within far more than rounding of clear; a
 * capsule's ends are measured by d_z z. */
RS_INLINE int low_points(const rs_shape *s, const double d[3], double dn, double nx,
                         double rr, double nxs, double clear, cand *c, int cap)
{
    if (s->kind == RS_SHAPE_BOX && cap >= 8) {
        const double *h = s->dim;
        const double a0 = d[0] * h[0], a1 = d[1] * h[1], a2 = d[2] * h[2];
        const int lo = (a0 > 0.0) | (a1 > 0.0) << 1 | (a2 > 0.0) << 2;
        const double dlo =
            ((lo & 1) ? a0 : -a0) + ((lo & 2) ? a1 : -a1) + ((lo & 4) ? a2 : -a2);
        const double hlo = -dn * dlo + nx - rr - nxs;
        const double b0 = fabs(a0), b1 = fabs(a1), b2 = fabs(a2);
        const double rise =
            2.0 * dn * (b0 < b1 ? (b0 < b2 ? b0 : b2) : (b1 < b2 ? b1 : b2));
        const double margin = 1e-9 * (dn * (b0 + b1 + b2) + fabs(nx) + rr + fabs(nxs));
        const int only = hlo + rise > clear + margin; /* the lowest alone */
        const int v0 = only ? lo : 0, v1 = only ? lo + 1 : 8;
        int n = 0;
        for (int v = v0; v < v1; v++) {
            const double dp =
                ((v & 1) ? a0 : -a0) + ((v & 2) ? a1 : -a1) + ((v & 4) ? a2 : -a2);
            if (-dn * dp + nx - rr - nxs > clear)
                continue;
            c[n].p[0] = (v & 1) ? h[0] : -h[0];
            c[n].p[1] = (v & 2) ? h[1] : -h[1];
            c[n].p[2] = (v & 4) ? h[2] : -h[2];
            c[n++].id = 1 + v;
        }
        return n;
    }
    if ((s->kind == RS_SHAPE_CYLINDER || s->kind == RS_SHAPE_CONE) && cap >= 8) {
        /* each point's d.p about (rim: h_0 (rho, 0, -rho, 0)_k + d_z z; apex: d_z z):
         * only those within far more than rounding of clear are made and measured */
        const double *h = s->dim;
        const int cyl = s->kind == RS_SHAPE_CYLINDER, m = cyl ? 8 : 5;
        const double ra = h[0] * sqrt(d[0] * d[0] + d[1] * d[1]);
        const double z0 = cyl ? h[1] : -0.25 * h[1] - s->shift[2], z1 = -h[1];
        const double za = 0.75 * h[1] - s->shift[2];
        const double margin = 1e-9 * (dn * (h[0] + fabs(z0) + fabs(z1) + fabs(za)) +
                                      fabs(nx) + rr + fabs(nxs));
        const double ring[4] = {ra, 0.0, -ra, 0.0};
        int n = 0, turned = 0;
        double c0 = 1.0, s0 = 0.0;
        for (int j = 0; j < m; j++) {
            const double dpa =
                !cyl && j == 4 ? d[2] * za : ring[j % 4] + d[2] * (j < 4 ? z0 : z1);
            if (-dn * dpa + nx - rr - nxs > clear + margin)
                continue;
            if (!turned)
                rim_turn(d, &c0, &s0), turned = 1;
            rim_point(s, c0, s0, j, c + n);
            if (!(-dn * rs_dot3(d, c[n].p) + nx - rr - nxs > clear))
                n++;
        }
        return n;
    }
    if (s->kind == RS_SHAPE_CAPSULE && cap >= 2) {
        /* its ends' d.p = d_z z (the dot product's other terms are zeros, which change
         * no comparison) */
        int n = 0;
        for (int e = 0; e < 2; e++) {
            const double z = e ? -s->dim[1] : s->dim[1];
            if (-dn * (d[2] * z) + nx - rr - nxs > clear)
                continue;
            c[n].p[0] = c[n].p[1] = 0.0;
            c[n].p[2] = z;
            c[n++].id = 1 + e;
        }
        return n;
    }
    const int m = core_points(s, d, c, cap);
    int n = 0;
    for (int k = 0; k < m; k++)
        if (!(-dn * rs_dot3(d, c[k].p) + nx - rr - nxs > clear))
            c[n++] = c[k];
    return n;
}

int rs_body_low_points(const rs_shape *s, const double d[3], double dn, double nx,
                       double rr, double nxs, double clear, rs_core_cand *c, int cap)
{
    return low_points(s, d, dn, nx, rr, nxs, clear, c, cap);
}

/* Does the shape have core points (core_points gives some)? */
static int core_points_of(const rs_shape *s)
{
    return s->kind == RS_SHAPE_BOX || s->kind == RS_SHAPE_POLYHEDRON ||
           s->kind == RS_SHAPE_CYLINDER || s->kind == RS_SHAPE_CONE ||
           s->kind == RS_SHAPE_CAPSULE;
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

/* A body's window for its core points' balls: gap and depth limit twice its reach and
 * the gap (0 for none: no NaN). The block's balls are asked over the widest, and each
 * keeps what lies in its own body's (rs_contacts_pick). */
static double window(double reach, double gap_max)
{
    const double w = 2.0 * reach + gap_max;
    return w > 0.0 ? w : 0.0;
}

/* A core point's query: its body, the feature (index into the body's list) and id, its
 * ball's place among the balls asked of the kind's query (-1 where the kind answers it in
 * closed form, rs_surface_ops.feature_point: that answer in dist, xm, n), its point in the
 * world and the lift of its ball; with framed, the frame t1, t2 of the closed form (else
 * the frame follows from n, as on a MESH: zeros). A body's core points are listed feature
 * by feature, each feature's in the order made, asked and answered alike. */
typedef struct corner {
    int body, f, id, ball, framed;
    double cw[3], lift;
    double dist, xm[3], n[3], t1[3], t2[3];
} corner;

typedef struct corners {
    corner *q;
    double *x; /* the balls asked: x, y, z, radius, cap each */
    int n, nball, cap;
} corners;

/* Room for cap core points in a; 0, -1 when out of memory (a unchanged but a->q, which
 * may have moved). */
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
            if (a->nball)
                memcpy(nx + (size_t)k * cap, a->x + (size_t)k * a->cap,
                       (size_t)a->nball * sizeof *nx);
        free(a->x);
        a->q = nq, a->x = nx, a->cap = cap;
    }
    return 0;
}

/* The ball of core point q (the last of a's list) asked of the query: centre cl, radius r.
 */
static void corners_ball(corners *a, corner *q, const double cl[3], double r)
{
    const int j = q->ball = a->nball++;
    a->x[j] = cl[0], a->x[a->cap + j] = cl[1], a->x[2 * a->cap + j] = cl[2];
    a->x[3 * a->cap + j] = r;
}

/* A manifold point as the selection sees it: its id and depth, and where its contact is:
 * the query's contact j of core point q, q's closed form (j < 0), or the pair's deepest
 * point (q NULL). */
typedef struct mpoint {
    int id, j;
    double depth;
    const corner *q;
} mpoint;

static int by_depth(const mpoint *a, const mpoint *b)
{
    return a->depth < b->depth ? 1 : a->depth > b->depth ? -1 : a->id - b->id;
}

/* Appends manifold point m of pair o (feature, its deepest point) to c, read from where
 * it stands: the query's contacts pc, a core point's closed form (flat: curvatures zero;
 * its frame, or zeros where the kind's frame convention sets it), or o; a core point's
 * witness is its ball's foot on the body, cw - rr n. */
static int append(rs_contacts *c, int point, double radius, const rs_body_contact *o,
                  const mpoint *m, const rs_contacts *pc, double rr, rs_error *err)
{
    if (c->n >= c->cap || !c->xs[0]) { /* room, and witness points (c->witness) */
        const int rc =
            rs_contacts_reserve(c, c->n < c->cap ? c->n + 1 : 2 * c->n + 64, err);
        if (rc)
            return rc;
    }
    double xm[3], nw[3], t1[3], t2[3], xs[3], cv[2];
    const corner *q = m->q;
    if (!q) {
        for (int d = 0; d < 3; d++) {
            xm[d] = o->xm[d], nw[d] = o->normal[d], t1[d] = o->t1[d], t2[d] = o->t2[d];
            xs[d] = o->xs[d];
        }
        cv[0] = o->curv[0], cv[1] = o->curv[1];
    } else if (m->j >= 0) {
        const int j = m->j;
        for (int d = 0; d < 3; d++) {
            xm[d] = pc->xm[d][j], nw[d] = pc->nrm[d][j];
            t1[d] = pc->t1[d][j], t2[d] = pc->t2[d][j];
            xs[d] = q->cw[d] - rr * nw[d];
        }
        cv[0] = pc->curv[0][j], cv[1] = pc->curv[1][j];
    } else {
        for (int d = 0; d < 3; d++) {
            xm[d] = q->xm[d], nw[d] = q->n[d];
            t1[d] = q->framed ? q->t1[d] : 0.0, t2[d] = q->framed ? q->t2[d] : 0.0;
            xs[d] = q->cw[d] - rr * nw[d];
        }
        cv[0] = cv[1] = 0.0;
    }
    const int k = c->n++;
    c->point[k] = point;
    c->feature[k] = RS_FEATURE_MANIFOLD(o->feature, m->id);
    for (int d = 0; d < 3; d++) {
        c->xm[d][k] = xm[d];
        c->nrm[d][k] = nw[d];
        c->t1[d][k] = t1[d];
        c->t2[d][k] = t2[d];
        c->xs[d][k] = xs[d];
    }
    c->dist[k] = radius - m->depth;
    c->curv[0][k] = cv[0];
    c->curv[1][k] = cv[1];
    c->share[k] = 1.0;
    return RS_OK;
}

/* A polyhedron's first cap vertices asked (low_points), before the rest. */
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
 * Later points lie no farther along d than key_last: on the plane, no deeper than the
 * last known point by more than dn times the keys' difference, and a margin for the
 * rounding and for the faces a later point may rest on (the feature's own, or a coplanar
 * one: same_wall). */
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
    /* no later point is within the gap */
    if (bound < -gap_max && bound < o->depth - 1e-12 * reach)
        return 1;
    /* a core point stands for the deepest point (as the manifold decides) */
    int core = o->iterations < 0;
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

/* A feature f of s beyond the manifold's ids (RS_MANIFOLD_STRIDE). */
static int beyond_ids(const rs_surface *s, int f, rs_error *err)
{
    return rs_error_set(err, RS_ERR_CAPACITY,
                        "body query: feature %d of '%s' is beyond the manifold's ids (%d)",
                        f, s->name, RS_MANIFOLD_STRIDE);
}

void rs_body_work_free(rs_body_work *w)
{
    rs_contacts_free(&w->pc);
    free(w->mem);
    free(w->q);
    free(w->x);
    free(w->off);
    free(w->rot);
    free(w->kind_mem);
    free(w->flat);
    free(w->flat_at);
    rs_body_fixed_work_free(&w->fp);
    memset(w, 0, sizeof *w);
}

int rs_body_manifold(const rs_surface *s, const rs_pose *pose, const rs_body *body, int n,
                     int point0, const double *radius, double gap_max, rs_contacts *c,
                     rs_error *err)
{
    rs_body_work w;
    memset(&w, 0, sizeof w);
    const int rc =
        rs_body_manifold_in(s, pose, body, n, point0, radius, gap_max, &w, c, err);
    rs_body_work_free(&w);
    return rc;
}

int rs_body_manifold_in(const rs_surface *s, const rs_pose *pose, const rs_body *body,
                        int n, int point0, const double *radius, double gap_max,
                        rs_body_work *w, rs_contacts *c, rs_error *err)
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
    /* in one block: each body's features, checked body, reach, window and list */
    const size_t bytes = (size_t)n * (FEATURES * sizeof(rs_body_contact) + sizeof(rs_body) +
                                      2 * sizeof(double) + sizeof(rs_body_contacts));
    if (bytes > w->bytes) {
        free(w->mem);
        w->bytes = 0;
        if (!(w->mem = malloc(bytes)))
            return rs_error_set(err, RS_ERR_NOMEM,
                                "body query: out of memory for %d bodies", n);
        w->bytes = bytes;
    }
    rs_body_contact *pool = w->mem;
    rs_body *bc = (rs_body *)(pool + (size_t)n * FEATURES);
    double *rch = (double *)(bc + n), *win = rch + n;
    rs_body_contacts *fl = (rs_body_contacts *)(win + n);
    for (int i = 0; i < n; i++) {
        const rs_body_contacts l = {0, FEATURES, pool + (size_t)i * FEATURES, 1};
        fl[i] = l;
    }
    /* the checked bodies: as given, unless a quaternion is to be normalised (then all
     * copied, that one normalised: rs_body_check_pose) */
    int rc = RS_OK, unit = 1;
    for (int i = 0; i < n && rc == RS_OK; i++) { /* a run of one shape: its checks once */
        if (!(i > 0 && body[i].shape && body[i].shape == body[i - 1].shape))
            rc = rs_body_check_shape(s, body + i, gap_max, err);
        double nq;
        if (rc == RS_OK && (rc = rs_body_check_norm(body + i, &nq, err)) == RS_OK)
            unit &= !(fabs(nq - 1.0) > 1e-12);
    }
    for (int i = 0; i < n && rc == RS_OK && !unit; i++)
        rc = rs_body_check_pose(body + i, bc + i, err);
    const rs_body *b = unit ? body : bc;
    if (rc == RS_OK && !s->ops->body)
        rc = rs_error_set(err, RS_ERR_ARG, "body query: surface '%s' (%s) takes no bodies",
                          s->name, s->ops->name);
    /* where the kind takes them, the bodies' rotations made once for it and for the core
     * points below, and its work arrays kept over the query's runs */
    const double *rot = NULL;
    if (rc == RS_OK && s->ops->body_run) {
        if (n > w->nrot) {
            free(w->rot);
            w->nrot = 0;
            if ((w->rot = malloc(9 * (size_t)n * sizeof *w->rot)))
                w->nrot = n;
            else
                rc = rs_error_set(err, RS_ERR_NOMEM, "body query: out of memory");
        }
        for (int i = 0; i < n && rc == RS_OK; i++)
            rs_body_rotation(b + i, w->rot + 9 * i);
        rot = w->rot;
    }
    w->point = NULL, w->point_ctx = NULL, w->kit = NULL; /* (the kind's body_run's) */
    if (rc == RS_OK)
        rc = rot ? s->ops->body_run(s, pose, b, rot, n, gap_max, 1, fl, w, err)
                 : s->ops->body(s, pose, b, n, gap_max, 1, fl, err);

    /* Every body's core points that may reach the wall, each rounded toward it, asked in
     * one query: its own contact with the feature (the same owning feature, else it rests
     * on another one). flat facets (the FACETED convention): a ball moved along the
     * normal has the same depth on their planes. */
    const int mesh = s->ops->frame == RS_FRAME_GLOBAL_X;
    corners cq = {w->q, w->x, 0, 0, w->cap};
    if (rc == RS_OK && corners_room(&cq, n + 64))
        rc = rs_error_set(err, RS_ERR_NOMEM, "body query: out of memory");
    w->q = cq.q, w->x = cq.x, w->cap = cq.cap;
    /* room for the bodies' manifolds answered in closed form (a flat face whose core
     * points the kind's body_run answers: rs_body_flat_manifold) */
    if (rc == RS_OK && w->point && n > w->nflat) {
        free(w->flat), free(w->flat_at);
        w->nflat = 0;
        w->flat = malloc((size_t)n * sizeof *w->flat);
        w->flat_at = malloc((size_t)n * sizeof *w->flat_at);
        if (w->flat && w->flat_at)
            w->nflat = n;
        else
            rc = rs_error_set(err, RS_ERR_NOMEM, "body query: out of memory");
    }
    for (int i = 0; rc == RS_OK && w->point && i < n; i++)
        w->flat_at[i] = -1;
    int nflat = 0;
    double gap = 0.0; /* the widest window of the bodies (window) */
    for (int i = 0; i < n && rc == RS_OK; i++) { /* (checked bodies only) */
        const double g = win[i] = window(rch[i] = rs_body_reach(b + i), gap_max);
        gap = g > gap ? g : gap;
    }
    for (int i = 0; i < n && rc == RS_OK; i++) {
        const double rr = rs_shape_core_radius(b[i].shape), reach = rch[i];
        /* every feature within the manifold's ids (a body with core points: below, before
         * its core points are asked) */
        const int core = core_points_of(b[i].shape);
        for (int f = 0; !core && f < fl[i].n && rc == RS_OK; f++)
            if (fl[i].c[f].feature >= RS_MANIFOLD_STRIDE)
                rc = beyond_ids(s, fl[i].c[f].feature, err);
        if (rc != RS_OK || !core)
            continue; /* a smooth body: its deepest point only */
        double Ri[9];
        if (!rot)
            rs_body_rotation(b + i, Ri);
        const double *const R = rot ? rot + 9 * i : Ri;
        /* one flat face whose core points the kind answers in closed form: the manifold
         * in one pass (the same points and contacts), else as below */
        const rs_body_contact *o1 = fl[i].c;
        const struct rs_flat_face *kit =
            w->kit && !mesh && fl[i].n == 1 && b[i].shape->kind != RS_SHAPE_POLYHEDRON &&
                    o1->feature < RS_MANIFOLD_STRIDE &&
                    RS_FEATURE_TYPE(o1->feature) == RS_FEAT_FACE && o1->curv[0] == 0.0 &&
                    o1->curv[1] == 0.0
                ? w->kit(w->point_ctx, RS_FEATURE_BASE(o1->feature))
                : NULL;
        if (kit && rs_body_flat_manifold(b + i, R, o1, reach, win[i], gap_max, kit,
                                         w->flat + nflat)) {
            w->flat_at[i] = nflat++;
            continue;
        }
        for (int f = 0; f < fl[i].n && rc == RS_OK; f++) {
            const rs_body_contact *o = &fl[i].c[f];
            if (o->feature >= RS_MANIFOLD_STRIDE) {
                rc = beyond_ids(s, o->feature, err);
                break;
            }
            double d[3];
            for (int k = 0; k < 3; k++)
                d[k] = -(R[k] * o->normal[0] + R[3 + k] * o->normal[1] +
                         R[6 + k] * o->normal[2]);
            const double dn = rs_norm3(d);
            for (int k = 0; k < 3; k++)
                d[k] /= dn;
            /* a wall flat or convex toward the body lies below the tangent plane at the
             * deepest point: a point higher above it than the depth plus the gap does not
             * reach it; elsewhere the body's reach bounds it */
            const double above =
                o->depth + gap_max +
                (o->curv[0] >= 0.0 && o->curv[1] >= 0.0 ? 1e-9 : 1.0) * reach;
            const int flat = mesh || (o->curv[0] == 0.0 && o->curv[1] == 0.0);
            const double lift =
                flat ? (o->depth > 0.0 ? o->depth : 0.0) + 1e-9 * reach : 0.0;
            /* a core point's height in the body frame, n.(R p) = -dn d.p, passes over the
             * points clearly too high at three products each (its rounding is far below
             * the margin); the rest are measured in the world as below */
            const double nx = rs_dot3(o->normal, b[i].x), nxs = rs_dot3(o->normal, o->xs);
            const double clear = above + 1e-12 * (reach + fabs(nx) + fabs(nxs));
            cand cp[CAND_MAX];
            /* a polyhedron's cap vertices low enough, farthest first: on a kind with
             * closed forms the first few, the rest where all of those are low enough (the
             * height is monotone along the list) and do not settle the manifold */
            const int poly =
                b[i].shape->kind == RS_SHAPE_POLYHEDRON && s->ops->feature_point != NULL;
            int ncp = low_points(b[i].shape, d, dn, nx, rr, nxs, clear, cp,
                                 poly ? CORE_FIRST : CAND_MAX - 1);
            known_points kp;
            kp.n = kp.asked = 0;
            for (int k = 0; rc == RS_OK; k++) {
                if (k == ncp && poly && ncp == CORE_FIRST &&
                    !settled(&kp, o, dn, rs_dot3(d, cp[k - 1].p), reach, b[i].x, nxs,
                             gap_max)) /* the same first */
                    ncp =
                        low_points(b[i].shape, d, dn, nx, rr, nxs, clear, cp, CAND_MAX - 1);
                if (k == ncp)
                    break;
                if (cq.n == cq.cap && corners_room(&cq, 2 * cq.cap)) {
                    rc = rs_error_set(err, RS_ERR_NOMEM, "body query: out of memory");
                    break;
                }
                corner *q = cq.q + cq.n; /* made in place, kept below (cq.n++) */
                rs_matvec3(R, cp[k].p, q->cw);
                for (int j = 0; j < 3; j++)
                    q->cw[j] += b[i].x[j];
                const double h = rs_dot3(o->normal, q->cw) - rr - rs_dot3(o->normal, o->xs);
                if (h > above)
                    continue; /* too high above the deepest point to reach the wall */
                q->body = i, q->f = f, q->id = cp[k].id, q->lift = lift;
                /* the core point's rounding ball, as a sphere meets the wall; on a MESH,
                 * whose two sides answer a point by the side it is on, the ball grown by
                 * lift about its point moved as far out along the pair's normal, so that
                 * its centre is on the body's side (the same depth on the facets' planes)
                 */
                const double cl[3] = {q->cw[0] + lift * o->normal[0],
                                      q->cw[1] + lift * o->normal[1],
                                      q->cw[2] + lift * o->normal[2]};
                /* the kind's closed form where it has one and it pays, else the block's
                 * query: on a flat feature, the run's own closed form where the kind's
                 * body_run set one up (an extruded profile's LINE faces, cheaper a point
                 * than the block's query); else on a MESH, whose point query is dear, for
                 * every core point, and on the other kinds for a polyhedron's cap
                 * vertices, whose answers let the manifold stop after the first few; the
                 * frame kept where it does not follow from n (not on a MESH) */
                q->framed = !mesh;
                const int fb = RS_FEATURE_BASE(o->feature);
                const int known =
                    flat && w->point
                        ? w->point(w->point_ctx, fb, cl, rr + lift, win[i], win[i],
                                   &q->dist, q->xm, q->n, q->t1, q->t2)
                        : (mesh || poly) && s->ops->feature_point &&
                              s->ops->feature_point(
                                  s, pose, fb, cl, rr + lift, win[i], win[i], &q->dist,
                                  q->xm, q->n, mesh ? NULL : q->t1, mesh ? NULL : q->t2);
                q->ball = -1;
                if (!known)
                    corners_ball(&cq, q, cl, rr + lift);
                cq.n++;
                kp_note(&kp, known, q, rr, gap_max, rs_dot3(d, cp[k].p));
            }
        }
    }
    w->q = cq.q, w->x = cq.x, w->cap = cq.cap; /* (moved as the list grew) */
    rs_contacts pc = w->pc;
    if (rc == RS_OK && cq.nball > 0 && cq.nball + 1 > w->noff) {
        free(w->off);
        w->noff = 0;
        if ((w->off = malloc(((size_t)cq.nball + 1) * sizeof *w->off)))
            w->noff = cq.nball + 1;
    }
    int *off = w->off;
    if (rc == RS_OK && cq.nball > 0) {
        rc = off ? rs_contacts_reserve(&pc, 2 * cq.nball + 64, err)
                 : rs_error_set(err, RS_ERR_NOMEM, "body query: out of memory");
        if (rc == RS_OK)
            rc = rs_body_closest(s, pose, cq.nball, cq.x, cq.x + cq.cap, cq.x + 2 * cq.cap,
                                 cq.x + 3 * cq.cap, gap, gap, &pc, err);
        if (rc == RS_OK)
            rs_contacts_offsets(&pc, cq.nball, off);
    }

    /* Each body's manifold per feature, in order: the deepest point and the core points
     * that rest on the feature's wall. */
    for (int i = 0, a = 0; i < n && rc == RS_OK; i++) {
        const int k0 = c->n;
        const double rr = rs_shape_core_radius(b[i].shape), reach = rch[i];
        const int at = w->point ? w->flat_at[i] : -1;
        for (int k = 0; at >= 0 && k < w->flat[at].n && rc == RS_OK; k++)
            rc = rs_body_flat_append(c, point0 + i, radius[i], fl[i].c[0].feature,
                                     w->flat + at, k, err);
        for (int f = 0; at < 0 && f < fl[i].n && rc == RS_OK; f++) {
            const rs_body_contact *o = &fl[i].c[f];
            mpoint m[CAND_MAX];
            int nm = 1;
            m[0].id = 0;
            m[0].j = -1;
            m[0].depth = o->depth;
            m[0].q = NULL;
            int deep_is_core = 0;
            /* the core points in their order, each from the query or the closed form */
            for (; a < cq.n && cq.q[a].body == i && cq.q[a].f == f; a++) {
                const corner *q = cq.q + a;
                double dist = q->dist;
                int j = -1;
                if (q->ball >= 0) {
                    j = rs_contacts_pick(&pc, off[q->ball], off[q->ball + 1],
                                         RS_FEATURE_BASE(o->feature), -win[i],
                                         win[i] + cq.x[3 * cq.cap + q->ball]);
                    if (j < 0 || !same_wall(&pc, j, o, reach))
                        continue;
                    dist = pc.dist[j];
                } /* else on the pair's own feature: on its wall */
                const double depth = rr + q->lift - dist;
                if (!(-depth <= gap_max))
                    continue;
                if (depth >= o->depth - 1e-12 * reach)
                    deep_is_core = 1; /* as deep as the deepest point: it stands for it */
                mpoint *p = &m[nm++];
                p->id = q->id;
                p->j = j;
                p->depth = depth;
                p->q = q;
            }
            /* the deepest point stands for itself unless a core point is as deep (is it, or
             * rests on the wall beside it: a face, a rim); where it did not settle (a fold
             * sharper than the body) the core points stand for it, and a smooth body keeps
             * its deepest iterate */
            if (o->iterations < 0 && core_points_of(b[i].shape))
                deep_is_core = 1;
            const mpoint *keep = deep_is_core ? m + 1 : m;
            const int count = deep_is_core ? nm - 1 : nm;
            /* the deepest first (ties: the lower id, then the earlier point), one point
             * an id (a polyhedron's vertices i and i + 30: the deeper), at most
             * RS_MANIFOLD_MAX: the next in that order picked from those left, so that
             * only the kept and the skipped are ordered */
            unsigned char taken[CAND_MAX];
            int nk = 0, kept[RS_MANIFOLD_MAX];
            if (count == 1)
                kept[nk++] = 0;
            else
                memset(taken, 0, sizeof taken);
            for (int round = 0; count > 1 && round < count && nk < RS_MANIFOLD_MAX;
                 round++) {
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
                rc = append(c, point0 + i, radius[i], o, &keep[kept[k]], &pc, rr, err);
        }
        /* Contacts on features that fold concavely under the body (two facets of a drum)
         * overlap one patch of it: their shares, as a sphere's of radius R on each
         * witness point (docs/conventions.md, "Shares at concave folds"): weights a^2, a
         * = sqrt(R^2 - dist^2), cut to 0 where a contact's foot is on the fold line it
         * begins or ends at. Corners apart by more than their patches keep 1. */
        if (rc == RS_OK && c->n - k0 > 1)
            rs_contacts_body_shares(c, k0, c->n - k0, radius[i]);
    }
    w->pc = pc;
    for (int i = 0; i < n; i++)
        if (!fl[i].borrowed) /* (grown past its room in the pool) */
            rs_body_contacts_free(fl + i);
    return rc;
}
