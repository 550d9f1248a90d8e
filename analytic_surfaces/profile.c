/* Profile geometry: segments, arc lengths, vertex kinds and fillets (docs/conventions.md,
 * "Profiles and surfaces"). */
#include "profile.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static double cross2(const double a[2], const double b[2])
{
    return a[0] * b[1] - a[1] * b[0];
}

static double dot2(const double a[2], const double b[2])
{
    return a[0] * b[0] + a[1] * b[1];
}

static double inf_norm2(const double a[2])
{
    return fmax(fabs(a[0]), fabs(a[1]));
}

static int too_large(const char *where, rs_error *err)
{
    return rs_error_set(err, RS_ERR_GEOMETRY,
                        "%s: coordinates too large (expected a segment of finite length)",
                        where);
}

int rs_segment_line(rs_segment *g, const double p0[2], const double p1[2],
                    const char *where, rs_error *err)
{
    double e[2] = {p1[0] - p0[0], p1[1] - p0[1]};
    double len = hypot(e[0], e[1]);
    double scale = fmax(inf_norm2(p0), inf_norm2(p1));
    if (!(len > 1e-12 * scale) || len == 0.0)
        return rs_error_set(err, RS_ERR_GEOMETRY,
                            "%s: zero-length LINE (expected an end point different from "
                            "the current point (%g, %g))",
                            where, p0[0], p0[1]);
    if (!isfinite(len))
        return too_large(where, err);
    memset(g, 0, sizeof *g);
    g->type = RS_LINE;
    memcpy(g->p0, p0, sizeof g->p0);
    memcpy(g->p1, p1, sizeof g->p1);
    g->length = len;
    return RS_OK;
}

int rs_segment_circl(rs_segment *g, const double p0[2], const double p1[2],
                     const double c[2], const char *where, rs_error *err)
{
    double r0v[2] = {p0[0] - c[0], p0[1] - c[1]};
    double r1v[2] = {p1[0] - c[0], p1[1] - c[1]};
    double r0 = hypot(r0v[0], r0v[1]), r1 = hypot(r1v[0], r1v[1]);
    double chord = hypot(p1[0] - p0[0], p1[1] - p0[1]);
    double scale = fmax(fmax(inf_norm2(p0), inf_norm2(p1)), inf_norm2(c));
    if (chord == 0.0 || !(chord > 1e-12 * scale))
        return rs_error_set(err, RS_ERR_GEOMETRY,
                            "%s: zero-length CIRCL (expected an end point different from "
                            "the current point (%g, %g))",
                            where, p0[0], p0[1]);
    if (r0 == 0.0 || !(r0 > 1e-12 * scale))
        return rs_error_set(err, RS_ERR_GEOMETRY,
                            "%s: CIRCL centre (%g, %g) coincides with its start point",
                            where, c[0], c[1]);
    if (fabs(r0 - r1) > RS_RADIUS_TOL * fmax(r0, r1))
        return rs_error_set(err, RS_ERR_GEOMETRY,
                            "%s: CIRCL radius mismatch: start point at %.17g and end point "
                            "at %.17g from the centre (expected equal within %g relative)",
                            where, r0, r1, RS_RADIUS_TOL);
    if (!isfinite(r0) || !isfinite(r1) || !isfinite(chord))
        return too_large(where, err);
    double sweep = atan2(cross2(r0v, r1v), dot2(r0v, r1v));
    if (fabs(sweep) > RS_PI - 1e-9)
        return rs_error_set(
            err, RS_ERR_GEOMETRY,
            "%s: CIRCL spans 180 degrees or more (expected an arc under 180 "
            "degrees; split it in two)",
            where);
    memset(g, 0, sizeof *g);
    g->type = RS_CIRCL;
    memcpy(g->p0, p0, sizeof g->p0);
    memcpy(g->p1, p1, sizeof g->p1);
    memcpy(g->pm, c, sizeof g->pm);
    g->radius = 0.5 * (r0 + r1);
    g->ang0 = atan2(r0v[1], r0v[0]);
    g->sweep = sweep;
    g->length = g->radius * fabs(sweep);
    return RS_OK;
}

