/* GJK's distance between two convex cores (gjk.h). Debian's libccd 2.1 answers whether
 * shapes overlap and how deeply, not how far apart they are: this is the distance. */
#include "gjk.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <string.h>

enum { GJK_MAX_ITER = 256 };

typedef struct gjk_vertex {
    double w[3], pa[3], pb[3];
} gjk_vertex;

void rs_cvx_support(const rs_cvx *c, const double d[3], double out[3])
{
    if (!c->shape) {
        int best = 0;
        double bd = rs_dot3(c->tri, d);
        for (int i = 1; i < 3; i++) {
            const double p = rs_dot3(c->tri + 3 * i, d);
            if (p > bd) {
                bd = p;
                best = i;
            }
        }
        memcpy(out, c->tri + 3 * best, 3 * sizeof *out);
        return;
    }
    const double *R = c->R;
    double db[3], p[3];
    for (int i = 0; i < 3; i++)
        db[i] = R[i] * d[0] + R[3 + i] * d[1] + R[6 + i] * d[2];
    rs_shape_core_support(c->shape, db, p);
    rs_matvec3(R, p, out);
    for (int k = 0; k < 3; k++)
        out[k] += c->x[k];
}

static void lincomb(const gjk_vertex *s, const double *lam, int n, gjk_vertex *o)
{
    memset(o, 0, sizeof *o);
    for (int i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) {
            o->w[k] += lam[i] * s[i].w[k];
            o->pa[k] += lam[i] * s[i].pa[k];
            o->pb[k] += lam[i] * s[i].pb[k];
        }
}

/* The closest point to the origin of the segment or triangle s[0..n), its weights lam
 * (zero for the vertices whose Voronoi region it is not in). */
static void closest_segment(const gjk_vertex *s, double lam[2])
{
    double ab[3];
    for (int k = 0; k < 3; k++)
        ab[k] = s[1].w[k] - s[0].w[k];
    const double l2 = rs_dot3(ab, ab);
    double t = l2 > 0.0 ? -rs_dot3(s[0].w, ab) / l2 : 0.0;
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    lam[0] = 1.0 - t;
    lam[1] = t;
}

static double dist2_of(const gjk_vertex *s, const double *lam, int n)
{
    gjk_vertex o;
    lincomb(s, lam, n, &o);
    return rs_dot3(o.w, o.w);
}

static void closest_triangle(const gjk_vertex *s, double lam[3])
{
    const double *a = s[0].w, *b = s[1].w, *c = s[2].w;
    double ab[3], ac[3];
    for (int k = 0; k < 3; k++) {
        ab[k] = b[k] - a[k];
        ac[k] = c[k] - a[k];
    }
    /* Voronoi regions of the corners, edges and face (Ericson, Real-Time Collision
     * Detection, 5.1.5), for the point at the origin */
    const double d1 = -rs_dot3(ab, a), d2 = -rs_dot3(ac, a);
    const double d3 = -rs_dot3(ab, b), d4 = -rs_dot3(ac, b);
    const double d5 = -rs_dot3(ab, c), d6 = -rs_dot3(ac, c);
    const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
    lam[0] = lam[1] = lam[2] = 0.0;
    if (d1 <= 0.0 && d2 <= 0.0) {
        lam[0] = 1.0;
    } else if (d3 >= 0.0 && d4 <= d3) {
        lam[1] = 1.0;
    } else if (d6 >= 0.0 && d5 <= d6) {
        lam[2] = 1.0;
    } else if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        lam[1] = d1 / (d1 - d3);
        lam[0] = 1.0 - lam[1];
    } else if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        lam[2] = d2 / (d2 - d6);
        lam[0] = 1.0 - lam[2];
    } else if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
        lam[2] = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        lam[1] = 1.0 - lam[2];
    } else if (va + vb + vc > 0.0) {
        const double den = 1.0 / (va + vb + vc);
        lam[1] = vb * den;
        lam[2] = vc * den;
        lam[0] = 1.0 - lam[1] - lam[2];
    } else { /* a degenerate triangle: its best edge */
        double best = INFINITY;
        for (int e = 0; e < 3; e++) {
            const gjk_vertex seg[2] = {s[e], s[(e + 1) % 3]};
            double l2[2], l3[3] = {0.0, 0.0, 0.0};
            closest_segment(seg, l2);
            l3[e] = l2[0];
            l3[(e + 1) % 3] = l2[1];
            const double d = dist2_of(s, l3, 3);
            if (d < best) {
                best = d;
                memcpy(lam, l3, sizeof l3);
            }
        }
    }
}

