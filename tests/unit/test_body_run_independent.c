/* A body's contacts are a function of the body, the surface and the query's parameters
 * alone: every built-in shape (sphere, ellipsoid, box, rounded box, capsule, cylinder,
 * cone, a hull), each at two sizes whose reaches differ tenfold, in random poses in front
 * of the wall and behind it down to four reaches, gets bit for bit the same contacts in
 * blocks of mixed shapes and sizes (rs_surface_query, in two random orders) as alone
 * (rs_body_query, and a block of one), on a CYLINDER plane, a filleted trough, a filleted
 * REVOLUTION drum and a one-sided MESH tray. The fixed point and the manifold ask a
 * run's bodies at once over the widest window; a body's own window must decide what it
 * keeps. */
#include "rigidsurf/convex.h"
#include "rigidsurf/surface.h"
#include "rigidsurf/vec.h"
#define RS_TEST_SEED 0x3C6EF372FE94F82Bull
#include "rs_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { NSHAPE = 8, N = 320, GAP_MM = 2 };

/* The eight shapes at size a (a hull of 24 random points in a ball of radius a). */
static int make_shapes(double a, rs_shape *sh)
{
    rs_error e;
    double xyz[3 * 24];
    for (int k = 0; k < 24; k++) {
        double p[3], l;
        do {
            for (int d = 0; d < 3; d++)
                p[d] = urange(-1, 1);
            l = rs_norm3(p);
        } while (!(l > 0.2 && l <= 1.0));
        for (int d = 0; d < 3; d++)
            xyz[3 * k + d] = a * p[d];
    }
    return rs_shape_make_sphere(&sh[0], a, 0.0, &e) ||
           rs_shape_make_ellipsoid(&sh[1], a, 0.7 * a, 0.4 * a, 0.0, &e) ||
           rs_shape_make_box(&sh[2], a, 0.8 * a, 0.5 * a, 0.0, &e) ||
           rs_shape_make_box(&sh[3], 0.8 * a, 0.6 * a, 0.4 * a, 0.2 * a, &e) ||
           rs_shape_make_capsule(&sh[4], 0.5 * a, a, 0.0, &e) ||
           rs_shape_make_cylinder(&sh[5], 0.7 * a, a, 0.0, &e) ||
           rs_shape_make_cone(&sh[6], 0.8 * a, 1.6 * a, 0.0, &e) ||
           rs_shape_make_polyhedron(&sh[7], xyz, 24, 0.0, &e);
}

/* A MESH under construction: vertices (welded when it is made) and triangles. */
typedef struct soup {
    double xyz[3 * 4 * 256];
    int tri[3 * 2 * 256];
    int nv, nt;
} soup;

/* The quad a b c d as two triangles, turned so that its normal points toward in. */
static void add_quad(soup *m, double p[4][3], const double in[3])
{
    double u[3], v[3], n[3], w[3];
    for (int d = 0; d < 3; d++)
        u[d] = p[1][d] - p[0][d], v[d] = p[2][d] - p[0][d], w[d] = in[d] - p[0][d];
    rs_cross3(u, v, n);
    const int flip = rs_dot3(n, w) < 0.0, i0 = m->nv;
    for (int k = 0; k < 4; k++, m->nv++)
        memcpy(m->xyz + 3 * m->nv, p[flip ? 3 - k : k], 3 * sizeof(double));
    const int t[6] = {0, 1, 2, 0, 2, 3};
    for (int k = 0; k < 6; k++)
        m->tri[3 * m->nt + k] = i0 + t[k];
    m->nt += 2;
}

/* The tray: floor [-L, L]^2 at z = 0 and four walls up to H, each face a 3 x 3 grid of
 * quads, one-sided, its normals into the tray. */
enum { GRID = 3 };
static const double L = 0.5, H = 0.4;
static int tray(rs_surface *s)
{
    static soup m;
    m.nv = m.nt = 0;
    const double in[3] = {0.0, 0.0, 0.5 * H};
    for (int f = 0; f < 5; f++)
        for (int i = 0; i < GRID; i++)
            for (int j = 0; j < GRID; j++) {
                double p[4][3];
                for (int k = 0; k < 4; k++) {
                    const double a = (double)(i + (k == 1 || k == 2)) / GRID;
                    const double b = (double)(j + (k >= 2)) / GRID;
                    const double u = -L + 2.0 * L * a, hz = H * b, v = -L + 2.0 * L * b;
                    double *q = p[k];
                    if (f == 0)
                        q[0] = u, q[1] = v, q[2] = 0.0;
                    else if (f < 3)
                        q[0] = f == 1 ? -L : L, q[1] = u, q[2] = hz;
                    else
                        q[0] = u, q[1] = f == 3 ? -L : L, q[2] = hz;
                }
                add_quad(&m, p, in);
            }
    rs_mesh_def def = RS_MESH_DEF_INIT;
    def.sides = 1;
    return rs_surface_make_mesh(m.xyz, m.nv, m.tri, m.nt, &def, s, NULL);
}

