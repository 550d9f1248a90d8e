/* The fuzz target: a surface file is either rejected with a code and a message, or it
 * answers every query with finite contacts and unit normals. */
#include "fuzz_surface.h"

#include "rigidsurf/surface.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { NG = 5, NQ = NG * NG * NG };

long rs_fuzz_accepted;

static int all_finite(const double *v, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return 0;
    return 1;
}

static int bad(const char *what, int k, const char *name)
{
    fprintf(stderr, "fuzz_surface: surface '%s': contact %d: %s\n", name, k, what);
    return 1;
}

/* Every contact: finite point, frame, distance and curvatures, unit n, t1, t2, a share
 * in [0, 1]. */
static int check_contacts(const rs_surface *s, const rs_contacts *c, int nq)
{
    for (int k = 0; k < c->n; k++) {
        double v[14] = {c->xm[0][k],   c->xm[1][k],  c->xm[2][k], c->nrm[0][k],
                        c->nrm[1][k],  c->nrm[2][k], c->t1[0][k], c->t1[1][k],
                        c->t1[2][k],   c->t2[0][k],  c->t2[1][k], c->t2[2][k],
                        c->curv[0][k], c->curv[1][k]};
        if (!all_finite(v, 14) || !isfinite(c->dist[k]))
            return bad("a non-finite result", k, s->name);
        for (int a = 0; a < 3; a++) {
            const double len =
                sqrt(v[3 * a + 3] * v[3 * a + 3] + v[3 * a + 4] * v[3 * a + 4] +
                     v[3 * a + 5] * v[3 * a + 5]);
            if (fabs(len - 1.0) > 1e-9)
                return bad("a normal or tangent that is not a unit vector", k, s->name);
        }
        if (c->point[k] < 0 || c->point[k] >= nq)
            return bad("a point index outside the block", k, s->name);
        if (!(c->share[k] >= 0.0 && c->share[k] <= 1.0))
            return bad("a share outside [0, 1]", k, s->name);
    }
    return 0;
}

/* Points on a grid over the bounds, widened by a tenth of their size (finite sides
 * stand in for unbounded ones), as points and as spheres. */
static int query_grid(const rs_surface *s)
{
    double lo[3], hi[3];
    rs_surface_bounds(s, lo, hi);
    for (int d = 0; d < 3; d++) {
        if (!isfinite(lo[d]))
            lo[d] = isfinite(hi[d]) ? hi[d] - 1.0 : -1.0;
        if (!isfinite(hi[d]))
            hi[d] = lo[d] + 1.0;
        const double w = hi[d] - lo[d], pad = 0.1 * (w > 0.0 ? w : 1.0);
        lo[d] -= pad;
        hi[d] += pad;
    }
    static double x[NQ], y[NQ], z[NQ], r[NQ];
    double size = 0.0;
    for (int d = 0; d < 3; d++)
        size = fmax(size, hi[d] - lo[d]);
    int q = 0;
    for (int i = 0; i < NG; i++)
        for (int j = 0; j < NG; j++)
            for (int l = 0; l < NG; l++, q++) {
                x[q] = lo[0] + (hi[0] - lo[0]) * (i + 0.37) / NG;
                y[q] = lo[1] + (hi[1] - lo[1]) * (j + 0.29) / NG;
                z[q] = lo[2] + (hi[2] - lo[2]) * (l + 0.53) / NG;
                r[q] = 0.05 * size * (1 + (q % 3));
            }
    if (!all_finite(x, NQ) || !all_finite(y, NQ) || !all_finite(z, NQ))
        return 0; /* bounds of a surface beyond what doubles can sample */
    rs_contacts c;
    memset(&c, 0, sizeof c);
    int fail = 0;
    for (int sph = 0; sph < 2 && !fail; sph++) {
        rs_query qr = {.n = NQ,
                       .slave = {.x = x, .y = y, .z = z, .radius = sph ? r : NULL},
                       .pose = NULL,
                       .gap_max = INFINITY,
                       .dist_min = -INFINITY};
        rs_error e;
        c.n = 0;
        int rc = rs_surface_query(s, &qr, &c, &e);
        if (rc != RS_OK) {
            fprintf(stderr, "fuzz_surface: surface '%s': query failed: %s\n", s->name,
                    e.msg);
            fail = 1;
        } else {
            fail = check_contacts(s, &c, NQ);
        }
    }
    rs_contacts_free(&c);
    return fail;
}

int rs_fuzz_check_surface(const rs_surface *s)
{
    int fail = query_grid(s);
    rs_trimesh m;
    rs_error e;
    if (!fail && rs_surface_triangulate(s, 1.0, 16, &m, &e) == RS_OK) {
        if (!all_finite(m.xyz, 3 * m.nvert)) {
            fprintf(stderr, "fuzz_surface: surface '%s': non-finite display mesh\n",
                    s->name);
            fail = 1;
        }
        for (int i = 0; i < 3 * m.ntri && !fail; i++)
            if (m.tri[i] < 0 || m.tri[i] >= m.nvert) {
                fprintf(stderr, "fuzz_surface: surface '%s': bad mesh index\n", s->name);
                fail = 1;
            }
        rs_trimesh_free(&m);
    }
    return fail;
}

int rs_fuzz_surface_one(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0'; /* the text ends at its first NUL, as a C string does */
    rs_surface s;
    rs_error e;
    int fail = 0;
    int rc = rs_surface_parse(text, "fuzz", NULL, &s, &e);
    if (rc != RS_OK) {
        if (e.code != rc || e.msg[0] == '\0') {
            fprintf(stderr, "fuzz_surface: rejected without a message (code %d)\n", rc);
            fail = 1;
        }
    } else {
        rs_fuzz_accepted++;
        fail = rs_fuzz_check_surface(&s);
        rs_surface_free(&s);
    }
    free(text);
    fail |= rs_fuzz_arrays_one(data, size);
    return fail | rs_fuzz_bodies_one(data, size);
}

#ifdef RS_LIBFUZZER
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (rs_fuzz_surface_one(data, size))
        abort(); /* libFuzzer keeps the input as a crash */
    return 0;
}
#endif
