/* An engine's ellipsoids as the wall's convex bodies (bodies.h); its rounded polyhedra:
 * body_polyhedron.cpp. */
#include "bodies.h"

#include <cmath>
#include <cstring>

RsBodies::~RsBodies()
{
    for (auto &s : shapes_)
        rs_shape_free(s.second.get());
    for (auto &p : polyhedra_)
        rs_shape_free(&p.second->shape);
}

void RsBodies::resize(int n)
{
    const size_t un = n > 0 ? (size_t)n : 0;
    rs_body none;
    std::memset(&none, 0, sizeof none);
    body_.assign(un, none);
    radius_.assign(un, 0.0);
    omega_.assign(3 * un, 0.0);
}

void RsBodies::sphere(int i, double r, const double *w)
{
    body_[i].shape = nullptr;
    radius_[i] = r;
    for (int d = 0; d < 3; d++)
        omega_[3 * (size_t)i + d] = w ? w[d] : 0.0;
}

int RsBodies::ellipsoid(int i, const double half[3], const double x[3], const double q[4],
                        double m, const double L[3], rs_error *err)
{
    const std::array<double, 3> key = {half[0], half[1], half[2]};
    auto it = shapes_.find(key);
    if (it == shapes_.end()) {
        std::unique_ptr<rs_shape> s(new rs_shape);
        const int rc =
            rs_shape_make_ellipsoid(s.get(), half[0], half[1], half[2], 0.0, err);
        if (rc != RS_OK)
            return rc;
        it = shapes_.emplace(key, std::move(s)).first;
    }
    rs_body &b = body_[i];
    b.shape = it->second.get();
    for (int d = 0; d < 3; d++)
        b.x[d] = x[d];
    for (int d = 0; d < 4; d++)
        b.q[d] = q[d];
    b.mass = m;
    const double a2 = half[0] * half[0], b2 = half[1] * half[1], c2 = half[2] * half[2];
    b.inertia[0] = 0.2 * m * (b2 + c2);
    b.inertia[1] = 0.2 * m * (a2 + c2);
    b.inertia[2] = 0.2 * m * (a2 + b2);
    std::memset(b.axes, 0, sizeof b.axes);
    b.axes[0] = b.axes[4] = b.axes[8] = 1.0;
    radius_[i] = std::cbrt(half[0] * half[1] * half[2]);
    spin(i, L);
    return RS_OK;
}

/* w = R I^-1 R^T L: the momentum in body axes, over the moments, back to the world */
void RsBodies::spin(int i, const double L[3])
{
    const rs_body &b = body_[i];
    double R[9], wb[3];
    rs_body_rotation(&b, R);
    for (int k = 0; k < 3; k++) {
        const double Lk = R[k] * L[0] + R[3 + k] * L[1] + R[6 + k] * L[2];
        wb[k] = b.inertia[k] != 0.0 ? Lk / b.inertia[k] : 0.0;
    }
    for (int d = 0; d < 3; d++)
        omega_[3 * (size_t)i + d] =
            R[3 * d] * wb[0] + R[3 * d + 1] * wb[1] + R[3 * d + 2] * wb[2];
}
