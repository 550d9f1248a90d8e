/* CGAL's convex hull behind a C interface (cgal_hull.h). Exceptions never cross into
 * C. The kernel is Epick: the hull's orientation tests are exact, its points are the
 * input points. */
#include "cgal_hull.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>
#include <vector>

namespace
{

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;

/* Four points that span a volume, by exact orientation tests: false when every point
 * lies in one plane. */
bool spans_volume(const std::vector<Point> &p)
{
    const std::size_t n = p.size();
    std::size_t i1 = 1, i2, i3;
    while (i1 < n && p[i1] == p[0])
        i1++;
    if (i1 >= n)
        return false;
    for (i2 = i1 + 1; i2 < n; i2++)
        if (!CGAL::collinear(p[0], p[i1], p[i2]))
            break;
    if (i2 >= n)
        return false;
    for (i3 = i2 + 1; i3 < n; i3++)
        if (CGAL::orientation(p[0], p[i1], p[i2], p[i3]) != CGAL::COPLANAR)
            return true;
    return false;
}

} // namespace

extern "C" int rs_cgal_convex_hull(const double *xyz, int n, double **verts, int *nv,
                                   int **tris, int *nt, char *msg, size_t cap)
{
    *verts = nullptr;
    *tris = nullptr;
    *nv = *nt = 0;
    if (n < 4) {
        std::snprintf(msg, cap, "%d points (expected at least 4 that are not coplanar)", n);
        return -1;
    }
    try {
        std::vector<Point> pts;
        pts.reserve((std::size_t)n);
        for (int i = 0; i < n; i++) {
            const double *q = xyz + 3 * (std::size_t)i;
            if (!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2])) {
                std::snprintf(msg, cap,
                              "point %d is not finite (expected finite coordinates)",
                              i + 1);
                return -1;
            }
            pts.emplace_back(q[0], q[1], q[2]);
        }
        if (!spans_volume(pts)) {
            std::snprintf(
                msg, cap,
                "the %d points lie in one plane (expected at least 4 that are not "
                "coplanar)",
                n);
            return -1;
        }
        Mesh hull;
        CGAL::convex_hull_3(pts.begin(), pts.end(), hull);
        const std::size_t nvx = hull.number_of_vertices(), nf = hull.number_of_faces();
        double *v = (double *)std::malloc(3 * nvx * sizeof(double));
        int *t = (int *)std::malloc(3 * nf * sizeof(int));
        if (!v || !t) {
            std::free(v);
            std::free(t);
            std::snprintf(msg, cap, "out of memory for a hull of %zu vertices", nvx);
            return -1;
        }
        std::vector<int> index(hull.num_vertices(), -1);
        int k = 0;
        for (Mesh::Vertex_index vi : hull.vertices()) {
            const Point &p = hull.point(vi);
            v[3 * k] = p.x();
            v[3 * k + 1] = p.y();
            v[3 * k + 2] = p.z();
            index[(std::size_t)vi] = k++;
        }
        int f = 0;
        for (Mesh::Face_index fi : hull.faces()) {
            int c = 0;
            for (Mesh::Vertex_index vi :
                 CGAL::vertices_around_face(hull.halfedge(fi), hull)) {
                if (c < 3)
                    t[3 * f + c] = index[(std::size_t)vi];
                c++;
            }
            if (c != 3) {
                std::free(v);
                std::free(t);
                std::snprintf(msg, cap,
                              "the hull has a face of %d corners (expected triangles)", c);
                return -1;
            }
            f++;
        }
        *verts = v;
        *tris = t;
        *nv = k;
        *nt = f;
        return 0;
    } catch (const std::bad_alloc &) {
        std::snprintf(msg, cap, "out of memory for the hull of %d points", n);
    } catch (const std::exception &e) {
        std::snprintf(msg, cap, "the hull of %d points failed: %s", n, e.what());
    }
    return -1;
}
