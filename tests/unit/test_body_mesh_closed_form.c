/* What a body's query on a MESH answers in closed form, against the general path: a core
 * point on its pair's face (rs_surface_ops.feature_point, rs_mesh_feature_point) is the
 * point query's contact of that face bit for bit, wherever it answers; every body's
 * manifold (the 7 built-in shapes and two hulls, random poses, flat, folded, one-sided and
 * moved meshes) is the same bit for bit with the closed form as without it; and a hull's
 * support and farthest vertices (the climb and the best-first walk over its vertex graph)
 * are those of a scan of every vertex. */
#include "convex_geometry/convex_internal.h"
#include "rigidsurf/convex.h"
#include "rigidsurf/motion.h"
#include "rigidsurf/surface.h"
#include "rigidsurf/vec.h"
#define RS_TEST_SEED 0xBB67AE8584CAA73Bull
#include "rs_test.h"
#include "test_bodies.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { NMESH = 7 };

/* Mesh k: 0 a floor of two triangles; 1 a tilted grid; 2 a vee (concave fold); 3 a
 * ridge (convex fold); 4 the grid one-sided; 5 the vee one-sided; 6 a closed box. Grids
 * of 2 x 8 x 8 triangles over [-0.02, 0.02]^2. */
static int make_mesh(int k, rs_surface *s)
{
    static double xyz[3 * 100];
    static int tri[3 * 128];
    int nv = 0, nt = 0;
    if (k == 0) {
        const double f[12] = {-10, -10, 0, 10, -10, 0, 10, 10, 0, -10, 10, 0};
        const int t[6] = {0, 1, 2, 0, 2, 3};
        memcpy(xyz, f, sizeof f), memcpy(tri, t, sizeof t);
        nv = 4, nt = 2;
    } else if (k == 6) {
        const double h = 0.02;
        for (int v = 0; v < 8; v++, nv++) {
            xyz[3 * v] = (v & 1) ? h : -h;
            xyz[3 * v + 1] = (v & 2) ? h : -h;
            xyz[3 * v + 2] = (v & 4) ? h : -h;
        }
        const int t[36] = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                           2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
        memcpy(tri, t, sizeof t);
        nt = 12;
    } else {
        const int n = 8, kind = k == 2 || k == 5 ? 1 : k == 3 ? 2 : 0;
        for (int j = 0; j <= n; j++)
            for (int i = 0; i <= n; i++, nv++) {
                const double x = -0.02 + 0.04 * i / n, y = -0.02 + 0.04 * j / n;
                xyz[3 * nv] = x;
                xyz[3 * nv + 1] = y;
                xyz[3 * nv + 2] = kind == 1   ? 0.3 * fabs(x)
                                  : kind == 2 ? -0.3 * fabs(x)
                                              : 0.05 * x + 0.02 * y;
            }
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
                const int q[6] = {a, b, d, a, d, c}, r[6] = {a, b, c, b, d, c};
                memcpy(tri + 3 * nt, (i + j) & 1 ? q : r, sizeof q);
                nt += 2;
            }
    }
    rs_mesh_def def = RS_MESH_DEF_INIT;
    def.sides = k == 4 || k == 5 || k == 6 ? 1 : 0;
    rs_error e;
    rs_error_clear(&e);
    return rs_surface_make_mesh(xyz, nv, tri, nt, &def, s, &e);
}

/* The surface's height under (x, y) where a body is dropped: 0 for the floor and the box's
 * top (z = 0.02 there), the grids' own. */
static double ground(int k, double x, double y)
{
    switch (k) {
    case 0:
        return 0.0;
    case 2:
    case 5:
        return 0.3 * fabs(x);
    case 3:
        return -0.3 * fabs(x);
    case 6:
        return 0.02;
    default:
        return 0.05 * x + 0.02 * y;
    }
}

static void moved_pose(rs_pose *p)
{
    rs_pose_identity(p);
    const double a = 0.3;
    p->R[0] = cos(a), p->R[1] = -sin(a), p->R[3] = sin(a), p->R[4] = cos(a);
    p->T[0] = 0.001, p->T[1] = -0.0005, p->T[2] = 0.002;
}

/* Points near each mesh, with and without a pose: wherever feature_point answers for a
 * face, the point query gives that face exactly one contact, with the same numbers; a
 * random face it answers for is among the query's. */
