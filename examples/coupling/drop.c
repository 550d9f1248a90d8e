/* Spheres dropped on a floor that a DEM code holds as arrays: the rigidsurf calls of one
 * time step in a DEM code of one's own (docs/coupling.md). The floor z = 0 is a square of
 * two triangles (rs_surface_make_mesh), the law the built-in hertz; the spheres do not
 * touch each other. Prints each sphere's rest height and overlap. */
#include <rigidsurf/contact_block.h>
#include <rigidsurf/law.h>
#include <rigidsurf/motion.h>
#include <rigidsurf/surface.h>
#include <rigidsurf/track.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

enum { N = 3, CAP = 4 }; /* spheres; history slots per sphere */
static const double RHO = 2500.0, G = 9.81, DT = 1e-5, T_END = 0.6;
/* hertz: Y_particle nu_particle Y_wall nu_wall restitution friction curvature */
static const double PROPS[7] = {1e7, 0.3, 1e7, 0.3, 0.5, 0.4, 0.0};

static int fail(const rs_error *err)
{
    fprintf(stderr, "drop: %s\n", err->msg);
    return 1;
}

int main(void)
{
    const double xyz[12] = {-0.1, -0.1, 0, 0.1, -0.1, 0, 0.1, 0.1, 0, -0.1, 0.1, 0};
    const int tri[6] = {0, 1, 2, 0, 2, 3}; /* counter-clockwise seen from +z: n = +z */
    rs_surface floor;
    rs_error err;
    if (rs_surface_make_mesh(xyz, 4, tri, 2, NULL, &floor, &err) != RS_OK)
        return fail(&err);
    const rs_law *law = rs_law_find("hertz");
    if (rs_law_check_props(law, PROPS, 7, &err) != RS_OK)
        return fail(&err);

    /* the spheres: centres, velocities, spins, radii, masses, ids */
    double x[N], y[N], z[N], vx[N] = {0}, vy[N] = {0}, vz[N] = {0};
    double wx[N] = {0}, wy[N] = {0}, wz[N] = {0}, r[N], m[N];
    int id[N];
    for (int i = 0; i < N; i++) {
        r[i] = 0.004 + 0.001 * i;
        m[i] = RHO * 4.0 / 3.0 * 3.14159265358979324 * r[i] * r[i] * r[i];
        x[i] = -0.05 + 0.05 * i, y[i] = 0.0, z[i] = r[i] + 0.01 * (i + 1);
        vx[i] = 0.05 * (i - 1); /* sliding and rolling too */
        id[i] = i + 1;
    }
    /* history: per sphere a directory of CAP doubles, then CAP slots; zeroed = empty */
    rs_tracker tr = {CAP, law->nstatev, rs_surface_ndir(&floor), 0.0, rs_law_drops(law)};
    const ptrdiff_t slot = rs_track_slot_size(&tr), per = CAP * (1 + slot);
    double *hist = calloc((size_t)(N * per), sizeof *hist), *dir[N], *slot0[N];
    for (int i = 0; i < N; i++)
        dir[i] = hist + i * per, slot0[i] = dir[i] + CAP;

    rs_motion motion; /* the floor stays in place; a moving wall sets its rates here */
    rs_motion_init(&motion);
    rs_contacts c = {0};
    rs_track_out trk = {0};
    rs_contact_block cb = {0};
    cb.area_mode = RS_AREA_NODE; /* hertz returns force: stress per unit area */
    cb.ndir = tr.ndir, cb.nstatev = tr.nstatev;
    if (!hist || rs_cblock_reserve(&cb, N * CAP, &err) != RS_OK)
        return fail(&err);

    const int nd = tr.ndir, nstep = (int)(T_END / DT + 0.5);
    for (int step = 0; step < nstep; step++) {
        if (step > 0 && rs_motion_advance(&motion, DT, &err) != RS_OK)
            return fail(&err);
        /* the spheres as one block, which every call below reads */
        const rs_particle_block p = {.n = N,
                                     .x = x,
                                     .y = y,
                                     .z = z,
                                     .radius = r,
                                     .vx = vx,
                                     .vy = vy,
                                     .vz = vz,
                                     .wx = wx,
                                     .wy = wy,
                                     .wz = wz,
                                     .id = id,
                                     .dir = dir,
                                     .hist = slot0,
                                     .slot_stride = slot,
                                     .mass = m};
        /* 1. contacts of the spheres with the floor in its current pose */
        rs_query q = {.n = N,
                      .slave = p,
                      .pose = &motion.pose,
                      .gap_max = tr.tracking,
                      .dist_min = -INFINITY};
        c.n = 0;
        if (rs_surface_query(&floor, &q, &c, &err) != RS_OK)
            return fail(&err);
        /* 2. matched to history: overlap, slip, frame rotation; leaving contacts */
        if (rs_track_update(&tr, &floor, &motion, step ? DT : 0.0, &p, &c, &trk, &err))
            return fail(&err);
        /* 3. the law's inputs: last stress and state, then per-contact values */
        rs_track_load(&tr, &trk, cb.stress, cb.statev);
        rs_cblock_inputs(&cb, &trk, &p, DT);
        rs_track_load_energy(&tr, &trk, cb.sed, cb.flux_slv, cb.flux_mst);
        rs_law_block b;
        rs_law_block_init(&b);
        b.kInc = step + 1, b.nDir = nd, b.nSurfDir = nd - 1;
        b.nStateVar = tr.nstatev, b.nProps = 7, b.props = PROPS;
        b.timStep = b.timGlb = step * DT, b.dTimCur = DT;
        b.analytic_master = !rs_surface_has_facets(&floor);
        if (rs_cblock_call(&cb, law, &b, &trk, &err) != RS_OK)
            return fail(&err);
        /* 4. F = w A (s1 n - s2 t1 - s3 t2) at the contact point and its torque per
         * contact (and the floor's totals), scattered onto the spheres; before the
         * commit, which frees the slots of leaving contacts (they apply nothing) */
        double fe[N * CAP][3], te[N * CAP][3], f[N][3] = {{0}}, t[N][3] = {{0}};
        const double origin[3] = {0, 0, 0};
        rs_wall_load wall;
        rs_cblock_loads(&cb, &trk, &p, origin, fe[0], te[0], NULL, &wall);
        for (int e = 0; e < trk.n; e++)
            for (int k = 0; k < 3; k++) {
                f[trk.point[e]][k] += fe[e][k];
                t[trk.point[e]][k] += te[e][k];
            }
        /* 5. stress, state, energies into history; leaving contacts' slots freed */
        rs_track_commit_energy(&tr, &trk, cb.sed, cb.flux_slv, cb.flux_mst);
        rs_track_commit(&tr, &trk, cb.stress, cb.statev);

        /* 6. explicit integration (symplectic Euler), gravity along -z */
        for (int i = 0; i < N; i++) {
            const double I = 0.4 * m[i] * r[i] * r[i];
            vx[i] += DT * f[i][0] / m[i], vy[i] += DT * f[i][1] / m[i];
            vz[i] += DT * (f[i][2] / m[i] - G);
            x[i] += DT * vx[i], y[i] += DT * vy[i], z[i] += DT * vz[i];
            wx[i] += DT * t[i][0] / I, wy[i] += DT * t[i][1] / I, wz[i] += DT * t[i][2] / I;
        }
    }
    for (int i = 0; i < N; i++)
        printf("sphere %d R %.9g z %.12g overlap %.9e v %.9e\n", id[i], r[i], z[i],
               r[i] - z[i], sqrt(vx[i] * vx[i] + vy[i] * vy[i] + vz[i] * vz[i]));
    rs_cblock_free(&cb);
    rs_track_out_free(&trk);
    rs_contacts_free(&c);
    rs_surface_free(&floor);
    free(hist);
    return 0;
}
