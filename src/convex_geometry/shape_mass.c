/* Mass properties of the shapes (rs_shape_mass_props): the volume moments of each kind
 * in closed form (rounded solids from rounded_mass.c), then the inertia tensor about
 * the centre of mass and its principal axes. */
#include "convex_internal.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <string.h>

static void diag_moments(rs_moments *m, double v, double xx, double yy, double zz)
{
    memset(m, 0, sizeof *m);
    m->v = v;
    m->ss[0] = xx;
    m->ss[4] = yy;
    m->ss[8] = zz;
}

/* The volume moments of s about its body origin. */
/* Returns 0, -1 when out of memory. */
static int shape_moments(const rs_shape *s, rs_moments *m)
{
    const double *d = s->dim, r = s->rounding;
    switch (s->kind) {
    case RS_SHAPE_SPHERE: {
        const double rho = d[0] + r, v = 4.0 / 3.0 * RS_PI * rho * rho * rho;
        diag_moments(m, v, v * rho * rho / 5.0, v * rho * rho / 5.0, v * rho * rho / 5.0);
        return 0;
    }
    case RS_SHAPE_ELLIPSOID:
        rs_ellipsoid_moments(d[0], d[1], d[2], r, m);
        return 0;
    case RS_SHAPE_BOX:
        if (r > 0.0) {
            double v[24];
            static const int t[36] = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                                      2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
            for (int i = 0; i < 8; i++)
                for (int k = 0; k < 3; k++)
                    v[3 * i + k] = (i >> k & 1) ? d[k] : -d[k];
            return rs_polytope_moments(v, t, 12, r, m);
        }
        const double v = 8.0 * d[0] * d[1] * d[2];
        diag_moments(m, v, v * d[0] * d[0] / 3.0, v * d[1] * d[1] / 3.0,
                     v * d[2] * d[2] / 3.0);
        return 0;
    case RS_SHAPE_CYLINDER:
        if (r > 0.0) {
            const double prof[8] = {0.0, -d[1], d[0], -d[1], d[0], d[1], 0.0, d[1]};
            rs_revolved_moments(prof, 4, r, m);
        } else {
            const double v = 2.0 * RS_PI * d[0] * d[0] * d[1];
            diag_moments(m, v, v * d[0] * d[0] / 4.0, v * d[0] * d[0] / 4.0,
                         v * d[1] * d[1] / 3.0);
        }
        return 0;
    case RS_SHAPE_CAPSULE: {
        const double rho = d[0] + r, h = d[1];
        const double vc = 2.0 * RS_PI * rho * rho * h,
                     vs = 4.0 / 3.0 * RS_PI * rho * rho * rho;
        const double xx = vc * rho * rho / 4.0 + vs * rho * rho / 5.0;
        diag_moments(m, vc + vs, xx, xx,
                     vc * h * h / 3.0 + vs * (h * h + 0.75 * h * rho + rho * rho / 5.0));
        return 0;
    }
    case RS_SHAPE_CONE:
        if (r > 0.0) {
            const double prof[6] = {0.0,          -0.25 * d[1], d[0],
                                    -0.25 * d[1], 0.0,          0.75 * d[1]};
            rs_revolved_moments(prof, 3, r, m);
        } else {
            const double v = RS_PI * d[0] * d[0] * d[1] / 3.0;
            diag_moments(m, v, 0.15 * v * d[0] * d[0], 0.15 * v * d[0] * d[0],
                         v * 3.0 * d[1] * d[1] / 80.0);
        }
        return 0;
    case RS_SHAPE_POLYHEDRON:
        return rs_polytope_moments(s->verts, s->tris, s->nt, r, m);
    case RS_SHAPE_USER:
        break;
    }
    memset(m, 0, sizeof *m);
    return 0;
}

/* Eigenvalues and eigenvectors of the symmetric a by cyclic Jacobi rotations: a is
 * diagonalised in place, the columns of e are the eigenvectors. */
