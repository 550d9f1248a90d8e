/* Closest features of a profile in its plane: the ownership rules of profile.h, per
 * point (rs_pcache_hits) and per block of points (rs_pcache_points). */
#include "profile.h"
#include "revolution_point.h"
#include "rs_compiler.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define SEG_HIT 1
#define SEG_DROP 2

/* Segment k's record: the stored one, or (compact) one made in *tmp. */
RS_INLINE const rs_pseg *seg_rec(const rs_pcache *pc, int k, rs_pseg *tmp)
{
    if (pc->ps)
        return &pc->ps[k];
    rs_pvert v0, v1;
    rs_pcache_vertex(pc, k, &v0);
    rs_pcache_vertex(pc, k + 1 == pc->nvert ? 0 : k + 1, &v1);
    rs_pcache_segment(pc, k, &v0, &v1, tmp);
    return tmp;
}

/* Vertex j's record: the stored one, or (compact) one made in *tmp. */
RS_INLINE const rs_pvert *vert_rec(const rs_pcache *pc, int j, rs_pvert *tmp)
{
    if (pc->pv)
        return &pc->pv[j];
    rs_pcache_vertex(pc, j, tmp);
    return tmp;
}

/* Candidate contact of segment k (before the side and distance filters); 1 when the
 * segment owns the point. LINE here, CIRCL and PARAB in rs_pseg_curve (curves.c). */
RS_INLINE int eval_seg(const rs_pcache *pc, int k, double px, double py, rs_hit2 *h)
{
    rs_pseg tmp;
    const rs_pseg *q = seg_rec(pc, k, &tmp);
    if (q->type != RS_LINE)
        return rs_pseg_curve(pc, q, px, py, h);
    int in_start, in_end;
    rs_pseg_owns(q, px, py, &in_start, &in_end);
    if (!(in_start && in_end))
        return 0;
    double wx = px - q->o[0], wy = py - q->o[1];
    double tau = (wx * q->e[0] + wy * q->e[1]) * q->inv_len2;
    tau = tau < 0.0 ? 0.0 : tau > 1.0 ? 1.0 : tau;
    h->x[0] = q->o[0] + tau * q->e[0];
    h->x[1] = q->o[1] + tau * q->e[1];
    h->n[0] = -q->t[1];
    h->n[1] = q->t[0];
    h->dist = wx * h->n[0] + wy * h->n[1];
    h->kappa = 0.0;
    if (pc->sides == 2 && h->dist < 0.0) {
        h->dist = -h->dist;
        h->n[0] = -h->n[0];
        h->n[1] = -h->n[1];
    }
    h->feature = RS_FEATURE(RS_FEAT_FACE, k);
    return 1;
}

static int eval_vertex(const rs_pcache *pc, int j, double px, double py, rs_hit2 *h)
{
    if (pc->vk[j] == RS_VTX_SMOOTH)
        return 0;
    rs_pvert tmp;
    const rs_pvert *v = vert_rec(pc, j, &tmp);
    double dx = px - v->v[0], dy = py - v->v[1];
    double dA = dx * v->ta[0] + dy * v->ta[1], dB = dx * v->tb[0] + dy * v->tb[1];
    double sign = 1.0;
    int two = pc->sides == 2;
    switch (v->kind) {
    case RS_VTX_CONVEX:
        if (!(dA >= 0.0 && dB <= 0.0))
            return 0;
        break;
    case RS_VTX_CONCAVE:
        if (!(dA >= 0.0 && dB < 0.0))
            return 0;
        sign = two ? 1.0 : -1.0;
        break;
    default:
        if (v->sb < 0) { /* end of the profile */
            if (!(v->seg_owns_edge ? dA > 0.0 : dA >= 0.0))
                return 0;
            if (!two && !(dx * v->na[0] + dy * v->na[1] >= 0.0))
                return 0;
        } else { /* start of the profile */
            if (!(v->seg_owns_edge ? dB < 0.0 : dB <= 0.0))
                return 0;
            if (!two && !(dx * v->nb[0] + dy * v->nb[1] >= 0.0))
                return 0;
        }
        break;
    }
    double d = sqrt(dx * dx + dy * dy);
    h->feature = RS_FEATURE(RS_FEAT_VERTEX, j);
    h->x[0] = v->v[0];
    h->x[1] = v->v[1];
    if (d > 0.0) {
        h->n[0] = sign * dx / d;
        h->n[1] = sign * dy / d;
    } else {
        h->n[0] = v->nfb[0];
        h->n[1] = v->nfb[1];
    }
    h->dist = sign * d;
    h->kappa = 0.0;
    return 1;
}

