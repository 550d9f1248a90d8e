/* Closest features of a profile in its plane: the ownership rules of profile.h. */
#include "profile.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

enum { SEG_UNSEEN = 0, SEG_NONE = 1, SEG_HIT = 2 };
#define SEG_NEAR 4
#define SEG_DROP 8

static void seg_end_tangent(const rs_segment *g, int at_end, double t[2])
{
    double x[2], k;
    if (g->type == RS_CIRCL) {
        const double *p = at_end ? g->p1 : g->p0;
        double r[2] = {p[0] - g->pm[0], p[1] - g->pm[1]};
        double rl = hypot(r[0], r[1]), s = g->sweep > 0.0 ? 1.0 : -1.0;
        t[0] = -s * r[1] / rl;
        t[1] = s * r[0] / rl;
        return;
    }
    rs_segment_eval(g, at_end ? 1.0 : 0.0, x, t, &k);
}

static void normalize2(double v[2])
{
    double l = hypot(v[0], v[1]);
    v[0] /= l;
    v[1] /= l;
}

int rs_pcache_build(const rs_surface *s, rs_pcache **out, rs_error *err)
{
    const rs_profile *p = &s->profile;
    int n = p->nseg;
    *out = NULL;
    if (n < 1 || !p->seg)
        return rs_error_set(err, RS_ERR_ARG, "surface '%s' has no profile segments",
                            s->name);
    double size = rs_profile_size(p);
    const rs_segment *last = &p->seg[n - 1];
    int closed = p->vkind ? p->closed
                          : (n >= 2 && last->p1[0] == p->seg[0].p0[0] &&
                             last->p1[1] == p->seg[0].p0[1]);
    int nv = closed ? n : n + 1;
    size_t bytes =
        sizeof(rs_pcache) + (size_t)n * sizeof(rs_pseg) + (size_t)nv * sizeof(rs_pvert);
    unsigned char *blk = calloc(1, bytes);
    if (!blk)
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory for the query data");
    rs_pcache *pc = (rs_pcache *)blk;
    pc->ps = (rs_pseg *)(blk + sizeof(rs_pcache));
    pc->pv = (rs_pvert *)(blk + sizeof(rs_pcache) + (size_t)n * sizeof(rs_pseg));
    pc->nseg = n;
    pc->nvert = nv;
    pc->closed = closed;
    pc->sides = s->sides == 2 ? 2 : 1;
    pc->size = size;
    pc->seg = p->seg;
    for (int k = 0; k < n; k++) {
        const rs_segment *g = &p->seg[k];
        rs_pseg *q = &pc->ps[k];
        switch (g->type) {
        case RS_LINE:
            q->o[0] = g->p0[0];
            q->o[1] = g->p0[1];
            q->e[0] = g->p1[0] - g->p0[0];
            q->e[1] = g->p1[1] - g->p0[1];
            q->inv_len2 = 1.0 / (q->e[0] * q->e[0] + q->e[1] * q->e[1]);
            q->t[0] = q->e[0];
            q->t[1] = q->e[1];
            normalize2(q->t);
            q->bc[0] = 0.5 * (g->p0[0] + g->p1[0]);
            q->bc[1] = 0.5 * (g->p0[1] + g->p1[1]);
            q->br = 0.5 * hypot(q->e[0], q->e[1]);
            break;
        case RS_CIRCL:
            /* An arc under 180 degrees lies inside the circle on its chord (Thales). */
            q->sgn = g->sweep > 0.0 ? 1.0 : -1.0;
            q->o[0] = g->pm[0];
            q->o[1] = g->pm[1];
            q->rad = g->radius;
            q->bc[0] = 0.5 * (g->p0[0] + g->p1[0]);
            q->bc[1] = 0.5 * (g->p0[1] + g->p1[1]);
            q->br = 0.5 * hypot(g->p1[0] - g->p0[0], g->p1[1] - g->p0[1]);
            break;
        case RS_PARAB: {
            /* Bezier hull: p0, 2 pm - (p0 + p1)/2, p1. */
            double ctl[3][2];
            for (int i = 0; i < 2; i++) {
                q->B[i] = 0.5 * (g->p1[i] - g->p0[i]);
                q->C[i] = 0.5 * (g->p0[i] + g->p1[i]) - g->pm[i];
                ctl[0][i] = g->p0[i];
                ctl[1][i] = 2.0 * g->pm[i] - 0.5 * (g->p0[i] + g->p1[i]);
                ctl[2][i] = g->p1[i];
            }
            q->bc[0] = (ctl[0][0] + ctl[1][0] + ctl[2][0]) / 3.0;
            q->bc[1] = (ctl[0][1] + ctl[1][1] + ctl[2][1]) / 3.0;
            for (int i = 0; i < 3; i++)
                q->br = fmax(q->br, hypot(ctl[i][0] - q->bc[0], ctl[i][1] - q->bc[1]));
            break;
        }
        }
        q->br = q->br * (1.0 + 1e-12) + 1e-12 * size;
    }
    for (int j = 0; j < nv; j++) {
        rs_pvert *v = &pc->pv[j];
        v->sa = j > 0 ? j - 1 : (closed ? n - 1 : -1);
        v->sb = j < n ? j : -1;
        const double *pos = v->sb >= 0 ? p->seg[v->sb].p0 : p->seg[v->sa].p1;
        v->v[0] = pos[0];
        v->v[1] = pos[1];
        if (v->sa >= 0)
            seg_end_tangent(&p->seg[v->sa], 1, v->ta);
        if (v->sb >= 0)
            seg_end_tangent(&p->seg[v->sb], 0, v->tb);
        if (v->sa < 0 || v->sb < 0) {
            v->kind = RS_VTX_END;
        } else if (p->vkind && j < p->nvert) {
            v->kind = p->vkind[j];
        } else {
            double c = v->ta[0] * v->tb[1] - v->ta[1] * v->tb[0];
            double d = v->ta[0] * v->tb[0] + v->ta[1] * v->tb[1];
            double ang = atan2(c, d);
            v->kind = fabs(ang) <= RS_SMOOTH_ANGLE           ? RS_VTX_SMOOTH
                      : fabs(ang) >= RS_PI - RS_SMOOTH_ANGLE ? RS_VTX_CONVEX
                      : ang > 0.0                            ? RS_VTX_CONCAVE
                                                             : RS_VTX_CONVEX;
        }
        if (v->kind == RS_VTX_SMOOTH) {
            double t[2] = {v->ta[0] + v->tb[0], v->ta[1] + v->tb[1]};
            normalize2(t);
            v->ta[0] = v->tb[0] = t[0];
            v->ta[1] = v->tb[1] = t[1];
        }
        v->na[0] = -v->ta[1];
        v->na[1] = v->ta[0];
        v->nb[0] = -v->tb[1];
        v->nb[1] = v->tb[0];
        if (v->sa < 0) {
            v->nfb[0] = v->nb[0];
            v->nfb[1] = v->nb[1];
        } else if (v->sb < 0) {
            v->nfb[0] = v->na[0];
            v->nfb[1] = v->na[1];
        } else {
            double b[2] = {v->na[0] + v->nb[0], v->na[1] + v->nb[1]};
            if (hypot(b[0], b[1]) > 1e-6) {
                normalize2(b);
            } else {
                b[0] = v->ta[0];
                b[1] = v->ta[1];
            }
            v->nfb[0] = b[0];
            v->nfb[1] = b[1];
        }
        v->seg_owns_edge = s->kind == RS_SURF_REVOLUTION && v->kind == RS_VTX_END &&
                           fabs(v->v[0]) <= 1e-12 * size;
    }
    *out = pc;
    return RS_OK;
}