static void jacobi3(double a[9], double e[9])
{
    memset(e, 0, 9 * sizeof *e);
    e[0] = e[4] = e[8] = 1.0;
    for (int sweep = 0; sweep < 50; sweep++) {
        const double off = fabs(a[1]) + fabs(a[2]) + fabs(a[5]);
        const double scale = fabs(a[0]) + fabs(a[4]) + fabs(a[8]);
        if (off <= 1e-300 || off <= 1e-17 * scale)
            break;
        for (int p = 0; p < 2; p++)
            for (int q = p + 1; q < 3; q++) {
                const double apq = a[3 * p + q];
                if (apq == 0.0)
                    continue;
                const double th = (a[4 * q] - a[4 * p]) / (2.0 * apq);
                const double t =
                    (th >= 0.0 ? 1.0 : -1.0) / (fabs(th) + sqrt(th * th + 1.0));
                const double c = 1.0 / sqrt(t * t + 1.0), s = t * c;
                for (int k = 0; k < 3; k++) { /* a <- a J */
                    const double akp = a[3 * k + p], akq = a[3 * k + q];
                    a[3 * k + p] = c * akp - s * akq;
                    a[3 * k + q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; k++) { /* a <- J^T a */
                    const double apk = a[3 * p + k], aqk = a[3 * q + k];
                    a[3 * p + k] = c * apk - s * aqk;
                    a[3 * q + k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; k++) {
                    const double ekp = e[3 * k + p], ekq = e[3 * k + q];
                    e[3 * k + p] = c * ekp - s * ekq;
                    e[3 * k + q] = s * ekp + c * ekq;
                }
            }
    }
}

int rs_shape_mass_props(const rs_shape *s, double density, rs_mass_props *mp, rs_error *err)
{
    if (!s || !mp)
        return rs_error_set(err, RS_ERR_ARG, "mass properties: NULL argument");
    if (!isfinite(density) || density <= 0.0)
        return rs_error_set(err, RS_ERR_ARG, "density = %g (expected a finite number > 0)",
                            density);
    int rc = rs_shape_check(s, err);
    if (rc)
        return rc;
    if (s->kind == RS_SHAPE_USER)
        return rs_error_set(err, RS_ERR_ARG,
                            "a user shape has no mass properties of its own (expected "
                            "the body's mass and inertia from the caller)");
    rs_moments m;
    if (shape_moments(s, &m))
        return rs_error_set(err, RS_ERR_NOMEM, "mass properties: out of memory");
    if (!(m.v > 0.0))
        return rs_error_set(err, RS_ERR_GEOMETRY,
                            "mass properties: the shape has volume %g (expected > 0)", m.v);
    memset(mp, 0, sizeof *mp);
    mp->volume = m.v;
    mp->mass = density * m.v;
    double c[3];
    for (int k = 0; k < 3; k++)
        c[k] = m.s[k] / m.v;
    /* second moments about the centre of mass, then J = tr(C) I - C */
    double cm[9], tr = 0.0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            cm[3 * i + j] = m.ss[3 * i + j] - m.v * c[i] * c[j];
    tr = cm[0] + cm[4] + cm[8];
    for (int i = 0; i < 9; i++)
        mp->inertia[i] = density * ((i % 4 == 0 ? tr : 0.0) - cm[i]);
    for (int i = 0; i < 3; i++) /* symmetric to the last bit */
        for (int j = i + 1; j < 3; j++)
            mp->inertia[3 * j + i] = mp->inertia[3 * i + j];
    if (s->kind == RS_SHAPE_CONE)
        c[2] -= s->shift[2];
    memcpy(mp->com, c, sizeof c);
    double a[9];
    memcpy(a, mp->inertia, sizeof a);
    jacobi3(a, mp->axes);
    for (int k = 0; k < 3; k++)
        mp->principal[k] = a[4 * k];
    /* a right-handed frame */
    double x[3] = {mp->axes[0], mp->axes[3], mp->axes[6]},
           y[3] = {mp->axes[1], mp->axes[4], mp->axes[7]}, z[3];
    rs_cross3(x, y, z);
    if (z[0] * mp->axes[2] + z[1] * mp->axes[5] + z[2] * mp->axes[8] < 0.0)
        for (int k = 0; k < 3; k++)
            mp->axes[3 * k + 2] = -mp->axes[3 * k + 2];
    return RS_OK;
}