/* Position of segment k in the near list (sorted), -1 when it is not near. */
static inline int near_pos(const rs_pscratch *sc, int nnear, int k)
{
    for (int i = 0; i < nnear; i++)
        if (sc->near[i] >= k)
            return sc->near[i] == k ? i : -1;
    return -1;
}

/* Behind a convex vertex only the face with the smaller penetration keeps its contact
 * (the Voronoi region of the solid); ties keep the lower index. */
static void voronoi_pair(const rs_pcache *pc, rs_pscratch *sc, int nnear, int j, double px,
                         double py)
{
    rs_pvert tmp;
    const rs_pvert *v = vert_rec(pc, j, &tmp);
    if (v->kind != RS_VTX_CONVEX || v->sa < 0 || v->sb < 0 || v->sa == v->sb)
        return;
    int A = v->sa, B = v->sb, ia = near_pos(sc, nnear, A), ib = near_pos(sc, nnear, B);
    rs_hit2 ha, hb;
    int hit_a = ia >= 0 ? sc->state[ia] & SEG_HIT : eval_seg(pc, A, px, py, &ha);
    int hit_b = ib >= 0 ? sc->state[ib] & SEG_HIT : eval_seg(pc, B, px, py, &hb);
    if (!hit_a || !hit_b)
        return;
    double da = ia >= 0 ? sc->cand[ia].dist : ha.dist;
    double db = ib >= 0 ? sc->cand[ib].dist : hb.dist;
    if (!(da < 0.0 || db < 0.0))
        return;
    int drop = (da < db || (da == db && A > B)) ? ia : ib;
    if (drop >= 0)
        sc->state[drop] |= SEG_DROP;
}

/* Whether the box (xmin, xmax, ymin, ymax) lies farther than reach from the point along
 * x or y. */
RS_INLINE int box_far(const double b[4], double px, double py, double reach)
{
    return b[0] - px > reach || px - b[1] > reach || b[2] - py > reach || py - b[3] > reach;
}

/* Whether the point is within reach of segment k: its bounding box and, for LINE and
 * CIRCL, its line or circle. A superset of the segments within reach is enough (the
 * vertices of a segment lie on both). */
RS_INLINE int seg_near(const rs_pseg *q, double px, double py, double reach)
{
    if (box_far(q->box, px, py, reach))
        return 0;
    if (q->type == RS_LINE) {
        double sd = (px - q->o[0]) * (-q->t[1]) + (py - q->o[1]) * q->t[0];
        return fabs(sd) <= reach;
    }
    if (q->type == RS_CIRCL) {
        double wx = px - q->o[0], wy = py - q->o[1], r2 = wx * wx + wy * wy;
        double hi = q->rad + reach, lo = q->rad - reach;
        return !(r2 > hi * hi || (lo > 0.0 && r2 < lo * lo));
    }
    return 1;
}

/* Segment q into the near list when the point is within reach of it, with its candidate
 * contact (the walk of rs_pcache_hits). */
RS_INLINE void near_seg(const rs_pcache *pc, const rs_pseg *q, double px, double py,
                        double reach, rs_pscratch *sc, int *nnear, int *neg)
{
    if (box_far(q->box, px, py, reach))
        return;
    if (*nnear == sc->cap) {
        sc->full = 1; /* the compact form's scratch: rs_pcache_hits asks for more */
        return;
    }
    const int k = q->self;
    rs_hit2 *h = &sc->cand[*nnear];
    int hit;
    if (q->type == RS_LINE) {
        /* within reach of the line, then owned (profile.h): the signed distance is the
         * candidate's */
        double wx = px - q->o[0], wy = py - q->o[1];
        double nx = -q->t[1], ny = q->t[0], sd = wx * nx + wy * ny;
        if (fabs(sd) > reach)
            return;
        int in_start, in_end;
        rs_pseg_owns(q, px, py, &in_start, &in_end);
        hit = in_start && in_end;
        if (hit) {
            double tau = (wx * q->e[0] + wy * q->e[1]) * q->inv_len2;
            tau = tau < 0.0 ? 0.0 : tau > 1.0 ? 1.0 : tau;
            h->x[0] = q->o[0] + tau * q->e[0];
            h->x[1] = q->o[1] + tau * q->e[1];
            int flip = pc->sides == 2 && sd < 0.0;
            h->n[0] = flip ? -nx : nx;
            h->n[1] = flip ? -ny : ny;
            h->dist = flip ? -sd : sd;
            h->kappa = 0.0;
            h->feature = RS_FEATURE(RS_FEAT_FACE, k);
        }
    } else {
        if (!seg_near(q, px, py, reach))
            return;
        hit = rs_pseg_curve(pc, q, px, py, h);
    }
    sc->near[*nnear] = k;
    sc->state[*nnear] = (unsigned char)(hit ? SEG_HIT : 0);
    *neg |= hit && h->dist < 0.0;
    (*nnear)++;
}