size_t rs_pscratch_bytes(const rs_pcache *pc)
{
    size_t n = (size_t)pc->nseg, nv = (size_t)pc->nvert;
    size_t ints = (2 * n + nv) * sizeof(unsigned) + n;
    ints = (ints + 15) & ~(size_t)15;
    return ints + 4 * nv * sizeof(double) + (2 * n + nv) * sizeof(rs_hit2) + 64;
}

int rs_pscratch_init(rs_pscratch *sc, const rs_pcache *pc, void *stack, size_t stack_bytes)
{
    size_t need = rs_pscratch_bytes(pc);
    unsigned char *m = stack;
    sc->heap = NULL;
    if (!m || stack_bytes < need) {
        m = malloc(need);
        if (!m)
            return RS_ERR_NOMEM;
        sc->heap = m;
    }
    uintptr_t a = ((uintptr_t)m + 15u) & ~(uintptr_t)15u;
    m = (unsigned char *)a;
    size_t n = (size_t)pc->nseg, nv = (size_t)pc->nvert;
    size_t ints = (2 * n + nv) * sizeof(unsigned) + n;
    ints = (ints + 15) & ~(size_t)15;
    sc->seg_stamp = (unsigned *)m;
    sc->vtx_stamp = sc->seg_stamp + n;
    sc->near = (int *)(sc->vtx_stamp + nv);
    sc->seg_state = (unsigned char *)(sc->near + n);
    sc->vd = (double *)(m + ints);
    sc->cand = (rs_hit2 *)(m + ints + 4 * nv * sizeof(double));
    sc->hits = sc->cand + n;
    memset(sc->seg_stamp, 0, (n + nv) * sizeof(unsigned));
    sc->stamp = 0;
    return RS_OK;
}

