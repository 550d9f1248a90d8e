/* An engine's rounded polyhedra as the wall's convex bodies (bodies.h): the hull of the
 * vertices, checked to be the body (convex), rounded, in the engine's body frame. */
#include "bodies.h"

#include <cmath>
#include <cstring>

namespace
{

double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* The hull's triangle t as a plane: unit outward normal n and offset d (n.p = d on it). */
void hull_plane(const rs_shape &s, int t, double n[3], double &d)
{
    const double *a = s.verts + 3 * s.tris[3 * t], *b = s.verts + 3 * s.tris[3 * t + 1],
                 *c = s.verts + 3 * s.tris[3 * t + 2];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    n[0] = u[1] * v[2] - u[2] * v[1];
    n[1] = u[2] * v[0] - u[0] * v[2];
    n[2] = u[0] * v[1] - u[1] * v[0];
    const double l = std::sqrt(dot3(n, n));
    for (int k = 0; k < 3; k++)
        n[k] = l > 0.0 ? n[k] / l : 0.0;
    d = dot3(n, a);
}

/* The greatest signed distance of p (hull frame) beyond the hull's planes: <= 0 inside. */
double beyond_hull(const rs_shape &s, const double p[3])
{
    double worst = -HUGE_VAL;
    for (int t = 0; t < s.nt; t++) {
        double n[3], d;
        hull_plane(s, t, n, d);
        worst = std::fmax(worst, dot3(n, p) - d);
    }
    return worst;
}

} // namespace

/* Convex: every vertex on the hull's boundary (none inside it, none left outside it by the
 * hull's making), each face's vertices in one
 * plane (Newell's normal of the face) with every vertex on one side of it, the centre of
 * mass (the origin of verts) inside the hull. s is the hull in its own frame (verts less
 * s.shift). */
int RsBodies::check_convex(const rs_shape &s, const double *verts, int nv,
                           const double *faces, int nf, int face_size, rs_error *err)
{
    double size = 0.0;
    for (int i = 0; i < nv; i++)
        size = std::fmax(size, std::sqrt(dot3(verts + 3 * i, verts + 3 * i)));
    const double tol = 1e-9 * size;
    for (int i = 0; i < nv; i++) {
        const double p[3] = {verts[3 * i] - s.shift[0], verts[3 * i + 1] - s.shift[1],
                             verts[3 * i + 2] - s.shift[2]};
        const double out = beyond_hull(s, p);
        if (out > tol)
            return rs_error_set(err, RS_ERR_GEOMETRY,
                                "vertex %d lies %g outside the convex hull made of the "
                                "vertices (%d of %d kept as its corners): the body cannot "
                                "be made exactly (expected every vertex on the hull)",
                                i, out, s.nv, nv);
        if (out < -tol)
            return rs_error_set(err, RS_ERR_GEOMETRY,
                                "vertex %d lies inside the convex hull of the others, %g "
                                "from its surface: the body is not convex (expected a "
                                "convex polyhedron, each vertex a point of its hull's "
                                "surface)",
                                i, -out);
    }
    for (int f = 0; f < nf; f++) {
        const double *row = faces + (size_t)f * face_size;
        int m = 0;
        double n[3] = {0.0, 0.0, 0.0}, c[3] = {0.0, 0.0, 0.0};
        for (int k = 0; k < face_size && row[k] >= 0.0; k++, m++)
            if (row[k] >= nv || row[k] != std::floor(row[k]))
                return rs_error_set(err, RS_ERR_ARG,
                                    "face %d names vertex %g (expected 0 .. %d)", f, row[k],
                                    nv - 1);
        if (m < 3)
            return rs_error_set(err, RS_ERR_ARG,
                                "face %d has %d vertices (expected 3 .. %d)", f, m,
                                face_size);
        for (int k = 0; k < m; k++) { // Newell's normal and the centroid
            const double *a = verts + 3 * (int)row[k],
                         *b = verts + 3 * (int)row[(k + 1) % m];
            n[0] += (a[1] - b[1]) * (a[2] + b[2]);
            n[1] += (a[2] - b[2]) * (a[0] + b[0]);
            n[2] += (a[0] - b[0]) * (a[1] + b[1]);
            for (int d = 0; d < 3; d++)
                c[d] += a[d] / m;
        }
        const double l = std::sqrt(dot3(n, n));
        if (!(l > 0.0))
            return rs_error_set(err, RS_ERR_GEOMETRY,
                                "face %d has no area (expected a triangle or a planar "
                                "quadrilateral)",
                                f);
        for (int d = 0; d < 3; d++)
            n[d] /= l;
        const double off = dot3(n, c);
        double lo = 0.0, hi = 0.0;
        int ilo = 0, ihi = 0;
        for (int i = 0; i < nv; i++) {
            const double h = dot3(n, verts + 3 * i) - off;
            if (h < lo)
                lo = h, ilo = i;
            if (h > hi)
                hi = h, ihi = i;
        }
        for (int k = 0; k < m; k++) {
            const double h = dot3(n, verts + 3 * (int)row[k]) - off;
            if (std::fabs(h) > tol)
                return rs_error_set(err, RS_ERR_GEOMETRY,
                                    "face %d is not planar: its vertex %d is %g from its "
                                    "plane (expected a triangle or a planar quadrilateral)",
                                    f, (int)row[k], std::fabs(h));
        }
        if (lo < -tol && hi > tol)
            return rs_error_set(err, RS_ERR_GEOMETRY,
                                "vertices %d and %d lie on either side of face %d's plane "
                                "(%g and %g from it): the body is not convex (expected a "
                                "convex polyhedron)",
                                ilo, ihi, f, lo, hi);
    }
    const double o[3] = {-s.shift[0], -s.shift[1], -s.shift[2]};
    const double out = beyond_hull(s, o);
    if (!(out < 0.0))
        return rs_error_set(err, RS_ERR_GEOMETRY,
                            "its centre of mass (the particle's position) lies %g outside "
                            "the hull of its vertices (expected the vertices as "
                            "displacements from the centre of mass)",
                            out);
    return RS_OK;
}

