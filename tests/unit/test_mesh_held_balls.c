/* The held faces' balls (rs_mesh_held_balls, src/faceted/mesh_held.c): a sphere within the
 * ball its face's zone test left takes the ball's answer instead of the test. The numbers
 * must be those without balls, value for value, step after step of spheres walking over
 * the benchmark's cylinder (its quads split in triangles as in its STL: quad zones across
 * the diagonals, and kept as planar quads), a UV sphere (one-triangle faces, convex and
 * concave folds), one- and two-sided, in place and under a pose, with each sphere's own
 * ball and with balls left by others (a ball is a fact about the mesh alone); and every
 * face they give must be the query's without hints (every feature tested), value for
 * value. The walks must go through the balls for most of their steps. */
#include "faceted/cgal_mesh.h"
#include "faceted/mesh.h"
#include "faceted/mesh_held.h"
#include "mesh_soup.h"
#include "rigidsurf/motion.h"
#include "rigidsurf/surface.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { NB = 64, STEPS = 160 };

/* Do contact lists a and b hold the same m entries, value for value? */
static int same_lists(const rs_contacts *a, const rs_contacts *b, int m)
{
    for (int k = 0; k < m; k++) {
        if (a->point[k] != b->point[k] || a->feature[k] != b->feature[k] ||
            memcmp(&a->dist[k], &b->dist[k], sizeof(double)) ||
            a->share[k] != b->share[k] || a->curv[0][k] != b->curv[0][k] ||
            a->curv[1][k] != b->curv[1][k])
            return 0;
        for (int d = 0; d < 3; d++)
            if (memcmp(&a->xm[d][k], &b->xm[d][k], sizeof(double)) ||
                memcmp(&a->nrm[d][k], &b->nrm[d][k], sizeof(double)) ||
                memcmp(&a->t1[d][k], &b->t1[d][k], sizeof(double)) ||
                memcmp(&a->t2[d][k], &b->t2[d][k], sizeof(double)))
                return 0;
    }
    return 1;
}

typedef struct walk_tally {
    int calls, flagged, in_ball, foreign, bad;
} walk_tally;

/* A point on triangle t at height h over it, its barycentric weights w. */
static void on_triangle(const rs_mesh *m, int t, const double w[3], double h, double p[3])
{
    const rs_mtri *r = m->rec + t;
    const double sw = w[0] + w[1] + w[2];
    for (int d = 0; d < 3; d++) {
        p[d] = h * r->n[d];
        for (int k = 0; k < 3; k++)
            p[d] += w[k] / sw * m->xyz[3 * r->v[k] + d];
    }
}

/* NB spheres of radii r0 / 2 .. r0 walking over mesh s (in pairs: the second a hair from
 * the first, holding the same face), each step a random move of up to `step` along the
 * surface and across it (one in ten 50 times as far); now and then one is put down
 * elsewhere, or holds another face.
 * At each step the held faces with balls (each sphere's own, or on odd steps its pair's)
 * against those without, and the faces they flag against the query without hints. */
