/* CGAL's convex hull behind a C interface (cgal_hull.h). Exceptions never cross into
 * C. The kernel is Epick: the hull's orientation tests are exact, its points are the
 * input points. CGAL's quickhull walks the horizon in an order of memory addresses, so
 * the order of its vertices and how it splits a facet into triangles change from call
 * to call; the answer is made canonical here: the hull's extreme points sorted, each
 * facet (coplanar triangles, by exact tests) split as a fan from its least corner. */
#include "cgal_hull.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <vector>

namespace
{

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;

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

std::size_t root(std::vector<std::size_t> &g, std::size_t k)
{
    while (g[k] != k) {
        g[k] = g[g[k]];
        k = g[k];
    }
    return k;
}

typedef std::array<std::size_t, 3> Tri;

/* Is the triangle set (points p, triangles t) a closed hull: at least four points, every
 * index in range, each directed edge found again reversed? CGAL's quickhull takes points
 * whose orientation the exact tests see as a volume for coplanar when its inexact
 * constructions (a plane through denormal coordinates) lose them, and answers a polygon. */
bool closed(const std::vector<Point> &p, const std::vector<Tri> &t)
{
    if (p.size() < 4 || t.size() < 4)
        return false;
    std::vector<std::pair<std::size_t, std::size_t>> e;
    e.reserve(3 * t.size());
    for (const Tri &f : t)
        for (int j = 0; j < 3; j++) {
            if (f[j] >= p.size())
                return false;
            e.emplace_back(f[j], f[(j + 1) % 3]);
        }
    std::sort(e.begin(), e.end());
    for (const auto &ab : e)
        if (!std::binary_search(e.begin(), e.end(), std::make_pair(ab.second, ab.first)))
            return false;
    return true;
}

/* The hull (points p, triangles t, counter-clockwise seen from outside) as a canonical
 * list of vertices (sorted, extreme points only) and triangles (each facet a fan from its
 * least vertex, the triangles sorted). */
void canonical(const std::vector<Point> &p, const std::vector<Tri> &tin,
               std::vector<double> &verts, std::vector<int> &tris)
{
    const std::size_t nf = tin.size(), nv = p.size();
    /* counter-clockwise seen from outside: a vertex off the first triangle's plane lies
     * behind it (CGAL's hull of four points comes the other way) */
    std::vector<Tri> t = tin;
    for (std::size_t v = 0; v < nv; v++) {
        const CGAL::Orientation o =
            CGAL::orientation(p[t[0][0]], p[t[0][1]], p[t[0][2]], p[v]);
        if (o == CGAL::COPLANAR)
            continue;
        if (o == CGAL::POSITIVE)
            for (Tri &f : t)
                std::swap(f[1], f[2]);
        break;
    }
    /* each directed edge a -> b of a triangle, found again by its reverse */
    struct Edge {
        std::size_t a, b, f;
        bool operator<(const Edge &o) const
        {
            return a != o.a ? a < o.a : b < o.b;
        }
    };
    std::vector<Edge> edges;
    edges.reserve(3 * nf);
    for (std::size_t f = 0; f < nf; f++)
        for (int j = 0; j < 3; j++)
            edges.push_back({t[f][j], t[f][(j + 1) % 3], f});
    std::sort(edges.begin(), edges.end());
    auto across =
        [&edges](
            std::size_t a,
            std::size_t b) { /* the face of b -> a */
                             const Edge key{b, a, 0};
                             return std::lower_bound(edges.begin(), edges.end(), key)->f;
        };
    /* facets: triangles joined across edges whose four points are coplanar */
    std::vector<std::size_t> group(nf);
    for (std::size_t f = 0; f < nf; f++)
        group[f] = f;
    for (std::size_t f = 0; f < nf; f++)
        for (int j = 0; j < 3; j++) {
            const std::size_t a = t[f][j], b = t[f][(j + 1) % 3], g = across(a, b);
            const Tri &tg = t[g];
            const std::size_t d = tg[0] != a && tg[0] != b   ? tg[0]
                                  : tg[1] != a && tg[1] != b ? tg[1]
                                                             : tg[2];
            if (g > f &&
                CGAL::orientation(p[a], p[b], p[t[f][(j + 2) % 3]], p[d]) == CGAL::COPLANAR)
                group[root(group, f)] = root(group, g);
        }
    for (std::size_t f = 0; f < nf; f++)
        group[f] = root(group, f);
    /* extreme points: three facets or more meet at them (a point inside a facet or on
     * the edge between two is none) */
    std::vector<std::pair<std::size_t, std::size_t>> vg; /* (vertex, facet) */
    vg.reserve(3 * nf);
    for (std::size_t f = 0; f < nf; f++)
        for (int j = 0; j < 3; j++)
            vg.emplace_back(t[f][j], group[f]);
    std::sort(vg.begin(), vg.end());
    vg.erase(std::unique(vg.begin(), vg.end()), vg.end());
    std::vector<std::size_t> order;
    for (std::size_t i = 0, j; i < vg.size(); i = j) {
        for (j = i + 1; j < vg.size() && vg[j].first == vg[i].first;)
            j++;
        if (j - i >= 3)
            order.push_back(vg[i].first);
    }
    std::sort(order.begin(), order.end(), [&p](std::size_t a, std::size_t b) {
        return p[a].x() != p[b].x()   ? p[a].x() < p[b].x()
               : p[a].y() != p[b].y() ? p[a].y() < p[b].y()
                                      : p[a].z() < p[b].z();
    });
    std::vector<int> index(nv, -1);
    verts.resize(3 * order.size());
    for (std::size_t k = 0; k < order.size(); k++) {
        const Point &q = p[order[k]];
        index[order[k]] = (int)k;
        verts[3 * k] = q.x(), verts[3 * k + 1] = q.y(), verts[3 * k + 2] = q.z();
    }
    /* each facet's border: its edges whose reverse lies in another facet, one leaving
     * each of its border vertices; walked around, its corners only, as a fan */
    std::vector<Edge> border; /* (facet, a) -> b, in f's place */
    for (const Edge &e : edges)
        if (group[across(e.a, e.b)] != group[e.f])
            border.push_back({group[e.f], e.a, e.b});
    std::sort(border.begin(), border.end());
    std::vector<std::array<int, 3>> out;
    for (std::size_t i = 0, j; i < border.size(); i = j) {
        for (j = i + 1; j < border.size() && border[j].a == border[i].a;)
            j++;
        std::vector<int> ring;
        std::size_t v = border[i].b;
        do {
            const Edge key{border[i].a, v, 0};
            const auto it = std::lower_bound(border.begin() + i, border.begin() + j, key);
            if (index[v] >= 0)
                ring.push_back(index[v]);
            v = it->f;
        } while (v != border[i].b && ring.size() <= j - i);
        const std::size_t m = ring.size(),
                          s = std::min_element(ring.begin(), ring.end()) - ring.begin();
        for (std::size_t k = 1; k + 1 < m; k++)
            out.push_back({ring[s], ring[(s + k) % m], ring[(s + k + 1) % m]});
    }
    std::sort(out.begin(), out.end());
    tris.resize(3 * out.size());
    for (std::size_t k = 0; k < out.size(); k++)
        for (int c = 0; c < 3; c++)
            tris[3 * k + c] = out[k][c];
}

/* The points and triangles of the hull's mesh (each face a fan from its first corner). */
void mesh_triangles(const CGAL::Surface_mesh<Point> &sm, std::vector<Point> &hp,
                    std::vector<Tri> &ht)
{
    typedef CGAL::Surface_mesh<Point> Mesh;
    std::vector<std::size_t> index(sm.number_of_vertices() +
                                   sm.number_of_removed_vertices());
    for (Mesh::Vertex_index v : sm.vertices()) {
        index[(std::size_t)v] = hp.size();
        hp.push_back(sm.point(v));
    }
    for (Mesh::Face_index f : sm.faces()) {
        std::vector<std::size_t> c;
        for (Mesh::Vertex_index v : CGAL::vertices_around_face(sm.halfedge(f), sm))
            c.push_back(index[(std::size_t)v]);
        for (std::size_t k = 1; k + 1 < c.size(); k++)
            ht.push_back(Tri{c[0], c[k], c[k + 1]});
    }
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
        /* each point once: quickhull's scan with a triangle-set output stops on repeated
         * points (CGAL 5.5) */
        std::sort(pts.begin(), pts.end());
        pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
        /* the hull as a Surface_mesh: CGAL 5.5's overload that writes points and a
         * triangle set leaves out extreme points of a slender hull (a 24-sided prism of
         * radius 0.5 and length 10 keeps 40 of its 48 corners), its halfedge structure
         * keeps every one */
        CGAL::Surface_mesh<Point> sm;
        bool built = true;
        try {
            CGAL::convex_hull_3(pts.begin(), pts.end(), sm);
        } catch (const std::bad_alloc &) {
            throw;
        } catch (const std::exception &) {
            built = false; // a construction of its planes not finite in doubles
        }
        std::vector<Point> hp;
        std::vector<Tri> ht;
        if (built)
            mesh_triangles(sm, hp, ht);
        if (!built || !closed(hp, ht)) {
            std::snprintf(msg, cap,
                          "the %d points lie too close to one plane for the hull's "
                          "constructions in double precision (expected points that span "
                          "a volume the doubles resolve)",
                          n);
            return -1;
        }
        std::vector<double> v;
        std::vector<int> t;
        canonical(hp, ht, v, t);
        /* the C arrays last: nothing that may throw follows them */
        double *cv = (double *)std::malloc(v.size() * sizeof(double));
        int *ct = (int *)std::malloc(t.size() * sizeof(int));
        if (!cv || !ct) {
            std::free(cv);
            std::free(ct);
            std::snprintf(msg, cap, "out of memory for a hull of %zu vertices",
                          v.size() / 3);
            return -1;
        }
        std::memcpy(cv, v.data(), v.size() * sizeof(double));
        std::memcpy(ct, t.data(), t.size() * sizeof(int));
        *verts = cv;
        *tris = ct;
        *nv = (int)(v.size() / 3);
        *nt = (int)(t.size() / 3);
        return 0;
    } catch (const std::bad_alloc &) {
        std::snprintf(msg, cap, "out of memory for the hull of %d points", n);
    } catch (const std::exception &e) {
        std::snprintf(msg, cap, "the hull of %d points failed: %s", n, e.what());
    }
    return -1;
}
