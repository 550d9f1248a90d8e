/* CGAL behind a C interface (cgal_mesh.h): polygon-soup reading and the AABB tree of a
 * faceted surface. Exceptions never cross into C: every entry point catches them. */
#include "cgal_mesh.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>
#include <vector>

namespace
{

typedef CGAL::Simple_cartesian<double> K;
typedef K::Point_3 Point;
typedef K::Triangle_3 Triangle;
typedef std::vector<Triangle>::const_iterator TriIt;
typedef CGAL::AABB_triangle_primitive<K, TriIt> Primitive;
typedef CGAL::AABB_traits<K, Primitive> Traits;
typedef CGAL::AABB_tree<Traits> Tree;

struct MeshTree {
    std::vector<Triangle> tris;
    Tree tree;
};

/* Traversal of the tree for a box: the primitives of every leaf whose box meets the
 * query box, their indices into a bounded buffer, all of them counted. A primitive is
 * not tested against the box itself: its own test would read its triangle, and the
 * callers test each triangle exactly (its distance) from their own records. */
struct BoxList {
    TriIt begin;
    int *ids;
    int cap;
    int count;
    bool go_further() const
    {
        return true;
    }
    void intersection(const CGAL::Bbox_3 &, const Primitive &p)
    {
        if (count < cap)
            ids[count] = (int)(p.id() - begin);
        ++count;
    }
    template <class Node> bool do_intersect(const CGAL::Bbox_3 &q, const Node &node) const
    {
        return CGAL::do_overlap(q, node.bbox());
    }
};

std::string lower_extension(const char *path)
{
    const char *dot = std::strrchr(path, '.');
    const char *slash = std::strrchr(path, '/');
    if (!dot || (slash && dot < slash))
        return std::string();
    std::string e(dot + 1);
    for (char &c : e)
        c = (char)std::tolower((unsigned char)c);
    return e;
}

} // namespace

extern "C" int rs_cgal_read_soup(const char *path, rs_soup *soup, char *msg, size_t cap)
{
    std::memset(soup, 0, sizeof *soup);
    const std::string ext = lower_extension(path);
    if (ext != "stl" && ext != "obj" && ext != "off" && ext != "ply") {
        std::snprintf(msg, cap,
                      "unknown mesh format '.%s' (expected .stl, .obj, .off, .ply or an "
                      "Abaqus .inp)",
                      ext.c_str());
        return -1;
    }
    try {
        std::vector<Point> pts;
        std::vector<std::vector<std::size_t>> polys;
        bool ok = CGAL::IO::read_polygon_soup(std::string(path), pts, polys,
                                              CGAL::parameters::verbose(false));
        if (!ok) {
            std::snprintf(msg, cap, "not a readable %s file (broken or truncated)",
                          ext == "stl"   ? "STL"
                          : ext == "obj" ? "OBJ"
                          : ext == "off" ? "OFF"
                                         : "PLY");
            return -1;
        }
        if (pts.size() > (std::size_t)(1 << 28) || polys.size() > (std::size_t)(1 << 27)) {
            std::snprintf(msg, cap,
                          "%zu points and %zu polygons (expected at most %d and %d)",
                          pts.size(), polys.size(), 1 << 28, 1 << 27);
            return -1;
        }
        std::size_t ncorner = 0;
        for (const auto &p : polys) {
            ncorner += p.size();
            if (ncorner > (std::size_t)(1 << 29)) {
                std::snprintf(msg, cap, "too many polygon corners (expected at most %d)",
                              1 << 29);
                return -1;
            }
        }
        soup->xyz = (double *)std::malloc((pts.size() * 3 + 1) * sizeof(double));
        soup->off = (int *)std::malloc((polys.size() + 1) * sizeof(int));
        soup->idx = (int *)std::malloc((ncorner + 1) * sizeof(int));
        if (!soup->xyz || !soup->off || !soup->idx) {
            rs_soup_free(soup);
            std::snprintf(msg, cap, "out of memory for %zu points", pts.size());
            return -1;
        }
        soup->np = (int)pts.size();
        soup->nf = (int)polys.size();
        for (std::size_t i = 0; i < pts.size(); i++) {
            soup->xyz[3 * i] = pts[i].x();
            soup->xyz[3 * i + 1] = pts[i].y();
            soup->xyz[3 * i + 2] = pts[i].z();
        }
        int k = 0;
        for (std::size_t f = 0; f < polys.size(); f++) {
            soup->off[f] = k;
            for (std::size_t c : polys[f]) {
                if (c >= pts.size()) {
                    std::snprintf(msg, cap, "polygon %zu names point %zu of %zu", f + 1,
                                  c + 1, pts.size());
                    rs_soup_free(soup);
                    return -1;
                }
                soup->idx[k++] = (int)c;
            }
        }
        soup->off[polys.size()] = k;
        return 0;
    } catch (const std::bad_alloc &) {
        rs_soup_free(soup);
        std::snprintf(msg, cap, "out of memory reading the mesh");
        return -1;
    } catch (const std::exception &e) {
        rs_soup_free(soup);
        std::snprintf(msg, cap, "not a readable mesh file (%s)", e.what());
        return -1;
    } catch (...) {
        rs_soup_free(soup);
        std::snprintf(msg, cap, "not a readable mesh file");
        return -1;
    }
}

extern "C" void rs_soup_free(rs_soup *soup)
{
    std::free(soup->xyz);
    std::free(soup->off);
    std::free(soup->idx);
    std::free(soup->label);
    std::memset(soup, 0, sizeof *soup);
}

extern "C" void *rs_cgal_tree_new(int nt, const double *xyz, const int *tri)
{
    try {
        MeshTree *m = new MeshTree;
        m->tris.reserve((std::size_t)nt);
        for (int t = 0; t < nt; t++) {
            const double *a = xyz + 3 * tri[3 * t], *b = xyz + 3 * tri[3 * t + 1],
                         *c = xyz + 3 * tri[3 * t + 2];
            m->tris.push_back(Triangle(Point(a[0], a[1], a[2]), Point(b[0], b[1], b[2]),
                                       Point(c[0], c[1], c[2])));
        }
        m->tree.insert(m->tris.begin(), m->tris.end());
        m->tree.build();
        return m;
    } catch (...) {
        return nullptr;
    }
}

extern "C" void rs_cgal_tree_free(void *tree)
{
    delete static_cast<MeshTree *>(tree);
}

extern "C" int rs_cgal_tree_box(const void *tree, const double lo[3], const double hi[3],
                                int *ids, int cap)
{
    const MeshTree *m = static_cast<const MeshTree *>(tree);
    if (!m || m->tris.empty())
        return 0;
    const CGAL::Bbox_3 box(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    BoxList list{m->tris.begin(), ids, cap, 0};
    try {
        m->tree.traversal(box, list);
    } catch (...) {
        return -1;
    }
    return list.count;
}

extern "C" double rs_cgal_tree_nearest(const void *tree, const double p[3])
{
    const MeshTree *m = static_cast<const MeshTree *>(tree);
    if (!m || m->tris.empty())
        return -1.0;
    try {
        return std::sqrt(m->tree.squared_distance(Point(p[0], p[1], p[2])));
    } catch (...) {
        return -1.0;
    }
}