/* The tree's walk (profile.h): the boxes within reach, depth first, first child first,
 * so the segments come in profile order. In the compact form a segment's record is made
 * when its own box is within reach, each vertex's once along a run. */
static void near_tree(const rs_pcache *pc, double px, double py, double reach,
                      rs_pscratch *sc, int *nnear, int *neg)
{
    int sl[2 * RS_PC_MAXDEPTH + 2], si[2 * RS_PC_MAXDEPTH + 2], top = 0;
    sl[top] = pc->ntlev - 1;
    si[top++] = 0;
    while (top > 0) {
        const int l = sl[--top], i = si[top];
        const double *b = pc->tree + 4 * ((size_t)pc->tlev[l] + (size_t)i);
        if (box_far(b, px, py, reach))
            continue;
        if (l > 0) {
            if (2 * i + 1 < pc->tlev[l] - pc->tlev[l - 1]) {
                sl[top] = l - 1;
                si[top++] = 2 * i + 1;
            }
            sl[top] = l - 1;
            si[top++] = 2 * i;
            continue;
        }
        const int k0 = i * RS_PC_LEAF;
        const int k1 = k0 + RS_PC_LEAF < pc->nseg ? k0 + RS_PC_LEAF : pc->nseg;
        if (pc->ps) {
            for (int k = k0; k < k1; k++)
                near_seg(pc, &pc->ps[k], px, py, reach, sc, nnear, neg);
            continue;
        }
        rs_pvert va, vb;
        rs_pseg q;
        int have = -1; /* the vertex whose record va holds */
        for (int k = k0; k < k1; k++) {
            double sb[4];
            rs_pcache_box(pc, k, sb);
            if (box_far(sb, px, py, reach))
                continue;
            if (have != k)
                rs_pcache_vertex(pc, k, &va);
            rs_pcache_vertex(pc, k + 1 == pc->nvert ? 0 : k + 1, &vb);
            rs_pcache_segment(pc, k, &va, &vb, &q);
            near_seg(pc, &q, px, py, reach, sc, nnear, neg);
            va = vb;
            have = k + 1;
        }
    }
}

/* Whether the Voronoi pass of rs_pcache_hits (voronoi_pair at vertex j) drops face k,
 * penetrated at distance dk, for the point: at a convex vertex whose other segment owns
 * it too, the face with the larger penetration goes (ties: the higher index). */
static int face_dropped(const rs_pcache *pc, int k, double dk, int j, double px, double py)
{
    rs_pvert tmp;
    const rs_pvert *v = vert_rec(pc, j, &tmp);
    if (v->kind != RS_VTX_CONVEX || v->sa < 0 || v->sb < 0 || v->sa == v->sb)
        return 0;
    const int g = v->sa == k ? v->sb : v->sa;
    rs_hit2 hg;
    if (!eval_seg(pc, g, px, py, &hg))
        return 0;
    return dk < hg.dist || (dk == hg.dist && k > g);
}