static void walk(const rs_surface *s, const rs_pose *pose, double r0, double gap_max,
                 double step, unsigned long long seed, walk_tally *ty)
{
    const rs_mesh *m = s->impl;
    double X[NB][3], r[NB], x[NB], y[NB], z[NB];
    int hint[NB], row[NB], face_a[NB], face_b[NB];
    rs_mesh_held_ball balls[NB];
    for (int i = 0; i < NB; i++)
        balls[i].face = -1;
    rs_contacts ca, cb, cq;
    memset(&ca, 0, sizeof ca);
    memset(&cb, 0, sizeof cb);
    memset(&cq, 0, sizeof cq);
    rs_error e;
    if (rs_contacts_reserve(&ca, NB, &e) || rs_contacts_reserve(&cb, NB, &e)) {
        ty->bad++;
        return;
    }
    double rmax = 0.0;
    for (int step_no = 0; step_no < STEPS && !ty->bad; step_no++) {
        for (int i = 0; i < NB; i += 2) {
            const int put = step_no == 0 || rs_test_urand(&seed) < 0.01;
            if (put) { /* down on a random triangle, touching it or nearly */
                const int t = (int)(rs_test_xorshift(&seed) % (unsigned long long)m->nt);
                const double w[3] = {rs_test_urand(&seed), rs_test_urand(&seed),
                                     rs_test_urand(&seed)};
                r[i] = r[i + 1] = r0 * (0.5 + 0.5 * rs_test_urand(&seed));
                const double hs = s->sides == 2 && rs_test_urand(&seed) < 0.3 ? -1.0 : 1.0;
                on_triangle(m, t, w, hs * r[i] * (0.8 + 0.3 * rs_test_urand(&seed)), X[i]);
                hint[i] = hint[i + 1] = RS_FEATURE(RS_FEAT_FACE, m->rec[t].el);
            } else {
                /* now and then a long stride: out of its ball, or its zone */
                const double f = rs_test_urand(&seed) < 0.1 ? 50.0 : 1.0;
                for (int d = 0; d < 3; d++)
                    X[i][d] += f * step * (2.0 * rs_test_urand(&seed) - 1.0);
                if (rs_test_urand(&seed) < 0.02) /* another face held */
                    hint[i] = hint[i + 1] =
                        RS_FEATURE(RS_FEAT_FACE, (int)(rs_test_xorshift(&seed) %
                                                       (unsigned long long)m->nel));
            }
            for (int d = 0; d < 3; d++)
                X[i + 1][d] = X[i][d] + 1e-9 * r0 * (rs_test_urand(&seed) - 0.5);
            rmax = fmax(rmax, r[i]);
        }
        for (int i = 0; i < NB; i++) {
            double xw[3];
            if (pose)
                rs_pose_to_global(pose, X[i], xw);
            else
                memcpy(xw, X[i], sizeof xw);
            x[i] = xw[0], y[i] = xw[1], z[i] = xw[2];
            row[i] = step_no % 2 ? i ^ 1 : i;
        }
        /* which spheres lie within the ball they read, before the call */
        for (int i = 0; i < NB; i++) {
            const rs_mesh_held_ball *b = balls + row[i];
            const double d2 = (X[i][0] - b->x[0]) * (X[i][0] - b->x[0]) +
                              (X[i][1] - b->x[1]) * (X[i][1] - b->x[1]) +
                              (X[i][2] - b->x[2]) * (X[i][2] - b->x[2]);
            const int in = b->face == hint[i] && d2 < 0.99 * b->reach * b->reach;
            ty->in_ball += in;
            ty->foreign += in && row[i] != i;
        }
        rs_mesh_held_faces(s, pose, NB, x, y, z, r, hint, gap_max, -rmax, &ca, face_a);
        rs_mesh_held_balls(s, pose, NB, x, y, z, r, hint, gap_max, -rmax, balls, row, &cb,
                           face_b);
        rs_frame_orient(s->ops->frame, &ca, 0, ca.n);
        rs_frame_orient(s->ops->frame, &cb, 0, cb.n);
        ty->calls += NB;
        if (ca.n != NB || cb.n != NB || memcmp(face_a, face_b, sizeof face_a) ||
            !same_lists(&ca, &cb, NB)) {
            fprintf(stderr,
                    "step %d: the held faces with balls differ from those without\n",
                    step_no);
            ty->bad++;
            break;
        }
        /* the flagged faces are the query's without hints */
        rs_query q;
        memset(&q, 0, sizeof q);
        q.n = NB;
        q.slave.x = x, q.slave.y = y, q.slave.z = z, q.slave.radius = r;
        q.gap_max = gap_max;
        q.dist_min = -rmax;
        q.pose = pose;
        cq.n = 0;
        if (rs_surface_query(s, &q, &cq, &e) != RS_OK) {
            fprintf(stderr, "query: %s\n", e.msg);
            ty->bad++;
            break;
        }
        for (int i = 0; i < NB; i++) {
            if (!face_b[i])
                continue;
            ty->flagged++;
            int k = -1, nk = 0;
            for (int a = 0; a < cq.n; a++)
                if (cq.point[a] == i)
                    k = a, nk++;
            int same = nk == 1 && cb.feature[i] == cq.feature[k] &&
                       cb.dist[i] == cq.dist[k] && cq.share[k] == 1.0;
            for (int d = 0; d < 3; d++)
                same = same && cb.xm[d][i] == cq.xm[d][k] && cb.nrm[d][i] == cq.nrm[d][k] &&
                       cb.t1[d][i] == cq.t1[d][k] && cb.t2[d][i] == cq.t2[d][k];
            if (!same) {
                fprintf(stderr,
                        "step %d, sphere %d: held face %d at %.17g, the query's %d "
                        "contacts, %d at %.17g\n",
                        step_no, i, cb.feature[i], cb.dist[i], nk,
                        k >= 0 ? cq.feature[k] : -1, k >= 0 ? cq.dist[k] : 0.0);
                ty->bad++;
            }
        }
    }
    rs_contacts_free(&ca);
    rs_contacts_free(&cb);
    rs_contacts_free(&cq);
}