int RsBodies::polyhedron(int i, const double *verts, int nv, const double *faces, int nf,
                         int face_size, double rounding, const double x[3],
                         const double q[4], double m, const double I[3], const double L[3],
                         rs_error *err)
{
    if (nv < 4)
        return rs_error_set(err, RS_ERR_ARG,
                            "a body of %d vertices (expected a polyhedron of 4 or more "
                            "vertices not in one plane; spheres: atom_style sphere)",
                            nv);
    std::vector<double> key;
    key.reserve(4 + 3 * (size_t)nv + (size_t)nf * face_size);
    key.push_back(rounding);
    key.push_back(nv);
    key.push_back(nf);
    key.push_back(face_size);
    key.insert(key.end(), verts, verts + 3 * (size_t)nv);
    key.insert(key.end(), faces, faces + (size_t)nf * face_size);
    auto it = polyhedra_.find(key);
    if (it == polyhedra_.end()) {
        std::unique_ptr<Polyhedron> p(new Polyhedron);
        rs_shape &s = p->shape;
        std::memset(&s, 0, sizeof s);
        int rc = rs_shape_make_polyhedron(&s, verts, nv, rounding, err);
        if (rc != RS_OK)
            return rc;
        rs_mass_props mp;
        rc = check_convex(s, verts, nv, faces, nf, face_size, err);
        if (rc == RS_OK)
            rc = rs_shape_mass_props(&s, 1.0, &mp, err);
        if (rc != RS_OK) {
            rs_shape_free(&s);
            return rc;
        }
        p->radius = std::cbrt(3.0 * mp.volume / (4.0 * M_PI));
        /* the body frame as the engine gives it: its origin the engine's centre of mass
         * (the hull's vertices, bounds and reach moved back by the shift; the adjacency and
         * the support's start vertices do not depend on the origin) */
        double r2 = 0.0;
        for (int v = 0; v < s.nv; v++)
            for (int d = 0; d < 3; d++)
                s.verts[3 * v + d] += s.shift[d];
        for (int d = 0; d < 3; d++) {
            s.box[d] += s.shift[d];
            s.box[3 + d] += s.shift[d];
            s.shift[d] = 0.0;
            const double e = std::fmax(std::fabs(s.box[d]), std::fabs(s.box[3 + d]));
            r2 += e * e;
        }
        s.reach = std::sqrt(r2);
        it = polyhedra_.emplace(std::move(key), std::move(p)).first;
    }
    rs_body &b = body_[i];
    b.shape = &it->second->shape;
    for (int d = 0; d < 3; d++) {
        b.x[d] = x[d];
        b.inertia[d] = I[d];
    }
    for (int d = 0; d < 4; d++)
        b.q[d] = q[d];
    b.mass = m;
    std::memset(b.axes, 0, sizeof b.axes);
    b.axes[0] = b.axes[4] = b.axes[8] = 1.0;
    radius_[i] = it->second->radius;
    spin(i, L);
    return RS_OK;
}