/* X(xi) = pm + xi B + xi^2 C with B = (p1 - p0)/2, C = (p0 + p1 - 2 pm)/2. */
static void parab_coef(const rs_segment *g, double B[2], double C[2])
{
    for (int i = 0; i < 2; i++) {
        B[i] = 0.5 * (g->p1[i] - g->p0[i]);
        C[i] = 0.5 * (g->p0[i] + g->p1[i]) - g->pm[i];
    }
}

static double parab_speed(const double B[2], const double C[2], double xi)
{
    return hypot(B[0] + 2.0 * xi * C[0], B[1] + 2.0 * xi * C[1]);
}

/* Arc length of a PARAB: 20-point Gauss-Legendre on 2^m pieces, refined until two levels
 * agree to 1e-15 (the speed is smooth and bounded away from zero). */
static double parab_length(const double B[2], const double C[2])
{
    static const double x[10] = {0.0765265211334973337546404, 0.2277858511416450780804962,
                                 0.3737060887154195606725482, 0.5108670019508270980043641,
                                 0.6360536807265150254528367, 0.7463319064601507926143051,
                                 0.8391169718222188233945291, 0.9122344282513259058677524,
                                 0.9639719272779137912676661, 0.9931285991850949247861224};
    static const double w[10] = {0.1527533871307258506980843, 0.1491729864726037467878287,
                                 0.1420961093183820513292983, 0.1316886384491766268984945,
                                 0.1181945319615184173123774, 0.1019301198172404350367501,
                                 0.0832767415767047487247581, 0.0626720483341090635695065,
                                 0.0406014298003869413310400, 0.0176140071391521183118620};
    double prev = 0.0;
    for (int m = 0; m < 8; m++) {
        int np = 1 << m;
        double h = 2.0 / np, sum = 0.0;
        for (int p = 0; p < np; p++) {
            double mid = -1.0 + (p + 0.5) * h;
            for (int i = 0; i < 10; i++) {
                double dx = 0.5 * h * x[i];
                sum += 0.5 * h * w[i] *
                       (parab_speed(B, C, mid - dx) + parab_speed(B, C, mid + dx));
            }
        }
        if (m > 0 && fabs(sum - prev) <= 1e-15 * sum)
            return sum;
        prev = sum;
    }
    return prev;
}

int rs_segment_parab(rs_segment *g, const double p0[2], const double pm[2],
                     const double p1[2], const char *where, rs_error *err)
{
    double chord = hypot(p1[0] - p0[0], p1[1] - p0[1]);
    double scale = fmax(fmax(inf_norm2(p0), inf_norm2(p1)), inf_norm2(pm));
    if (chord == 0.0 || !(chord > 1e-12 * scale))
        return rs_error_set(err, RS_ERR_GEOMETRY,
                            "%s: zero-length PARAB (expected an end point different from "
                            "the current point (%g, %g))",
                            where, p0[0], p0[1]);
    memset(g, 0, sizeof *g);
    g->type = RS_PARAB;
    memcpy(g->p0, p0, sizeof g->p0);
    memcpy(g->p1, p1, sizeof g->p1);
    memcpy(g->pm, pm, sizeof g->pm);
    double B[2], C[2];
    parab_coef(g, B, C);
    /* The speed |X'| must not vanish on [-1, 1]: otherwise the curve doubles back. */
    double cc = dot2(C, C), smin;
    double xi = cc > 0.0 ? -dot2(B, C) / (2.0 * cc) : 0.0;
    xi = fmin(1.0, fmax(-1.0, xi));
    smin = parab_speed(B, C, xi);
    double smax = fmax(parab_speed(B, C, -1.0), parab_speed(B, C, 1.0));
    if (!(smin > 1e-8 * smax))
        return rs_error_set(err, RS_ERR_GEOMETRY,
                            "%s: degenerate PARAB: the curve doubles back (expected the "
                            "middle point (%g, %g) between the end points)",
                            where, pm[0], pm[1]);
    g->length = parab_length(B, C);
    if (!isfinite(g->length) || !isfinite(smax))
        return too_large(where, err);
    return RS_OK;
}