int rs_pcache_face(const rs_pcache *pc, int k, double px, double py, double dlo, double dhi,
                   rs_hit2 *h)
{
    if (!pc->ps || k < 0 || k >= pc->nseg || pc->ps[k].type != RS_LINE)
        return -1;
    const rs_pseg *q = &pc->ps[k];
    double dist, hx, hy;
    int flip;
    if (!rs_pseg_line_face(q, pc->sides == 2, px, py, dlo, dhi, &dist, &flip, &hx, &hy))
        return 0;
    const int j1 = k + 1 == pc->nvert ? 0 : k + 1;
    if (pc->sides == 1 && dist < 0.0 &&
        ((pc->vk[k] == RS_VTX_CONVEX && face_dropped(pc, k, dist, k, px, py)) ||
         (pc->vk[j1] == RS_VTX_CONVEX && face_dropped(pc, k, dist, j1, px, py))))
        return 0;
    const double nx = -q->t[1], ny = q->t[0];
    h->feature = RS_FEATURE(RS_FEAT_FACE, k);
    h->x[0] = hx;
    h->x[1] = hy;
    h->n[0] = flip ? -nx : nx;
    h->n[1] = flip ? -ny : ny;
    h->dist = dist;
    h->kappa = 0.0;
    return 1;
}

int rs_pcache_hits(const rs_pcache *pc, double px, double py, double dlo, double dhi,
                   rs_pscratch *sc)
{
    const int n = pc->nseg;
    int nh = 0, nnear = 0, neg = 0;
    double reach = (pc->sides == 2 || dhi > -dlo) ? dhi : -dlo;
    if (!(reach >= 0.0) || dlo > dhi)
        return 0;
    sc->full = 0;
    /* the candidates: one bucket's list at the first level whose margin covers reach,
     * else every segment of a small profile, else (and in the compact form) the tree's */
    int l = 0;
    while (pc->ps && l < pc->nlevel && pc->margin[l] < reach)
        l++;
    if (!pc->ps || (l == pc->nlevel && n > RS_PC_SCAN)) {
        near_tree(pc, px, py, reach, sc, &nnear, &neg);
    } else {
        const int *list = pc->boff + pc->all_at, *end = list + n;
        if (l < pc->nlevel) {
            double c = pc->axis ? py : px;
            double f = (c - pc->lo) * pc->inv_w, top = (double)(pc->nbucket - 1);
            int b = f > 0.0 ? (int)(f < top ? f : top) : 0;
            const int *bs = pc->bstart + (size_t)l * (size_t)(pc->nbucket + 1);
            list = pc->boff + bs[b];
            end = pc->boff + bs[b + 1];
        }
        for (; list < end; list++)
            near_seg(pc, &pc->ps[rs_pcache_seg(*list)], px, py, reach, sc, &nnear, &neg);
    }
    if (sc->full) /* more segments within reach than the scratch holds: again, larger */
        return rs_pscratch_grow(sc, pc) == RS_OK ? rs_pcache_hits(pc, px, py, dlo, dhi, sc)
                                                 : -1;
    if (pc->sides == 1 && neg) {
        for (int i = 0; i < nnear; i++) {
            int k = sc->near[i];
            if (!(sc->state[i] & SEG_HIT) || !(sc->cand[i].dist < 0.0))
                continue;
            voronoi_pair(pc, sc, nnear, k, px, py);
            voronoi_pair(pc, sc, nnear, k + 1 == pc->nvert ? 0 : k + 1, px, py);
        }
    }
    for (int i = 0; i < nnear; i++) {
        int k = sc->near[i];
        /* vertex k (the start of segment k) is within reach when both its segments are */
        if (pc->vk[k] != RS_VTX_SMOOTH) {
            int sa = k > 0 ? k - 1 : (pc->closed ? n - 1 : -1);
            int sa_near =
                sa < 0 || (i > 0 ? sc->near[i - 1] == sa : sc->near[nnear - 1] == sa);
            rs_hit2 *h = &sc->hits[nh];
            if (sa_near && eval_vertex(pc, k, px, py, h) && h->dist >= dlo &&
                h->dist <= dhi)
                nh++;
        }
        if (sc->state[i] == SEG_HIT) {
            const rs_hit2 *c = &sc->cand[i];
            if (c->dist >= dlo && c->dist <= dhi)
                sc->hits[nh++] = *c;
        }
        if (k == n - 1 && !pc->closed) {
            rs_hit2 *h = &sc->hits[nh];
            if (eval_vertex(pc, n, px, py, h) && h->dist >= dlo && h->dist <= dhi)
                nh++;
        }
    }
    return nh;
}

/* The output arrays of rs_pcache_points, in profile-plane form. */
typedef struct pout {
    int *point, *feature;
    double *x0, *x1, *n0, *n1, *dist, *kap;
} pout;