static double det3(const double a[3], const double b[3], const double c[3])
{
    double bc[3];
    rs_cross3(b, c, bc);
    return rs_dot3(a, bc);
}

/* The tetrahedron: 1 when the origin is inside, else its closest point's weights. */
static int closest_tetrahedron(const gjk_vertex *s, double lam[4])
{
    static const int face[4][4] = {{0, 1, 2, 3}, {0, 3, 1, 2}, {0, 2, 3, 1}, {1, 3, 2, 0}};
    double best = INFINITY;
    int outside = 0;
    for (int f = 0; f < 4; f++) {
        const double *a = s[face[f][0]].w, *b = s[face[f][1]].w, *c = s[face[f][2]].w,
                     *d = s[face[f][3]].w;
        double ab[3], ac[3], ad[3], ao[3];
        for (int k = 0; k < 3; k++) {
            ab[k] = b[k] - a[k];
            ac[k] = c[k] - a[k];
            ad[k] = d[k] - a[k];
            ao[k] = -a[k];
        }
        const double sd = det3(ab, ac, ad), so = det3(ab, ac, ao);
        if (sd != 0.0 && so * sd > 0.0)
            continue; /* the origin is on d's side of this face */
        outside = 1;
        const gjk_vertex tri[3] = {s[face[f][0]], s[face[f][1]], s[face[f][2]]};
        double l3[3], l4[4] = {0.0, 0.0, 0.0, 0.0};
        closest_triangle(tri, l3);
        for (int i = 0; i < 3; i++)
            l4[face[f][i]] = l3[i];
        const double dd = dist2_of(s, l4, 4);
        if (dd < best) {
            best = dd;
            memcpy(lam, l4, sizeof l4);
        }
    }
    return !outside;
}

/* Keeps the vertices of positive weight; returns how many. */
static int reduce(gjk_vertex *s, const double *lam, int n)
{
    int m = 0;
    for (int i = 0; i < n; i++)
        if (lam[i] > 0.0)
            s[m++] = s[i];
    return m;
}

void rs_gjk_distance(const rs_cvx *a, const rs_cvx *b, double stop, rs_gjk *res)
{
    gjk_vertex s[4];
    int n = 0;
    double v[3], vpa[3], vpb[3];
    memset(res, 0, sizeof *res);
    for (int k = 0; k < 3; k++)
        v[k] = a->x[k] - b->x[k];
    if (rs_dot3(v, v) == 0.0)
        v[0] = 1.0;
    const double scale = a->size + b->size + rs_norm3(v);
    int have = 0; /* v is a point of the Minkowski difference with witnesses */
    for (int it = 0; it < GJK_MAX_ITER; it++) {
        gjk_vertex w;
        const double mv[3] = {-v[0], -v[1], -v[2]};
        rs_cvx_support(a, mv, w.pa);
        rs_cvx_support(b, v, w.pb);
        for (int k = 0; k < 3; k++)
            w.w[k] = w.pa[k] - w.pb[k];
        const double vv = rs_dot3(v, v), vw = rs_dot3(v, w.w), nv = sqrt(vv);
        if (vw > 0.0 && vw > stop * nv) { /* a lower bound of the distance beyond stop */
            res->apart = 1;
            res->dist = vw / nv;
            return;
        }
        if (have && (vv - vw <= 1e-13 * vv || vv - vw <= 4e-16 * scale * nv))
            break;
        int dup = 0;
        for (int i = 0; i < n; i++)
            dup |= s[i].w[0] == w.w[0] && s[i].w[1] == w.w[1] && s[i].w[2] == w.w[2];
        if (dup && have)
            break;
        s[n++] = w;
        double lam[4] = {1.0, 0.0, 0.0, 0.0};
        if (n == 2)
            closest_segment(s, lam);
        else if (n == 3)
            closest_triangle(s, lam);
        else if (n == 4 && closest_tetrahedron(s, lam)) {
            res->overlap = 1;
            return;
        }
        gjk_vertex o;
        lincomb(s, lam, n, &o);
        n = reduce(s, lam, n);
        const double oo = rs_dot3(o.w, o.w);
        if (have && oo >= vv)
            break; /* no progress: v stays */
        memcpy(v, o.w, sizeof v);
        memcpy(vpa, o.pa, sizeof vpa);
        memcpy(vpb, o.pb, sizeof vpb);
        have = 1;
        if (oo <= 1e-30 * scale * scale) {
            res->overlap = 1;
            return;
        }
    }
    res->dist = rs_norm3(v);
    memcpy(res->pa, vpa, sizeof vpa);
    memcpy(res->pb, vpb, sizeof vpb);
}