void rs_segment_eval(const rs_segment *g, double u, double x[2], double t[2], double *k)
{
    switch (g->type) {
    case RS_CIRCL: {
        double th = g->ang0 + u * g->sweep, s = g->sweep > 0.0 ? 1.0 : -1.0;
        double c = cos(th), sn = sin(th);
        x[0] = g->pm[0] + g->radius * c;
        x[1] = g->pm[1] + g->radius * sn;
        t[0] = -s * sn;
        t[1] = s * c;
        *k = s / g->radius;
        return;
    }
    case RS_PARAB: {
        double B[2], C[2], xi = 2.0 * u - 1.0;
        parab_coef(g, B, C);
        double d[2] = {B[0] + 2.0 * xi * C[0], B[1] + 2.0 * xi * C[1]};
        double sp = hypot(d[0], d[1]);
        x[0] = g->pm[0] + xi * B[0] + xi * xi * C[0];
        x[1] = g->pm[1] + xi * B[1] + xi * xi * C[1];
        t[0] = d[0] / sp;
        t[1] = d[1] / sp;
        *k = 2.0 * cross2(d, C) / (sp * sp * sp);
        return;
    }
    default: {
        double e[2] = {g->p1[0] - g->p0[0], g->p1[1] - g->p0[1]};
        double len = hypot(e[0], e[1]);
        x[0] = g->p0[0] + u * e[0];
        x[1] = g->p0[1] + u * e[1];
        t[0] = e[0] / len;
        t[1] = e[1] / len;
        *k = 0.0;
        return;
    }
    }
}

void rs_segment_end_tangent(const rs_segment *g, int at_end, double t[2])
{
    switch (g->type) {
    case RS_CIRCL: {
        const double *p = at_end ? g->p1 : g->p0;
        double r[2] = {p[0] - g->pm[0], p[1] - g->pm[1]};
        double rl = hypot(r[0], r[1]), s = g->sweep > 0.0 ? 1.0 : -1.0;
        t[0] = -s * r[1] / rl;
        t[1] = s * r[0] / rl;
        return;
    }
    case RS_PARAB: {
        double B[2], C[2], xi = at_end ? 1.0 : -1.0;
        parab_coef(g, B, C);
        double d[2] = {B[0] + 2.0 * xi * C[0], B[1] + 2.0 * xi * C[1]};
        double sp = hypot(d[0], d[1]);
        t[0] = d[0] / sp;
        t[1] = d[1] / sp;
        return;
    }
    default: {
        double e[2] = {g->p1[0] - g->p0[0], g->p1[1] - g->p0[1]};
        double len = hypot(e[0], e[1]);
        t[0] = e[0] / len;
        t[1] = e[1] / len;
        return;
    }
    }
}

double rs_profile_size(const rs_profile *p)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY}, far = 0.0;
    for (int k = 0; k < p->nseg; k++) {
        const rs_segment *g = &p->seg[k];
        const double *pts[3] = {g->p0, g->p1, g->pm};
        int npts = g->type == RS_LINE ? 2 : 3;
        for (int i = 0; i < npts; i++) {
            for (int d = 0; d < 2; d++) {
                lo[d] = fmin(lo[d], pts[i][d]);
                hi[d] = fmax(hi[d], pts[i][d]);
            }
            far = fmax(far, inf_norm2(pts[i]));
        }
    }
    if (p->nseg == 0)
        return 1.0;
    double size = fmax(fmax(hi[0] - lo[0], hi[1] - lo[1]), far);
    return size > 0.0 ? size : 1.0;
}

static int classify(const double ta[2], const double tb[2])
{
    double ang = atan2(cross2(ta, tb), dot2(ta, tb));
    if (fabs(ang) <= RS_SMOOTH_ANGLE)
        return RS_VTX_SMOOTH;
    if (fabs(ang) >= RS_PI - RS_SMOOTH_ANGLE)
        return RS_VTX_CONVEX; /* a spike: its tip bulges toward the particles */
    return ang > 0.0 ? RS_VTX_CONCAVE : RS_VTX_CONVEX;
}