/* Contact h of point pt into slot k. */
RS_INLINE void put_hit(const pout *o, int k, int pt, const rs_hit2 *h)
{
    o->point[k] = pt;
    o->feature[k] = h->feature;
    o->x0[k] = h->x[0];
    o->x1[k] = h->x[1];
    o->n0[k] = h->n[0];
    o->n1[k] = h->n[1];
    o->dist[k] = h->dist;
    o->kap[k] = h->kappa;
}

/* Vertex j's contact into slot nh when the vertex owns the point within [dlo, dhi];
 * returns the new count. */
static int put_vertex(const rs_pcache *pc, const pout *o, int nh, int j, int pt, double px,
                      double py, double dlo, double dhi)
{
    rs_hit2 hv;
    if (eval_vertex(pc, j, px, py, &hv) && hv.dist >= dlo && hv.dist <= dhi)
        put_hit(o, nh++, pt, &hv);
    return nh;
}

/* Face contact of LINE segment k (its projection is interior) into slot nh when its
 * distance lies in [dlo, dhi]; returns the new count. */
RS_INLINE int put_line(const pout *o, int nh, int k, const rs_pseg *q, int pt, double wx,
                       double wy, double sd, int two, double dlo, double dhi)
{
    const int flip = two && sd < 0.0;
    const double dist = flip ? -sd : sd;
    if (!(dist >= dlo && dist <= dhi))
        return nh;
    double tau = (wx * q->e[0] + wy * q->e[1]) * q->inv_len2;
    tau = tau < 0.0 ? 0.0 : tau > 1.0 ? 1.0 : tau;
    o->point[nh] = pt;
    o->feature[nh] = RS_FEATURE(RS_FEAT_FACE, k);
    o->x0[nh] = q->o[0] + tau * q->e[0];
    o->x1[nh] = q->o[1] + tau * q->e[1];
    o->n0[nh] = flip ? -q->nl[0] : q->nl[0];
    o->n1[nh] = flip ? -q->nl[1] : q->nl[1];
    o->dist[nh] = dist;
    o->kap[nh] = 0.0;
    return nh + 1;
}

/* The nk contacts rs_pcache_hits left in sc->hits, of point pt, into slots nh onwards
 * (room reserved); returns the new count. */
static int put_found(const pout *o, int nh, int pt, const rs_pscratch *sc, int nk)
{
    for (int k = 0; k < nk; k++)
        put_hit(o, nh + k, pt, &sc->hits[k]);
    return nh + nk;
}

/* The contacts of one point by rs_pcache_hits into slots nh onwards (room reserved);
 * returns the new count. For the stored form, whose scratch holds every segment, so
 * that it never grows (rs_pcache_hits >= 0). Out of line: the walks' slow path, kept
 * out of their loops. */
static RS_NOINLINE int put_hits(const rs_pcache *pc, const pout *o, int nh, int pt,
                                double px, double py, double dlo, double dhi,
                                rs_pscratch *sc)
{
    return put_found(o, nh, pt, sc, rs_pcache_hits(pc, px, py, dlo, dhi, sc));
}

/* Points searched per pre-pass of rs_pcache_points. */
enum { PP_SUB = 64 };

/* Per point: a pre-pass over a run of points finds each one's reach and its bucket's
 * list (offsets into boff), then one pass per point walks the near segments in profile
 * order, each followed at once by its contacts (vertex k, segment k, closing vertex),
 * which is the order of rs_pcache_hits when no Voronoi pair can drop a face. A
 * penetrated face with one side (the Voronoi pass), the start vertex of a closed
 * profile (its other segment is the last near one) and, in a profile of more than
 * RS_PC_SCAN segments, a reach beyond the last level (the tree's walk) hand the point to
 * rs_pcache_hits. */
/* Vertex k, the start of segment k (prev: the near segment before k in the list, -1
 * for none): emitted when the segment before it is near too, or when it starts an open
 * profile. Returns 1, having emitted nothing, for the start vertex of a closed profile,
 * whose segment before comes last in the list; the per-point path handles that one. */
