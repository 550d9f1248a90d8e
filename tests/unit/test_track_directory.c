/* The tracker's history directory (track.h, docs/conventions.md "History slot"): zeroed
 * memory is an empty directory, and one feature held in two slots is an error. Contacts
 * are built by hand from planes, so the expected kinematics are closed forms. */
#include "rigidsurf/track.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"
#include "rs_test_contacts.h"

#include <stdlib.h>

#define NS 2
#define HS RS_HIST_SIZE(NS)
#define NP 3

/* The contact of centre x with the plane through the origin with unit normal n and
 * tangents t1, t2 = n x t1. */
static void add_plane(rs_test_clist *l, int point, int feature, const double x[3],
                      const double n[3], const double t1[3])
{
    double t2[3];
    rs_cross3(n, t1, t2);
    const double dist = rs_dot3(x, n);
    const double xm[3] = {x[0] - dist * n[0], x[1] - dist * n[1], x[2] - dist * n[2]};
    rs_test_clist_add(l, point, feature, xm, n, t1, t2, dist);
}

/* NP spheres whose directories and slots come from calloc, never cleared. */
typedef struct zblock {
    double x[NP], y[NP], z[NP], vx[NP], vy[NP], vz[NP], r[NP];
    int id[NP];
    double *dir[NP], *hist[NP];
    rs_particles p;
} zblock;

static int zblock_init(zblock *b, int cap)
{
    memset(b, 0, sizeof *b);
    int ok = 1;
    for (int i = 0; i < NP; i++) {
        b->dir[i] = calloc((size_t)cap, sizeof(double));
        b->hist[i] = calloc((size_t)cap * HS, sizeof(double));
        ok &= b->dir[i] && b->hist[i];
        b->id[i] = 4711 + i;
        b->r[i] = 0.01;
    }
    b->p = (rs_particles){.n = NP,
                          .x = b->x,
                          .y = b->y,
                          .z = b->z,
                          .vx = b->vx,
                          .vy = b->vy,
                          .vz = b->vz,
                          .radius = b->r,
                          .id = b->id,
                          .dir = b->dir,
                          .hist = b->hist};
    return ok;
}

static void zblock_free(zblock *b)
{
    for (int i = 0; i < NP; i++) {
        free(b->dir[i]);
        free(b->hist[i]);
    }
}

/* Entry e of o is a new contact of a sphere with velocity v against the plane (n, t1):
 * drot = I, rdisp(2:3) = drdisp(2:3) = (v.t1, v.t2) dt, drdisp(1) = -v.n dt, rdisp(1) =
 * R - dist, and its slot's stress and statev zero. */
static int is_new_contact(const rs_track_out *o, int e, const double v[3],
                          const double n[3], const double t1[3], double pen, double dt)
{
    double t2[3];
    rs_cross3(n, t1, t2);
    const double tol = 1e-15;
    int ok = RS_DROT(o->drot, 0, 0, e) == 1.0 && RS_DROT(o->drot, 1, 1, e) == 1.0 &&
             RS_DROT(o->drot, 0, 1, e) == 0.0 && RS_DROT(o->drot, 1, 0, e) == 0.0;
    ok &= fabs(RS_A2(o->rdisp, 3, 0, e) - pen) <= tol;
    ok &= fabs(RS_A2(o->drdisp, 3, 0, e) + rs_dot3(v, n) * dt) <= tol;
    ok &= fabs(RS_A2(o->rdisp, 3, 1, e) - rs_dot3(v, t1) * dt) <= tol;
    ok &= fabs(RS_A2(o->rdisp, 3, 2, e) - rs_dot3(v, t2) * dt) <= tol;
    ok &= RS_A2(o->drdisp, 3, 1, e) == RS_A2(o->rdisp, 3, 1, e);
    ok &= RS_A2(o->drdisp, 3, 2, e) == RS_A2(o->rdisp, 3, 2, e);
    for (int b = 0; b < 3 + NS; b++)
        ok &= o->slot[e][RS_H_STRESS + b] == 0.0;
    return ok;
}

/* Directories in calloc'd memory: a first contact of feature 0 (the value zeroed memory
 * would have meant under a feature-as-is encoding) starts as a new contact, a particle
 * without contacts has no entries, and the next call adds a second contact of another
 * feature on the same particle while the first carries its slip. Capacities 4 (the
 * tracker's fast path for 4 slots) and 3. */