void rs_pscratch_free(rs_pscratch *sc)
{
    free(sc->heap);
    sc->heap = NULL;
}

/* Segment state for the current point (0 when not yet touched). */
static inline unsigned seg_st(const rs_pscratch *sc, int k)
{
    return sc->seg_stamp[k] == sc->stamp ? sc->seg_state[k] : 0u;
}

static inline void seg_set(rs_pscratch *sc, int k, unsigned v)
{
    sc->seg_stamp[k] = sc->stamp;
    sc->seg_state[k] = (unsigned char)v;
}

static inline const double *vtx_tests(const rs_pcache *pc, rs_pscratch *sc, int j,
                                      double px, double py)
{
    double *o = sc->vd + 4 * j;
    if (sc->vtx_stamp[j] != sc->stamp) {
        const rs_pvert *v = &pc->pv[j];
        double dx = px - v->v[0], dy = py - v->v[1];
        o[0] = dx;
        o[1] = dy;
        o[2] = dx * v->ta[0] + dy * v->ta[1];
        o[3] = dx * v->tb[0] + dy * v->tb[1];
        sc->vtx_stamp[j] = sc->stamp;
    }
    return o;
}

/* f'(xi)/1 = (X(xi) - P).X'(xi) = a3 xi^3 + a2 xi^2 + a1 xi + a0 */
static inline double cubic(const double a[4], double x)
{
    return ((a[3] * x + a[2]) * x + a[1]) * x + a[0];
}

static inline double dcubic(const double a[4], double x)
{
    return (3.0 * a[3] * x + 2.0 * a[2]) * x + a[1];
}

/* Root of the cubic in (lo, hi) with cubic < 0 at lo and > 0 at hi: Newton steps kept
 * inside the bracket, bisection when a step leaves it, to full precision. */
static double cubic_root(const double a[4], double lo, double hi)
{
    double x = 0.5 * (lo + hi);
    for (int it = 0; it < 200; it++) {
        double f = cubic(a, x);
        if (f == 0.0)
            return x;
        if (f < 0.0)
            lo = x;
        else
            hi = x;
        double df = dcubic(a, x), xn = df != 0.0 ? x - f / df : lo;
        if (!(xn > lo && xn < hi))
            xn = 0.5 * (lo + hi);
        if (xn == x || hi - lo <= 2.0 * DBL_EPSILON * fmax(fabs(lo), fabs(hi)) ||
            hi - lo <= DBL_MIN)
            return xn;
        x = xn;
    }
    return x;
}