RS_INLINE int start_vertex(const rs_pcache *pc, const pout *o, int *nh, int k, int prev,
                           int pt, double px, double py, double dlo, double dhi)
{
    const int sa = pc->pv[k].sa;
    if (sa >= 0 && k == 0)
        return 1;
    if (sa < 0 || prev == sa)
        *nh = put_vertex(pc, o, *nh, k, pt, px, py, dlo, dhi);
    return 0;
}

/* The face contact of LINE segment q for m points, as put_line computes it, with what[j]
 * = 1 when point j gets it (owned on its particle side, or either side with two, and
 * within [dlo, dhi]), 0 when the point is owned but out of range, -1 when the segment
 * does not own it. Branch-free, so it vectorises. */
RS_MULTIVERSION static void line_faces(const rs_pseg *q, int two, double dlo, int m,
                                       const double *restrict pu, const double *restrict pv,
                                       const double *restrict ph, double *restrict fx0,
                                       double *restrict fx1, double *restrict fn0,
                                       double *restrict fn1, double *restrict fd,
                                       double *restrict what)
{
    const rs_pseg s = *q; /* a local copy: its fields stay in registers */
    for (int j = 0; j < m; j++)
        rs_line_face1(&s, two, dlo, pu[j], pv[j], ph[j], &fx0[j], &fx1[j], &fn0[j], &fn1[j],
                      &fd[j], &what[j]);
}

/* rs_pcache_points for a profile of one LINE (a plane, a cylinder's mantle, a cone):
 * no bucket to choose and no list to walk. A point the segment owns (profile.h) on its
 * particle side (or either side with SIDES=2) gets the face contact, within [dlo, dhi];
 * the reach and box tests of the general walk follow from that. Every other point (an
 * end vertex's region, behind a one-sided face) takes the per-point rs_pcache_hits.
 * Per run of points, one branch-free loop computes the ownership and the face contact
 * of every point (as put_line does), then one loop writes the kept ones out. */
static int points_one_line(const rs_pcache *pc, const rs_ppoints *pts, int i,
                           rs_contacts *out, rs_pscratch *sc, int *need)
{
    const rs_pseg *q = &pc->ps[0];
    const int m = pts->n, two = pc->sides == 2, cap = out->cap, base = pts->base;
    const double dlo = pts->dlo;
    const int feat = RS_FEATURE(RS_FEAT_FACE, 0);
    const pout o = {out->point,  out->feature, out->xm[0], out->xm[1],
                    out->nrm[0], out->nrm[1],  out->dist,  out->curv[0]};
    const int room = 3; /* the face and the two end vertices */
    double fx0[PP_SUB], fx1[PP_SUB], fn0[PP_SUB], fn1[PP_SUB], fd[PP_SUB];
    double what[PP_SUB]; /* 1: face contact, 0: none, -1: per-point path */
    int nh = out->n;
    while (i < m) {
        const int c = m - i < PP_SUB ? m - i : PP_SUB;
        line_faces(q, two, dlo, c, pts->u + i, pts->v + i, pts->dhi + i, fx0, fx1, fn0, fn1,
                   fd, what);
        /* Every point of the run a face contact, with room for all: straight copies. */
        int nf = 0;
        for (int j = 0; j < c; j++)
            nf += what[j] > 0.0;
        if (nf == c && nh + c + room - 1 <= cap) {
            const size_t bytes = (size_t)c * sizeof(double);
            memcpy(o.x0 + nh, fx0, bytes);
            memcpy(o.x1 + nh, fx1, bytes);
            memcpy(o.n0 + nh, fn0, bytes);
            memcpy(o.n1 + nh, fn1, bytes);
            memcpy(o.dist + nh, fd, bytes);
            memset(o.kap + nh, 0, bytes); /* 0.0 */
            int *restrict op = o.point + nh, *restrict of = o.feature + nh;
            for (int j = 0; j < c; j++) {
                op[j] = base + i + j;
                of[j] = feat;
            }
            nh += c;
            i += c;
            continue;
        }
        int j = 0;
        for (; j < c; j++) {
            if (nh > cap - room) {
                *need = room;
                out->n = nh;
                return i + j;
            }
            if (what[j] > 0.0) {
                o.point[nh] = base + i + j;
                o.feature[nh] = feat;
                o.x0[nh] = fx0[j];
                o.x1[nh] = fx1[j];
                o.n0[nh] = fn0[j];
                o.n1[nh] = fn1[j];
                o.dist[nh] = fd[j];
                o.kap[nh] = 0.0;
                nh++;
            } else if (what[j] < 0.0) {
                nh = put_hits(pc, &o, nh, base + i + j, pts->u[i + j], pts->v[i + j], dlo,
                              pts->dhi[i + j], sc);
            }
        }
        i += c;
    }
    out->n = nh;
    return i;
}