/* A centre at signed distance t (< 0: behind) from surface p's wall, roughly along the
 * wall's normal. p: 0 plane z = 0, 1 trough (floor |x| < 0.2, sides at 45 degrees), 2 drum
 * (r 0.5, z in [-0.4, 0.4]), 3 tray. */
static void place(int p, double t, double x[3])
{
    if (p == 0 || p == 1) {
        x[0] = urange(-0.55, 0.55), x[1] = urange(-0.3, 0.3);
        const double side = fabs(x[0]) - 0.2;
        const int slope = p == 1 && side > 0.0; /* on a side: t along its normal */
        x[2] = (slope ? side : 0.0) + (slope ? sqrt(2.0) : 1.0) * t;
        return;
    }
    if (p == 2) {
        const double th = urange(0, 2 * RS_PI);
        if (urand() < 0.5) { /* the mantle, normal -e_r */
            const double r = 0.5 - t, z = urange(-0.38, 0.38);
            x[0] = r * cos(th), x[1] = r * sin(th), x[2] = z;
        } else { /* an end cap, normal into the drum */
            const double r = urange(0.0, 0.48), sg = urand() < 0.5 ? -1.0 : 1.0;
            x[0] = r * cos(th), x[1] = r * sin(th), x[2] = sg * (0.4 - t);
        }
        return;
    }
    const int f = (int)(5 * urand());
    const double u = urange(-0.48, 0.48), v = urange(0.02, 0.38);
    if (f == 0)
        x[0] = u, x[1] = urange(-0.48, 0.48), x[2] = t;
    else if (f < 3)
        x[0] = f == 1 ? -L + t : L - t, x[1] = u, x[2] = v;
    else
        x[0] = u, x[1] = f == 3 ? -L + t : L - t, x[2] = v;
}

/* Contacts [k0, k0 + n) of a against [j0, j0 + n) of b, bit for bit. */
static int same(const rs_contacts *a, int k0, const rs_contacts *b, int j0, int n)
{
    const size_t sz = (size_t)n * sizeof(double);
    int ok = memcmp(a->feature + k0, b->feature + j0, (size_t)n * sizeof(int)) == 0 &&
             memcmp(a->dist + k0, b->dist + j0, sz) == 0 &&
             memcmp(a->share + k0, b->share + j0, sz) == 0 &&
             memcmp(a->curv[0] + k0, b->curv[0] + j0, sz) == 0 &&
             memcmp(a->curv[1] + k0, b->curv[1] + j0, sz) == 0;
    for (int d = 0; d < 3; d++)
        ok &= memcmp(a->xm[d] + k0, b->xm[d] + j0, sz) == 0 &&
              memcmp(a->nrm[d] + k0, b->nrm[d] + j0, sz) == 0 &&
              memcmp(a->t1[d] + k0, b->t1[d] + j0, sz) == 0 &&
              memcmp(a->t2[d] + k0, b->t2[d] + j0, sz) == 0 &&
              memcmp(a->xs[d] + k0, b->xs[d] + j0, sz) == 0;
    return ok;
}

/* The block query of bodies b[ord[0 .. n)] (radius r), into c. */
static int block(const rs_surface *s, const rs_body *b, const double *r, const int *ord,
                 int n, rs_contacts *c)
{
    static rs_body bb[N];
    static double x[4 * N];
    double *y = x + N, *z = y + N, *rr = z + N;
    for (int k = 0; k < n; k++) {
        bb[k] = b[ord[k]];
        x[k] = bb[k].x[0], y[k] = bb[k].x[1], z[k] = bb[k].x[2], rr[k] = r[ord[k]];
    }
    rs_query q;
    memset(&q, 0, sizeof q);
    q.n = n;
    q.slave.x = x, q.slave.y = y, q.slave.z = z, q.slave.radius = rr;
    q.slave.body = bb;
    q.gap_max = GAP_MM * 1e-3;
    q.dist_min = -INFINITY;
    c->n = 0;
    return rs_surface_query(s, &q, c, NULL);
}