static void test_feature_point_is_the_point_query(void)
{
    int answered = 0, declined = 0;
    for (int k = 0; k < NMESH; k++) {
        rs_surface s;
        ENSURE(make_mesh(k, &s) == RS_OK);
        ENSURE(s.ops->feature_point != NULL);
        for (int moved = 0; moved < 2; moved++) {
            rs_pose pose;
            moved_pose(&pose);
            for (int i = 0; i < 3000; i++) {
                double x[3] = {urange(-0.025, 0.025), urange(-0.025, 0.025), 0.0};
                x[2] = ground(k, x[0], x[1]) + urange(-0.004, 0.006);
                if (k == 6 && i % 2)
                    x[2] = urange(-0.025, 0.025),
                    x[i % 4 == 1 ? 0 : 1] = urange(0.014, 0.024);
                const double r = urange(0.0, 0.003), gap = urange(0.0, 0.02);
                rs_query q;
                memset(&q, 0, sizeof q);
                q.n = 1;
                q.slave.x = x, q.slave.y = x + 1, q.slave.z = x + 2, q.slave.radius = &r;
                q.pose = moved ? &pose : NULL;
                q.gap_max = gap;
                q.dist_min = -gap;
                rs_contacts c;
                memset(&c, 0, sizeof c);
                rs_error e;
                rs_error_clear(&e);
                ENSURE(s.ops->closest(&s, &q, &c, &e) == RS_OK);
                /* each face the query gives, and a random face */
                for (int j = 0; j <= c.n; j++) {
                    const int f = j < c.n ? RS_FEATURE_BASE(c.feature[j])
                                          : RS_FEATURE(RS_FEAT_FACE, (int)(urand() * 200));
                    if (RS_FEATURE_TYPE(f) != RS_FEAT_FACE)
                        continue;
                    double dist, xm[3], n[3], t1[3], t2[3];
                    if (!s.ops->feature_point(&s, q.pose, f, x, r, gap, gap, &dist, xm, n,
                                              t1, t2)) {
                        declined++;
                        continue;
                    }
                    answered++;
                    int hits = 0, at = -1;
                    for (int m = 0; m < c.n; m++)
                        if (RS_FEATURE_BASE(c.feature[m]) == f)
                            hits++, at = m;
                    ENSURE(hits == 1);
                    ENSURE(test_same_bits(dist, c.dist[at]));
                    for (int d = 0; d < 3; d++) {
                        ENSURE(test_same_bits(xm[d], c.xm[d][at]));
                        ENSURE(test_same_bits(n[d], c.nrm[d][at]));
                        ENSURE(t1[d] == 0.0 && t2[d] == 0.0); /* the frame follows n */
                    }
                }
                rs_contacts_free(&c);
            }
        }
        rs_surface_free(&s);
    }
    ENSURE(answered > 5000);
    ENSURE(declined > 500);
}

/* Every contact of a block of bodies (all fields, bit for bit) with the kind's closed form
 * and with the point query alone (the same kind without feature_point). */
static void test_manifold_is_the_general_paths(void)
{
    enum { N = 150 };
    int contacts = 0;
    for (int k = 0; k < NMESH; k++) {
        rs_surface s;
        ENSURE(make_mesh(k, &s) == RS_OK);
        rs_surface_ops general = *s.ops;
        general.feature_point = NULL;
        rs_surface g = s; /* the same mesh data, the general path */
        g.ops = &general;
        for (int moved = 0; moved < 2; moved++) {
            rs_pose pose;
            moved_pose(&pose);
            for (int sh = 0; sh < TEST_NSHAPE; sh++) {
                rs_shape shape;
                ENSURE(test_make_shape(sh, &shape) == RS_OK);
                rs_body b[N];
                double zero[N], radius[N];
                for (int i = 0; i < N; i++) {
                    double q[4],
                        x0[3] = {urange(-0.025, 0.025), urange(-0.025, 0.025), 0.0};
                    random_unit_quaternion(q);
                    ENSURE(rs_body_init(b + i, &shape, 1000.0, x0, q, NULL) == RS_OK);
                    const double down[3] = {0, 0, -1};
                    double low[3];
                    rs_body_support(b + i, down, low);
                    b[i].x[2] += ground(k, x0[0], x0[1]) - low[2] + urange(-0.002, 0.0005) +
                                 (moved ? 0.002 : 0.0);
                    zero[i] = 0.0;
                    radius[i] = 0.005;
                }
                rs_query q;
                memset(&q, 0, sizeof q);
                q.n = N;
                q.slave.x = zero, q.slave.y = zero, q.slave.z = zero;
                q.slave.radius = radius;
                q.slave.body = b;
                q.pose = moved ? &pose : NULL;
                q.gap_max = 5e-4;
                q.dist_min = -INFINITY;
                rs_contacts ca, cb;
                memset(&ca, 0, sizeof ca), memset(&cb, 0, sizeof cb);
                ca.witness = cb.witness = 1;
                rs_error e;
                rs_error_clear(&e);
                ENSURE(rs_surface_query(&s, &q, &ca, &e) == RS_OK);
                ENSURE(rs_surface_query(&g, &q, &cb, &e) == RS_OK);
                test_same_contacts(&ca, &cb);
                contacts += ca.n;
                rs_contacts_free(&ca), rs_contacts_free(&cb);
                rs_shape_free(&shape);
            }
        }
        rs_surface_free(&s);
    }
    ENSURE(contacts > 10000);
}