/* Closest interior point of a PARAB. The signs of the cubic at xi = -1 and xi = 1 come
 * from the vertex tests (in_start: decreasing at -1; in_end: increasing at 1) so that
 * segment and vertex ownership agree exactly. Returns 0 when no interior minimum. */
static int parab_min(const rs_segment *g, const rs_pseg *q, double px, double py,
                     int in_start, int in_end, double *xi_out)
{
    double D[2] = {g->pm[0] - px, g->pm[1] - py};
    const double *B = q->B, *C = q->C;
    double a[4];
    a[3] = 2.0 * (C[0] * C[0] + C[1] * C[1]);
    a[2] = 3.0 * (B[0] * C[0] + B[1] * C[1]);
    a[1] = (B[0] * B[0] + B[1] * B[1]) + 2.0 * (D[0] * C[0] + D[1] * C[1]);
    a[0] = D[0] * B[0] + D[1] * B[1];
    /* break points where the cubic turns: 3 a3 x^2 + 2 a2 x + a1 = 0 */
    double br[4];
    int nb = 0;
    br[nb++] = -1.0;
    double qa = 3.0 * a[3], qb = 2.0 * a[2], qc = a[1], r[2];
    int nr = 0;
    if (qa == 0.0) {
        if (qb != 0.0)
            r[nr++] = -qc / qb;
    } else {
        double disc = qb * qb - 4.0 * qa * qc;
        if (disc > 0.0) {
            double qq = -0.5 * (qb + copysign(sqrt(disc), qb));
            r[nr++] = qq / qa;
            if (qq != 0.0)
                r[nr++] = qc / qq;
        }
    }
    if (nr == 2 && r[0] > r[1]) {
        double t = r[0];
        r[0] = r[1];
        r[1] = t;
    }
    for (int i = 0; i < nr; i++)
        if (r[i] > -1.0 && r[i] < 1.0)
            br[nb++] = r[i];
    br[nb++] = 1.0;
    double best = INFINITY, bxi = 0.0;
    int found = 0;
    for (int i = 0; i + 1 < nb; i++) {
        double l = br[i], h = br[i + 1];
        double fl = i == 0 ? (in_start ? -1.0 : 1.0) : cubic(a, l);
        double fh = i + 2 == nb ? (in_end ? 1.0 : -1.0) : cubic(a, h);
        if (!(fl < 0.0 && fh > 0.0))
            continue;
        double xi = cubic_root(a, l, h);
        double X0 = D[0] + xi * B[0] + xi * xi * C[0];
        double X1 = D[1] + xi * B[1] + xi * xi * C[1];
        double f = X0 * X0 + X1 * X1;
        if (f < best) {
            best = f;
            bxi = xi;
            found = 1;
        }
    }
    *xi_out = bxi;
    return found;
}