int rs_profile_finish(rs_profile *p, const unsigned char *smooth, rs_error *err)
{
    int n = p->nseg;
    if (n < 1 || !p->seg)
        return rs_error_set(err, RS_ERR_ARG, "profile has no segments");
    double size = rs_profile_size(p);
    rs_segment *last = &p->seg[n - 1];
    double gap = hypot(last->p1[0] - p->seg[0].p0[0], last->p1[1] - p->seg[0].p0[1]);
    p->closed = n >= 2 && gap <= 1e-10 * size;
    if (p->closed && gap > 0.0) {
        /* Snap the end onto START so that vertex 0 is one point. */
        last->p1[0] = p->seg[0].p0[0];
        last->p1[1] = p->seg[0].p0[1];
        if (last->type == RS_CIRCL) {
            double r0v[2] = {last->p0[0] - last->pm[0], last->p0[1] - last->pm[1]};
            double r1v[2] = {last->p1[0] - last->pm[0], last->p1[1] - last->pm[1]};
            last->sweep = atan2(cross2(r0v, r1v), dot2(r0v, r1v));
            last->length = last->radius * fabs(last->sweep);
        }
    }
    double s = 0.0;
    for (int k = 0; k < n; k++) {
        p->seg[k].s0 = s;
        s += p->seg[k].length;
    }
    p->nvert = p->closed ? n : n + 1;
    int *vk = realloc(p->vkind, (size_t)p->nvert * sizeof *vk);
    if (!vk)
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory for %d vertices", p->nvert);
    p->vkind = vk;
    for (int j = 0; j < p->nvert; j++) {
        int sa = j > 0 ? j - 1 : (p->closed ? n - 1 : -1);
        int sb = j < n ? j : -1;
        if (sa < 0 || sb < 0) {
            vk[j] = RS_VTX_END;
            continue;
        }
        if (smooth && smooth[j]) {
            vk[j] = RS_VTX_SMOOTH;
            continue;
        }
        double ta[2], tb[2];
        rs_segment_end_tangent(&p->seg[sa], 1, ta);
        rs_segment_end_tangent(&p->seg[sb], 0, tb);
        vk[j] = classify(ta, tb);
    }
    return RS_OK;
}

void rs_profile_free(rs_profile *p)
{
    free(p->seg);
    free(p->vkind);
    memset(p, 0, sizeof *p);
}

/* ---- Fillets ----------------------------------------------------------------------- */

/* A segment moved by delta along its normal: a line (p, unit u) or a circle (c, R). */
typedef struct offset_curve {
    int circle;
    double p[2], u[2];
    double c[2], R;
} offset_curve;

static int make_offset(const rs_segment *g, double delta, offset_curve *o)
{
    memset(o, 0, sizeof *o);
    if (g->type == RS_LINE) {
        rs_segment_end_tangent(g, 0, o->u);
        o->p[0] = g->p0[0] - delta * o->u[1];
        o->p[1] = g->p0[1] + delta * o->u[0];
        return 1;
    }
    /* CIRCL: n points to the centre when the sweep is counter-clockwise. */
    double sgn = g->sweep > 0.0 ? 1.0 : -1.0;
    o->circle = 1;
    o->c[0] = g->pm[0];
    o->c[1] = g->pm[1];
    o->R = g->radius - sgn * delta;
    return o->R > 0.0;
}