/* The scan: the highest d.v (first of ties) and all vertices sorted by d.v, then index. */
static int scan_support(const rs_shape *s, const double d[3], double *best)
{
    int at = 0;
    *best = -INFINITY;
    for (int i = 0; i < s->nv; i++) {
        const double p = rs_dot3(s->verts + 3 * i, d);
        if (p > *best)
            *best = p, at = i;
    }
    return at;
}

static const double *sort_key;
static int by_key(const void *a, const void *b)
{
    const int i = *(const int *)a, j = *(const int *)b;
    return sort_key[i] > sort_key[j]   ? -1
           : sort_key[i] < sort_key[j] ? 1
                                       : (i > j) - (i < j);
}

/* Hulls of points on an ellipsoid (100 to 10^4 points: climbed) and on the rims of a
 * prism's caps (many coplanar vertices: ties along its axis): the climb's vertex is as far
 * along d as the scan's, the same vertex where no other is as far; the best-first walk's 31
 * farthest are the scan's order. Directions at random, along the axes and the cube's cell
 * borders, with parts of 1e-300 and zero. */
static void test_hull_support_is_the_scan(void)
{
    const int sizes[4] = {100, 1000, 10000, 3000};
    for (int h = 0; h < 4; h++) {
        const int np = sizes[h], prism = h == 3;
        double *xyz = malloc(3 * (size_t)np * sizeof *xyz);
        ENSURE(xyz != NULL);
        for (int i = 0; i < np; i++) {
            if (prism) { /* on the rims of a prism's two caps: coplanar vertices */
                const double ph = urange(0, 2 * RS_PI);
                xyz[3 * i] = cos(ph);
                xyz[3 * i + 1] = sin(ph);
                xyz[3 * i + 2] = i % 2 ? 1.0 : -1.0;
            } else {
                const double z = urange(-1, 1), ph = urange(0, 2 * RS_PI),
                             r = sqrt(1 - z * z);
                xyz[3 * i] = 0.005 * r * cos(ph);
                xyz[3 * i + 1] = 0.003 * r * sin(ph);
                xyz[3 * i + 2] = 0.004 * z;
            }
        }
        rs_shape s;
        rs_error e;
        rs_error_clear(&e);
        ENSURE(rs_shape_make_polyhedron(&s, xyz, np, 0.0, &e) == RS_OK);
        free(xyz);
        ENSURE(s.nv > RS_HULL_SCAN);
        double *key = malloc((size_t)s.nv * sizeof *key);
        int *order = malloc((size_t)s.nv * sizeof *order);
        ENSURE(key && order);
        for (int t = 0; t < 1500; t++) {
            double d[3];
            if (t < 27) { /* the 26 axes and diagonals (and the zero direction's) */
                const int m = t == 13 ? 22 : t;
                d[0] = m % 3 - 1.0, d[1] = (m / 3) % 3 - 1.0, d[2] = m / 9 - 1.0;
            } else if (t < 200) { /* on cells' borders: parts k / 4 of the largest */
                const int a = t % 3;
                d[a] = t % 2 ? 1.0 : -1.0;
                d[(a + 1) % 3] = (int)urange(-4, 5) / 4.0;
                d[(a + 2) % 3] = t % 5 ? (int)urange(-4, 5) / 4.0 : 1e-300;
            } else {
                for (int k = 0; k < 3; k++)
                    d[k] = urange(-1, 1);
            }
            double best;
            const int want = scan_support(&s, d, &best);
            const int got = rs_hull_support(&s, d);
            ENSURE(got >= 0 && got < s.nv);
            ENSURE(rs_dot3(s.verts + 3 * got, d) == best);
            int ties = 0;
            for (int i = 0; i < s.nv; i++) {
                key[i] = rs_dot3(s.verts + 3 * i, d);
                ties += key[i] == best;
                order[i] = i;
            }
            if (ties == 1)
                ENSURE(got == want);
            if (prism)
                continue; /* ties: the walk's order among them is its own */
            sort_key = key;
            qsort(order, (size_t)s.nv, sizeof *order, by_key);
            int far[RS_HULL_FARTHEST_MAX];
            const int nf = rs_hull_farthest(&s, d, 31, far);
            ENSURE(nf == 31);
            for (int k = 0; k < nf; k++)
                ENSURE(far[k] == order[k]);
        }
        free(key), free(order);
        rs_shape_free(&s);
    }
}

int main(void)
{
    RS_RUN(test_feature_point_is_the_point_query);
    RS_RUN(test_manifold_is_the_general_paths);
    RS_RUN(test_hull_support_is_the_scan);
    return rs_test_summary();
}