/* Candidate contact of segment k (before the side and distance filters). */
static void eval_seg(const rs_pcache *pc, rs_pscratch *sc, int k, double px, double py)
{
    int j0 = k, j1 = k + 1 == pc->nvert ? 0 : k + 1;
    const double *t0 = vtx_tests(pc, sc, j0, px, py);
    const double *t1 = vtx_tests(pc, sc, j1, px, py);
    const rs_pvert *v0 = &pc->pv[j0], *v1 = &pc->pv[j1];
    double dB = t0[3], dA = t1[2];
    int in_start =
        (v0->kind == RS_VTX_SMOOTH || v0->kind == RS_VTX_CONCAVE || v0->seg_owns_edge)
            ? dB >= 0.0
            : dB > 0.0;
    int in_end = v1->seg_owns_edge ? dA <= 0.0 : dA < 0.0;
    const rs_segment *g = &pc->seg[k];
    const rs_pseg *q = &pc->ps[k];
    rs_hit2 *h = &sc->cand[k];
    unsigned st = seg_st(sc, k) & SEG_NEAR;
    switch (g->type) {
    case RS_LINE: {
        if (!(in_start && in_end))
            goto none;
        double wx = px - g->p0[0], wy = py - g->p0[1];
        double tau = (wx * q->e[0] + wy * q->e[1]) * q->inv_len2;
        tau = tau < 0.0 ? 0.0 : tau > 1.0 ? 1.0 : tau;
        h->x[0] = g->p0[0] + tau * q->e[0];
        h->x[1] = g->p0[1] + tau * q->e[1];
        h->n[0] = -q->t[1];
        h->n[1] = q->t[0];
        h->dist = wx * h->n[0] + wy * h->n[1];
        h->kappa = 0.0;
        break;
    }
    case RS_CIRCL: {
        if (!(in_start && in_end))
            goto none;
        double wx = px - g->pm[0], wy = py - g->pm[1], rho = sqrt(wx * wx + wy * wy), ux,
               uy;
        if (rho > 0.0) {
            ux = wx / rho;
            uy = wy / rho;
        } else {
            double th = g->ang0 + 0.5 * g->sweep;
            ux = cos(th);
            uy = sin(th);
        }
        h->x[0] = g->pm[0] + g->radius * ux;
        h->x[1] = g->pm[1] + g->radius * uy;
        /* n points to the centre when the sweep is counter-clockwise */
        h->n[0] = -q->sgn * ux;
        h->n[1] = -q->sgn * uy;
        h->dist = q->sgn * (g->radius - rho);
        h->kappa = -q->sgn / g->radius;
        break;
    }
    default: {
        double xi;
        if (!parab_min(g, q, px, py, in_start, in_end, &xi))
            goto none;
        double d[2] = {q->B[0] + 2.0 * xi * q->C[0], q->B[1] + 2.0 * xi * q->C[1]};
        double sp = sqrt(d[0] * d[0] + d[1] * d[1]);
        h->x[0] = g->pm[0] + xi * q->B[0] + xi * xi * q->C[0];
        h->x[1] = g->pm[1] + xi * q->B[1] + xi * xi * q->C[1];
        h->n[0] = -d[1] / sp;
        h->n[1] = d[0] / sp;
        h->dist = (px - h->x[0]) * h->n[0] + (py - h->x[1]) * h->n[1];
        /* signed curvature > 0 turning toward n (a pocket); the wall convention is
         * the opposite sign */
        h->kappa = -2.0 * (d[0] * q->C[1] - d[1] * q->C[0]) / (sp * sp * sp);
        break;
    }
    }
    if (pc->sides == 2 && h->dist < 0.0) {
        h->dist = -h->dist;
        h->n[0] = -h->n[0];
        h->n[1] = -h->n[1];
        h->kappa = -h->kappa;
    }
    h->feature = RS_FEATURE(RS_FEAT_FACE, k);
    seg_set(sc, k, st | SEG_HIT);
    return;
none:
    seg_set(sc, k, st | SEG_NONE);
}

static inline int seg_hit(const rs_pscratch *sc, int k)
{
    return (seg_st(sc, k) & 3) == SEG_HIT;
}