/* Intersections of two offset curves; returns the count (0..2). */
static int intersect(const offset_curve *a, const offset_curve *b, double x[2][2])
{
    if (!a->circle && !b->circle) {
        double den = cross2(a->u, b->u);
        if (den == 0.0)
            return 0;
        double w[2] = {b->p[0] - a->p[0], b->p[1] - a->p[1]};
        double al = cross2(w, b->u) / den;
        x[0][0] = a->p[0] + al * a->u[0];
        x[0][1] = a->p[1] + al * a->u[1];
        return 1;
    }
    if (a->circle && !b->circle)
        return intersect(b, a, x);
    if (!a->circle) {
        /* |p + al u - c|^2 = R^2 with |u| = 1 */
        double w[2] = {a->p[0] - b->c[0], a->p[1] - b->c[1]};
        double hb = dot2(a->u, w), cc = dot2(w, w) - b->R * b->R;
        double disc = hb * hb - cc;
        if (disc < 0.0)
            return 0;
        double sq = sqrt(disc);
        double al[2] = {-hb - sq, -hb + sq};
        for (int i = 0; i < 2; i++) {
            x[i][0] = a->p[0] + al[i] * a->u[0];
            x[i][1] = a->p[1] + al[i] * a->u[1];
        }
        return 2;
    }
    double d[2] = {b->c[0] - a->c[0], b->c[1] - a->c[1]};
    double dl = hypot(d[0], d[1]);
    if (dl == 0.0)
        return 0;
    double along = (dl * dl + a->R * a->R - b->R * b->R) / (2.0 * dl);
    double h2 = a->R * a->R - along * along;
    if (h2 < 0.0)
        return 0;
    double h = sqrt(h2), e[2] = {d[0] / dl, d[1] / dl};
    for (int i = 0; i < 2; i++) {
        double sg = i == 0 ? -1.0 : 1.0;
        x[i][0] = a->c[0] + along * e[0] - sg * h * e[1];
        x[i][1] = a->c[1] + along * e[1] + sg * h * e[0];
    }
    return 2;
}

/* Foot of the fillet centre C on segment g (offset o) and its fraction along g. */
static double tangent_point(const rs_segment *g, const offset_curve *o, double delta,
                            const double C[2], double T[2])
{
    if (g->type == RS_LINE) {
        double n[2] = {-o->u[1], o->u[0]};
        T[0] = C[0] - delta * n[0];
        T[1] = C[1] - delta * n[1];
        double e[2] = {g->p1[0] - g->p0[0], g->p1[1] - g->p0[1]};
        return ((T[0] - g->p0[0]) * e[0] + (T[1] - g->p0[1]) * e[1]) / dot2(e, e);
    }
    double w[2] = {C[0] - g->pm[0], C[1] - g->pm[1]};
    T[0] = g->pm[0] + w[0] * (g->radius / o->R);
    T[1] = g->pm[1] + w[1] * (g->radius / o->R);
    double r0v[2] = {g->p0[0] - g->pm[0], g->p0[1] - g->pm[1]};
    double rt[2] = {T[0] - g->pm[0], T[1] - g->pm[1]};
    double ang = atan2(cross2(r0v, rt), dot2(r0v, rt));
    return ang / g->sweep;
}

typedef struct fillet_info {
    int on;
    double C[2], TA[2], TB[2];
} fillet_info;