/* rs_pcache_points for the compact form: each point through rs_pcache_hits. */
static int points_each(const rs_pcache *pc, const rs_ppoints *pts, int i, rs_contacts *out,
                       rs_pscratch *sc, int *need)
{
    const pout o = {out->point,  out->feature, out->xm[0], out->xm[1],
                    out->nrm[0], out->nrm[1],  out->dist,  out->curv[0]};
    for (; i < pts->n; i++) {
        const int nk = rs_pcache_hits(pc, pts->u[i], pts->v[i], pts->dlo, pts->dhi[i], sc);
        if (nk < 0) {
            *need = -1; /* out of memory for the scratch */
            return i;
        }
        if (nk > out->cap - out->n) {
            *need = nk;
            return i;
        }
        out->n = put_found(&o, out->n, pts->base + i, sc, nk);
    }
    return i;
}

int rs_pcache_points(const rs_pcache *pc, const rs_ppoints *pts, int i, rs_contacts *out,
                     rs_pscratch *sc, int *need)
{
    if (!pc->ps)
        return points_each(pc, pts, i, out, sc, need);
    if (pc->nseg == 1 && pc->ps[0].type == RS_LINE)
        return points_one_line(pc, pts, i, out, sc, need);
    const int n = pc->nseg, m = pts->n, two = pc->sides == 2, cap = out->cap;
    const double dlo = pts->dlo, lo = pc->lo, inv_w = pc->inv_w;
    const double top = (double)(pc->nbucket - 1);
    const int base = pts->base;
    const rs_pseg *ps = pc->ps;
    const int *const boff = pc->boff;
    const int all = pc->all_at;
    const double *const pu = pts->u, *const pv = pts->v, *const pdh = pts->dhi;
    const double *const pax = pc->axis ? pv : pu;
    const pout o = {out->point,  out->feature, out->xm[0], out->xm[1],
                    out->nrm[0], out->nrm[1],  out->dist,  out->curv[0]};
    double lreach = -1.0; /* the reach whose level was chosen last */
    const int *bs = NULL, *bc = NULL;
    int nh = out->n;
    double rch[PP_SUB];
    int bkt[PP_SUB], lb[PP_SUB], le[PP_SUB], lc[PP_SUB];
    while (i < m) {
        const int i1 = m - i < PP_SUB ? m : i + PP_SUB, c = i1 - i;
        /* reach and bucket of each point (branch-free); bkt < 0 skips the point */
        {
            const double *restrict dh = pdh + i, *restrict ax = pax + i;
            for (int j = 0; j < c; j++) {
                const double dhi = dh[j];
                const double reach = (two || dhi > -dlo) ? dhi : -dlo;
                const double f = (ax[j] - lo) * inv_w;
                const double fb = f > 0.0 ? (f < top ? f : top) : 0.0;
                const int ok = dhi >= dlo && reach >= 0.0;
                rch[j] = reach;
                bkt[j] = ok ? (int)fb : -1;
            }
        }
        /* each point's list; the points that fit in out as its lists bound them (each
         * near segment gives at most its start vertex, itself and the closing vertex) */
        int stop = c, bound = nh;
        for (int j = 0; j < c; j++) {
            const int b = bkt[j];
            if (b < 0) {
                lb[j] = le[j] = 0;
                continue;
            }
            if (rch[j] != lreach) {
                int l = 0;
                while (l < pc->nlevel && pc->margin[l] < rch[j])
                    l++;
                bs = l < pc->nlevel ? pc->bstart + (size_t)l * (size_t)(pc->nbucket + 1)
                                    : NULL;
                bc = l < pc->nlevel ? pc->bchain + (size_t)l * (size_t)pc->nbucket : NULL;
                lreach = rch[j];
            }
            /* beyond the last level: every segment, walked here in a small profile, else
             * by the per-point path's tree (-1) with room for every segment */
            lb[j] = bs ? bs[b] : all;
            le[j] = bs ? bs[b + 1] : all + n;
            lc[j] = bc ? bc[b] : n > RS_PC_SCAN ? -1 : 0;
            bound += 2 * (le[j] - lb[j]) + 1;
            if (bound > cap) {
                stop = j;
                break;
            }
        }
        for (int j = 0; j < stop; j++) {
            const int *list = boff + lb[j], *const end = boff + le[j];
            if (list == end)
                continue;
            const double px = pu[i + j], py = pv[i + j], dhi = pdh[i + j], reach = rch[j];
            const int k0 = nh, pt = base + i + j;
            int prev = -1, slow = 0;
            if (lc[j] < 0) {
                nh = put_hits(pc, &o, nh, pt, px, py, dlo, dhi, sc);
                continue;
            }
            if (lc[j]) {
                /* A LINE chain (rs_pcache_build): the face that owns the point, on its
                 * particle side (either side with SIDES=2), is its only contact; a
                 * point no face owns, or behind a one-sided face, takes the per-point
                 * path. The face contact is the walk's (put_line). */
                for (; list < end; list++) {
                    const rs_pseg *q = (const rs_pseg *)((const char *)ps + *list);
                    if (lc[j] >= 2) {
                        q = ps + (lc[j] - 2); /* the bucket's owner (chain_owner) */
                    } else {
                        int in_start, in_end;
                        rs_pseg_owns(q, px, py, &in_start, &in_end);
                        if (!(in_start && in_end))
                            continue;
                    }
                    const double wx = px - q->o[0], wy = py - q->o[1];
                    const double sd = wx * q->nl[0] + wy * q->nl[1];
                    if (two || sd >= 0.0)
                        nh = put_line(&o, nh, q->self, q, pt, wx, wy, sd, two, dlo, dhi);
                    else
                        slow = 1;
                    break;
                }
                slow |= list == end;
            }
            for (; !lc[j] && list < end; list++) {
                const rs_pseg *q = (const rs_pseg *)((const char *)ps + *list);
                const int k = q->self;
                if (box_far(q->box, px, py, reach))
                    continue;
                if (q->type == RS_LINE) {
                    /* The vertex tests of a segment are its ends' (profile.h): when the
                     * start test holds, vertex k cannot own the point, nor can the
                     * closing vertex when the end test holds. */
                    const double wx = px - q->o[0], wy = py - q->o[1];
                    const double sd = wx * q->nl[0] + wy * q->nl[1];
                    if (fabs(sd) > reach)
                        continue;
                    int in_start, in_end;
                    rs_pseg_owns(q, px, py, &in_start, &in_end);
                    const int hit = in_start && in_end;
                    if (hit && !two && sd < 0.0) {
                        slow = 1;
                        break;
                    }
                    if (!in_start && q->vtx_start &&
                        start_vertex(pc, &o, &nh, k, prev, pt, px, py, dlo, dhi)) {
                        slow = 1;
                        break;
                    }
                    if (hit)
                        nh = put_line(&o, nh, k, q, pt, wx, wy, sd, two, dlo, dhi);
                    if (!in_end && q->vtx_end)
                        nh = put_vertex(pc, &o, nh, n, pt, px, py, dlo, dhi);
                    prev = k;
                    continue;
                }
                if (!seg_near(q, px, py, reach))
                    continue;
                rs_hit2 h;
                const int hit = rs_pseg_curve(pc, q, px, py, &h);
                if (hit && !two && h.dist < 0.0) {
                    slow = 1;
                    break;
                }
                if (q->vtx_start &&
                    start_vertex(pc, &o, &nh, k, prev, pt, px, py, dlo, dhi)) {
                    slow = 1;
                    break;
                }
                if (hit && h.dist >= dlo && h.dist <= dhi)
                    put_hit(&o, nh++, pt, &h);
                if (q->vtx_end)
                    nh = put_vertex(pc, &o, nh, n, pt, px, py, dlo, dhi);
                prev = k;
            }
            if (slow)
                nh = put_hits(pc, &o, k0, pt, px, py, dlo, dhi, sc);
        }
        i += stop;
        if (stop < c) {
            /* the bound is loose: stop only when this point's own room is lacking */
            const int room = 2 * (le[stop] - lb[stop]) + 1;
            if (nh > cap - room) {
                *need = room;
                break;
            }
        }
    }
    out->n = nh;
    return i;
}