/* Vertex contact of vertex j, if it owns the point. */
static int eval_vertex(const rs_pcache *pc, rs_pscratch *sc, int j, double px, double py,
                       rs_hit2 *h)
{
    const rs_pvert *v = &pc->pv[j];
    if (v->kind == RS_VTX_SMOOTH)
        return 0;
    const double *t = vtx_tests(pc, sc, j, px, py);
    double dx = t[0], dy = t[1], dA = t[2], dB = t[3], sign = 1.0;
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

/* Behind a convex vertex only the face with the smaller penetration keeps its contact
 * (the Voronoi region of the solid); ties keep the lower index. */
static void voronoi_pair(const rs_pcache *pc, rs_pscratch *sc, int j, double px, double py)
{
    const rs_pvert *v = &pc->pv[j];
    if (v->kind != RS_VTX_CONVEX || v->sa < 0 || v->sb < 0 || v->sa == v->sb)
        return;
    int A = v->sa, B = v->sb;
    if (!(seg_st(sc, A) & 3))
        eval_seg(pc, sc, A, px, py);
    if (!(seg_st(sc, B) & 3))
        eval_seg(pc, sc, B, px, py);
    if (!seg_hit(sc, A) || !seg_hit(sc, B))
        return;
    double da = sc->cand[A].dist, db = sc->cand[B].dist;
    if (!(da < 0.0 || db < 0.0))
        return;
    int drop = (da < db || (da == db && A > B)) ? A : B;
    sc->seg_state[drop] |= SEG_DROP;
}

int rs_pcache_hits(const rs_pcache *pc, double px, double py, double dlo, double dhi,
                   rs_pscratch *sc)
{
    int n = pc->nseg, nh = 0, nnear = 0;
    double reach = (pc->sides == 2 || dhi > -dlo) ? dhi : -dlo;
    if (!(reach >= 0.0) || dlo > dhi)
        return 0;
    if (++sc->stamp == 0) {
        memset(sc->seg_stamp, 0, (size_t)(n + pc->nvert) * sizeof(unsigned));
        sc->stamp = 1;
    }
    /* A segment is within reach when the point is inside its bounding circle grown by
     * reach and, for LINE and CIRCL, within reach of its line or circle. Its vertices
     * lie on both, so a vertex is within reach only if both its segments are. */
    for (int k = 0; k < n; k++) {
        const rs_pseg *q = &pc->ps[k];
        double dx = px - q->bc[0], dy = py - q->bc[1], rr = q->br + reach;
        if (dx * dx + dy * dy > rr * rr)
            continue;
        int type = pc->seg[k].type;
        if (type == RS_LINE) {
            double sd = (px - q->o[0]) * (-q->t[1]) + (py - q->o[1]) * q->t[0];
            if (fabs(sd) > reach)
                continue;
        } else if (type == RS_CIRCL) {
            double wx = px - q->o[0], wy = py - q->o[1], r2 = wx * wx + wy * wy;
            double hi = q->rad + reach, lo = q->rad - reach;
            if (r2 > hi * hi || (lo > 0.0 && r2 < lo * lo))
                continue;
        }
        sc->near[nnear++] = k;
        seg_set(sc, k, SEG_NEAR);
    }
    if (nnear == 0)
        return 0;
    for (int i = 0; i < nnear; i++)
        eval_seg(pc, sc, sc->near[i], px, py);
    if (pc->sides == 1) {
        for (int i = 0; i < nnear; i++) {
            int k = sc->near[i];
            if (!seg_hit(sc, k) || !(sc->cand[k].dist < 0.0))
                continue;
            voronoi_pair(pc, sc, k, px, py);
            voronoi_pair(pc, sc, k + 1 == pc->nvert ? 0 : k + 1, px, py);
        }
    }
    for (int i = 0; i < nnear; i++) {
        int k = sc->near[i];
        /* vertex k (the start of segment k) is within reach when both its segments are */
        const rs_pvert *v = &pc->pv[k];
        if (v->sa < 0 || (seg_st(sc, v->sa) & SEG_NEAR)) {
            rs_hit2 *h = &sc->hits[nh];
            if (eval_vertex(pc, sc, k, px, py, h) && h->dist >= dlo && h->dist <= dhi)
                nh++;
        }
        if ((seg_st(sc, k) & (3 | SEG_DROP)) == SEG_HIT) {
            const rs_hit2 *c = &sc->cand[k];
            if (c->dist >= dlo && c->dist <= dhi)
                sc->hits[nh++] = *c;
        }
        if (k == n - 1 && !pc->closed) {
            rs_hit2 *h = &sc->hits[nh];
            if (eval_vertex(pc, sc, n, px, py, h) && h->dist >= dlo && h->dist <= dhi)
                nh++;
        }
    }
    return nh;
}