static void test_zeroed_directory_is_empty(void)
{
    const double n0[3] = {0, 0, 1}, a0[3] = {1, 0, 0}; /* floor z = 0, feature 0 */
    const double n1[3] = {1, 0, 0}, a1[3] = {0, 1, 0}; /* wall x = 0, feature 4 */
    const int f0 = RS_FEATURE(RS_FEAT_FACE, 0), f1 = RS_FEATURE(RS_FEAT_FACE, 1);
    const double R = 0.01, pen = 2e-4, dt = 1e-3;
    const double v[3] = {-0.3, 0.2, -0.1};
    for (int cap = 3; cap <= 4; cap++) {
        zblock b;
        ENSURE(zblock_init(&b, cap));
        rs_tracker tr = {cap, NS, 3, 1e-3, 0};
        rs_track_out o;
        memset(&o, 0, sizeof o);
        rs_error err;
        rs_error_clear(&err);
        /* particles 0 and 2 touch the floor; particle 1 is far away */
        for (int i = 0; i < NP; i++) {
            b.x[i] = 0.5 * i + R - pen + 0.004; /* clear of the wall x = 0 at first */
            b.y[i] = 0.0;
            b.z[i] = i == 1 ? 1.0 : R - pen;
            b.vx[i] = v[0];
            b.vy[i] = v[1];
            b.vz[i] = v[2];
        }
        rs_test_clist l;
        rs_test_clist_init(&l);
        for (int i = 0; i < NP; i++) {
            const double x[3] = {b.x[i], b.y[i], b.z[i]};
            if (i != 1)
                add_plane(&l, i, f0, x, n0, a0);
        }
        ENSURE(rs_track_update(&tr, NULL, NULL, dt, &b.p, &l.c, &o, &err) == RS_OK);
        ENSURE(o.n == 2 && o.nleave == 0);
        for (int e = 0; e < 2; e++) {
            ENSURE(o.point[e] == 2 * e && o.feature[e] == f0);
            ENSURE(is_new_contact(&o, e, v, n0, a0, pen, dt));
            ENSURE(*o.dir[e] == RS_DIR_LIVE(f0));
        }
        rs_track_commit(&tr, &o, NULL, NULL);
        for (int j = 1; j < cap; j++)
            ENSURE(b.dir[0][j] == RS_DIR_EMPTY && b.dir[1][j - 1] == RS_DIR_EMPTY);

        /* Next call: particle 0 has moved by v dt and now also touches the wall x = 0
         * with the same penetration. */
        rs_test_clist_init(&l);
        for (int i = 0; i < NP; i++) {
            b.x[i] += v[0] * dt;
            b.y[i] += v[1] * dt;
            b.z[i] += v[2] * dt;
        }
        b.x[0] = R - pen;
        b.z[0] = R - pen;
        for (int i = 0; i < NP; i++) {
            const double x[3] = {b.x[i], b.y[i], b.z[i]};
            if (i == 0)
                add_plane(&l, 0, f1, x, n1, a1);
            if (i != 1)
                add_plane(&l, i, f0, x, n0, a0);
        }
        /* the contacts of particle 0 are listed wall first: it takes a free slot */
        ENSURE(rs_track_update(&tr, NULL, NULL, dt, &b.p, &l.c, &o, &err) == RS_OK);
        ENSURE(o.n == 3 && o.nleave == 0);
        ENSURE(o.point[0] == 0 && o.feature[0] == f1);
        ENSURE(is_new_contact(&o, 0, v, n1, a1, pen, dt));
        ENSURE(o.point[1] == 0 && o.feature[1] == f0);
        /* the floor contact carries its slip: two increments of v.t dt, drot = I */
        ENSURE(RS_DROT(o.drot, 0, 0, 1) == 1.0 && RS_DROT(o.drot, 1, 0, 1) == 0.0);
        ENSURE_NEAR(RS_A2(o.rdisp, 3, 1, 1), 2 * v[0] * dt, 1e-15);
        ENSURE_NEAR(RS_A2(o.rdisp, 3, 2, 1), 2 * v[1] * dt, 1e-15);
        ENSURE(RS_A2(o.drdisp, 3, 0, 1) == 0.0); /* the same penetration */
        ENSURE(o.slot[1] == b.hist[0] && o.slot[0] != o.slot[1]);
        ENSURE(o.point[2] == 2 && o.feature[2] == f0);
        rs_track_commit(&tr, &o, NULL, NULL);
        int live = 0;
        for (int j = 0; j < cap; j++)
            live += RS_DIR_IS_LIVE(b.dir[0][j]);
        ENSURE(live == 2);
        rs_track_out_free(&o);
        zblock_free(&b);
    }
}