static void walk_case(const char *name, const soup *sp, int sides, const rs_pose *pose,
                      double r0, double step, unsigned long long seed)
{
    rs_surface s;
    if (make(sp, sides, &s) != RS_OK) {
        rs_test_current_failed = 1;
        return;
    }
    walk_tally ty = {0, 0, 0, 0, 0};
    walk(&s, pose, r0, 0.25 * r0, step, seed, &ty);
    printf("  %s, %d side%s%s: %d spheres' steps, %d held faces, %d within their balls "
           "(%d another sphere's)\n",
           name, sides, sides == 1 ? "" : "s", pose ? ", under a pose" : "", ty.calls,
           ty.flagged, ty.in_ball, ty.foreign);
    rs_surface_free(&s);
    ENSURE(ty.bad == 0);
    ENSURE(ty.calls == NB * STEPS);
    /* the zones hold a good share of the steps, and the balls most of those */
    ENSURE(ty.flagged >= ty.calls / 5);
    ENSURE(ty.in_ball >= ty.flagged / 2);
    ENSURE(ty.foreign > 0);
}

static void cylinder_walks(void)
{
    soup sp;
    memset(&sp, 0, sizeof sp);
    rs_pose pose;
    const double c = cos(0.7), sn = sin(0.7);
    const double R[9] = {c, -sn, 0, sn, c, 0, 0, 0, 1};
    memcpy(pose.R, R, sizeof R);
    pose.T[0] = 0.3, pose.T[1] = -0.2, pose.T[2] = 0.05;
    for (int quads = 0; quads <= 1; quads++) {
        cylinder(&sp, 200, 10, 0.05, -0.002, 0.317, quads);
        const char *name = quads ? "cylinder of quads" : "cylinder";
        for (int sides = 1; sides <= 2; sides++)
            walk_case(name, &sp, sides, NULL, 0.001, 2e-6,
                      11 + 2 * (unsigned)quads + sides);
        walk_case(name, &sp, 2, &pose, 0.001, 2e-6, 17 + (unsigned)quads);
        sp_free(&sp);
    }
}

static void sphere_walks(void)
{
    soup sp;
    memset(&sp, 0, sizeof sp);
    uv_sphere(&sp, 24, 48);
    for (int sides = 1; sides <= 2; sides++)
        walk_case("sphere", &sp, sides, NULL, 0.02, 2e-4, 31 + (unsigned)sides);
    sp_free(&sp);
}

int main(void)
{
    RS_RUN(cylinder_walks);
    RS_RUN(sphere_walks);
    return rs_test_summary();
}