static void test_a_body_s_contacts_do_not_depend_on_its_block(void)
{
    static const char *SURF[3] = {
        "*SURFACE, TYPE=CYLINDER, NAME=plane\n0, 0, 0, 1, 0, 0\n0, -1, 0\n"
        "START, -10, 0\nLINE, 10, 0\n",
        "*SURFACE, TYPE=CYLINDER, NAME=trough, FILLET RADIUS=0.05\n0, 0, 0, 1, 0, 0\n"
        "0, -1, 0\nSTART, -0.6, 0.4\nLINE, -0.2, 0\nLINE, 0.2, 0\nLINE, 0.6, 0.4\n",
        "*SURFACE, TYPE=REVOLUTION, NAME=drum, FILLET RADIUS=0.05\n0, 0, 0, 0, 0, 1\n"
        "START, 0, -0.4\nLINE, 0.5, -0.4\nLINE, 0.5, 0.4\nLINE, 0, 0.4\n"};
    rs_shape sh[2][NSHAPE];
    ENSURE(make_shapes(0.004, sh[0]) == 0 && make_shapes(0.04, sh[1]) == 0);
    static rs_body b[N];
    static double r[N], tt[N];
    static int ord[N], inv[N], off[N + 1];
    rs_contacts all, one, solo;
    memset(&all, 0, sizeof all);
    memset(&one, 0, sizeof one);
    memset(&solo, 0, sizeof solo);
    all.witness = one.witness = solo.witness = 1;
    int bad = 0;
    for (int p = 0; p < 4; p++) {
        rs_surface s;
        rs_error e;
        ENSURE((p < 3 ? rs_surface_parse(SURF[p], "t", NULL, &s, &e) : tray(&s)) == RS_OK);
        long total = 0, deep = 0, mixed_deep = 0;
        for (int i = 0; i < N; i++) {
            const rs_shape *shape = &sh[urand() < 0.5][(int)(NSHAPE * urand()) % NSHAPE];
            double q[4], l = 0.0, x[3];
            for (int k = 0; k < 4; k++) {
                q[k] = urange(-1, 1);
                l += q[k] * q[k];
            }
            for (int k = 0; k < 4; k++)
                q[k] /= sqrt(l);
            tt[i] = urange(-4.0, 1.0);
            place(p, tt[i] * shape->reach, x);
            ENSURE(rs_body_init(b + i, shape, 1000.0, x, q, &e) == RS_OK);
            r[i] = shape->reach;
        }
        /* two random orders, in blocks of mixed shapes and sizes (runs of RS_BLOCK) */
        for (int o = 0; o < 2; o++) {
            for (int i = 0; i < N; i++)
                ord[i] = i;
            for (int i = N - 1; i > 0; i--) {
                const int j = (int)((i + 1) * urand()) % (i + 1), t = ord[i];
                ord[i] = ord[j], ord[j] = t;
            }
            for (int k = 0; k < N; k++)
                inv[ord[k]] = k;
            ENSURE(block(&s, b, r, ord, N, &all) == RS_OK);
            for (int k = 0, j = 0; k <= N; k++) { /* where slave k's contacts start */
                off[k] = j;
                while (k < N && j < all.n && all.point[j] == k)
                    j++;
            }
            ENSURE(off[N] == all.n);
            for (int i = 0; i < N; i++) {
                const int k = inv[i], nk = off[k + 1] - off[k];
                one.n = 0;
                ENSURE(rs_body_query(&s, NULL, b + i, k, r[i], GAP_MM * 1e-3, &one, &e) ==
                       RS_OK);
                const int ok = one.n == nk && same(&all, off[k], &one, 0, nk);
                if (!ok && bad++ < 8)
                    fprintf(stderr,
                            "surface %d, order %d: body %d (reach %g, centre %a %a %a) "
                            "has %d contacts in the block, %d alone\n",
                            p, o, i, b[i].shape->reach, b[i].x[0], b[i].x[1], b[i].x[2], nk,
                            one.n);
                if (o == 0) {
                    total += one.n;
                    /* a small body deeper than twice its reach in a run with a large one */
                    double lo = 0.0;
                    for (int j = 0; j < one.n; j++)
                        lo = fmin(lo, one.dist[j] - r[i]);
                    deep += one.n > 0 && lo < -b[i].shape->reach;
                    int big = 0;
                    for (int j = k - k % RS_BLOCK; j < N && j < k - k % RS_BLOCK + RS_BLOCK;
                         j++)
                        big |= b[ord[j]].shape->reach > 5.0 * b[i].shape->reach;
                    mixed_deep += big && tt[i] < -2.0;
                }
                /* a block of one (its slave number 0) */
                if (o == 0) {
                    ENSURE(block(&s, b, r, &i, 1, &solo) == RS_OK);
                    one.n = 0;
                    ENSURE(rs_body_query(&s, NULL, b + i, 0, r[i], GAP_MM * 1e-3, &one,
                                         &e) == RS_OK);
                    ENSURE(solo.n == one.n && same(&solo, 0, &one, 0, one.n));
                }
            }
        }
        ENSURE(bad == 0);
        /* the case is exercised: contacts, deep ones, and bodies deeper than twice their
         * reach in a run with a body of a reach at least five times theirs */
        ENSURE(total > N / 2 && deep > 10 && mixed_deep > 10);
        rs_surface_free(&s);
    }
    rs_contacts_free(&all);
    rs_contacts_free(&one);
    rs_contacts_free(&solo);
    for (int z = 0; z < 2; z++)
        for (int k = 0; k < NSHAPE; k++)
            rs_shape_free(&sh[z][k]);
}

int main(void)
{
    RS_RUN(test_a_body_s_contacts_do_not_depend_on_its_block);
    return rs_test_summary();
}