/* A directory holding one feature in two slots: RS_ERR_HISTORY naming the particle's id
 * and the feature, whether a contact of that feature comes (which the slot would match),
 * another feature comes, or none; in a block alone and among other particles. */
static void test_feature_in_two_slots_is_error(void)
{
    const double n0[3] = {0, 0, 1}, a0[3] = {1, 0, 0};
    const int f = RS_FEATURE(RS_FEAT_FACE, 3), g = RS_FEATURE(RS_FEAT_EDGE, 5);
    const double R = 0.01, pen = 2e-4, dt = 1e-3;
    for (int cap = 2; cap <= 4; cap++)
        for (int which = 0; which < 3; which++) {
            zblock b;
            ENSURE(zblock_init(&b, cap));
            rs_tracker tr = {cap, NS, 3, 1e-3, 0};
            rs_track_out o;
            memset(&o, 0, sizeof o);
            rs_error err;
            rs_error_clear(&err);
            rs_test_clist l;
            rs_test_clist_init(&l);
            for (int i = 0; i < NP; i++) {
                b.x[i] = 0.5 * i;
                b.z[i] = R - pen;
                const double x[3] = {b.x[i], b.y[i], b.z[i]};
                if (i != 1 || which < 2)
                    add_plane(&l, i, i == 1 && which == 1 ? g : f, x, n0, a0);
            }
            /* particles 0 and 2 hold f once; particle 1 (id 4712) twice */
            b.dir[0][0] = b.dir[2][cap - 1] = RS_DIR_LIVE(f);
            b.dir[1][0] = b.dir[1][cap - 1] = RS_DIR_LIVE(f);
            char want[64];
            snprintf(want, sizeof want, "feature %d", f);
            ENSURE(rs_track_update(&tr, NULL, NULL, dt, &b.p, &l.c, &o, &err) ==
                   RS_ERR_HISTORY);
            ENSURE(err.code == RS_ERR_HISTORY);
            ENSURE(strstr(err.msg, "particle 4712") != NULL);
            ENSURE(strstr(err.msg, want) != NULL);
            /* the other particles alone: no error */
            b.dir[1][0] = RS_DIR_EMPTY;
            ENSURE(rs_track_update(&tr, NULL, NULL, dt, &b.p, &l.c, &o, &err) == RS_OK);
            rs_track_out_free(&o);
            zblock_free(&b);
        }
}

/* The encoding: zero is empty; live and leaving entries give back their feature, and
 * neither is taken for the other or for empty. */
static void test_directory_encoding(void)
{
    ENSURE(RS_DIR_EMPTY == 0.0);
    ENSURE(!RS_DIR_IS_LIVE(RS_DIR_EMPTY) && !RS_DIR_IS_LEAVING(RS_DIR_EMPTY));
    const int fs[] = {0, 1, 2, 3, RS_FEATURE(RS_FEAT_VERTEX, 77), 1 << 28};
    for (size_t k = 0; k < sizeof fs / sizeof fs[0]; k++) {
        const double l = RS_DIR_LIVE(fs[k]), g = RS_DIR_LEAVING(fs[k]);
        ENSURE(RS_DIR_IS_LIVE(l) && !RS_DIR_IS_LEAVING(l));
        ENSURE(RS_DIR_IS_LEAVING(g) && !RS_DIR_IS_LIVE(g));
        ENSURE(RS_DIR_FEATURE(l) == fs[k] && RS_DIR_FEATURE(g) == fs[k]);
    }
}

int main(void)
{
    RS_RUN(test_directory_encoding);
    RS_RUN(test_zeroed_directory_is_empty);
    RS_RUN(test_feature_in_two_slots_is_error);
    return rs_test_summary();
}