int rs_profile_fillet(rs_profile *p, double r, int **line, const char *origin,
                      rs_error *err)
{
    int n = p->nseg, nv = p->nvert;
    if (!(r > 0.0))
        return rs_error_set(err, RS_ERR_ARG, "%s: FILLET RADIUS must be > 0", origin);
    fillet_info *fi = calloc((size_t)nv, sizeof *fi);
    double *f0 = malloc((size_t)n * sizeof *f0), *f1 = malloc((size_t)n * sizeof *f1);
    rs_segment *ns = NULL;
    int *nl = NULL;
    unsigned char *smooth = NULL;
    int rc = RS_OK, nfil = 0;
    if (!fi || !f0 || !f1) {
        rc = rs_error_set(err, RS_ERR_NOMEM, "out of memory");
        goto done;
    }
    for (int k = 0; k < n; k++) {
        f0[k] = 0.0;
        f1[k] = 1.0;
    }
    for (int j = 0; j < nv; j++) {
        int kind = p->vkind[j];
        if (kind != RS_VTX_CONVEX && kind != RS_VTX_CONCAVE)
            continue;
        int sa = j > 0 ? j - 1 : n - 1, sb = j;
        const rs_segment *A = &p->seg[sa], *B = &p->seg[sb];
        if (A->type == RS_PARAB || B->type == RS_PARAB)
            continue; /* corners touching a PARAB stay sharp */
        double s = kind == RS_VTX_CONCAVE ? 1.0 : -1.0, delta = s * r;
        const double *v = B->p0;
        int vline = (*line)[sa];
        offset_curve oa, ob;
        double X[2][2];
        int nx = 0;
        if (make_offset(A, delta, &oa) && make_offset(B, delta, &ob))
            nx = intersect(&oa, &ob, X);
        int best = -1;
        double bd = INFINITY;
        for (int i = 0; i < nx; i++) {
            double dd = hypot(X[i][0] - v[0], X[i][1] - v[1]);
            if (dd < bd) {
                bd = dd;
                best = i;
            }
        }
        double fa = -1.0, fb = -1.0, sweep = 0.0;
        fillet_info *f = &fi[j];
        if (best >= 0) {
            memcpy(f->C, X[best], sizeof f->C);
            fa = tangent_point(A, &oa, delta, f->C, f->TA);
            fb = tangent_point(B, &ob, delta, f->C, f->TB);
            double ra[2] = {f->TA[0] - f->C[0], f->TA[1] - f->C[1]};
            double rb[2] = {f->TB[0] - f->C[0], f->TB[1] - f->C[1]};
            sweep = atan2(cross2(ra, rb), dot2(ra, rb));
        }
        if (best < 0 || !(fa >= 0.0 && fa <= 1.0) || !(fb >= 0.0 && fb <= 1.0) ||
            !(sweep * s > 0.0) || fabs(sweep) > RS_PI - 1e-9) {
            rc = rs_error_set(err, RS_ERR_GEOMETRY,
                              "%s:%d: FILLET RADIUS=%g does not fit at vertex %d (%g, %g) "
                              "(expected a radius small enough for the adjacent segments)",
                              origin, vline, r, j, v[0], v[1]);
            goto done;
        }
        f->on = 1;
        f1[sa] = fa;
        f0[sb] = fb;
        nfil++;
    }
    for (int k = 0; k < n; k++) {
        if (!(f1[k] - f0[k] > 1e-9)) {
            int j = (k + 1) % nv;
            if (!fi[j].on)
                j = k;
            const double *v = j < n ? p->seg[j].p0 : p->seg[n - 1].p1;
            rc = rs_error_set(err, RS_ERR_GEOMETRY,
                              "%s:%d: FILLET RADIUS=%g does not fit at vertex %d (%g, %g) "
                              "(the fillets at both ends of segment %d overlap; expected a "
                              "smaller radius)",
                              origin, (*line)[k], r, j, v[0], v[1], k);
            goto done;
        }
    }
    if (nfil == 0)
        goto done;
    int m = n + nfil;
    ns = calloc((size_t)m, sizeof *ns);
    nl = malloc((size_t)m * sizeof *nl);
    smooth = calloc((size_t)m + 1, 1);
    if (!ns || !nl || !smooth) {
        rc = rs_error_set(err, RS_ERR_NOMEM, "out of memory");
        goto done;
    }
    char where[300];
    int o = 0;
    for (int k = 0; k < n; k++) {
        const rs_segment *g = &p->seg[k];
        int jend = (k + 1) % nv;
        const double *q0 = fi[k].on ? fi[k].TB : g->p0;
        const double *q1 = fi[jend].on ? fi[jend].TA : g->p1;
        snprintf(where, sizeof where, "%s:%d", origin, (*line)[k]);
        /* a PARAB keeps its ends: corners touching it stay sharp */
        rc = g->type == RS_LINE    ? rs_segment_line(&ns[o], q0, q1, where, err)
             : g->type == RS_CIRCL ? rs_segment_circl(&ns[o], q0, q1, g->pm, where, err)
                                   : rs_segment_parab(&ns[o], q0, g->pm, q1, where, err);
        if (rc)
            goto done;
        nl[o++] = (*line)[k];
        if (fi[jend].on) {
            rc = rs_segment_circl(&ns[o], fi[jend].TA, fi[jend].TB, fi[jend].C, where, err);
            if (rc)
                goto done;
            nl[o] = (*line)[k];
            smooth[o] = 1;
            smooth[(o + 1) % (p->closed ? m : m + 1)] = 1;
            o++;
        }
    }
    free(p->seg);
    p->seg = ns;
    p->nseg = m;
    ns = NULL;
    free(*line);
    *line = nl;
    nl = NULL;
    rc = rs_profile_finish(p, smooth, err);
done:
    free(fi);
    free(f0);
    free(f1);
    free(ns);
    free(nl);
    free(smooth);
    return rc;
}
