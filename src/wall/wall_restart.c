/* The wall's global restart record: its layout version, the history's layout (capacity,
 * state variables, fields), the motion, the wall's heat and energy totals, the facets'
 * wear, the servo's controller and the spin. */
#include "wall_impl.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Restart layout version (global record).
 * 7: the global record ends with the spin's angle, its remainder, rate and orientation S
 *    (12 doubles; absent in 6, read as no spin so far);
 * 6: directory entries are RS_DIR_LIVE(f) = f + 1, empty 0, leaving -(f + 1) (5: f, -1
 *    and -2 - f, so an entry of 5 is one less: read and converted), and the global record
 *    ends with the servo's controller state (integral of the error, last process value;
 *    absent in 5);
 * 4: a slot ends with the contact's sed, fluxSlv and fluxMst; 3: each atom's record starts
 *    with the capacity it was written with (the capacity grows during a run); 2: directory
 *    in the row, slots after it. */
static const double kRestartVersion = 7.0;
/* The oldest version read: 5, its directories converted (rs_wall_unpack_restart). */
static const double kRestartOldest = 5.0;

enum {
    RST_VERSION,
    RST_CAPACITY,
    RST_NSTATEV,
    RST_NPRED,
    RST_T,
    RST_T_ERR,
    RST_DISP,
    RST_DISP_ERR = RST_DISP + 3,
    RST_PHI = RST_DISP_ERR + 3,
    RST_PHI_ERR,
    RST_VEL,
    RST_OMEGA = RST_VEL + 3,
    RST_TEMP,
    RST_DTEMP,
    RST_HEAT,
    RST_DISS,
    RST_COUNT = RST_DISS + 4
};

static int nwear(const rs_wall *w)
{
    return w->wear ? w->nfacet : 0;
}

int rs_wall_restart_size(rs_wall *w)
{
    return RST_COUNT + 1 + nwear(w) + 2 + 12;
}

void rs_wall_write_restart(rs_wall *w, double *list)
{
    double all[5] = {w->heat_wall, w->diss[0], w->diss[1], w->diss[2], w->diss[3]};
    if (w->host.reduce)
        w->host.reduce(w->host.ctx, all, 5, RS_REDUCE_SUM);
    const rs_motion *m = w->motion;
    list[RST_VERSION] = kRestartVersion;
    /* ranks may have grown apart: the largest */
    list[RST_CAPACITY] = wall_reduce1(w, w->capacity, RS_REDUCE_MAX);
    list[RST_NSTATEV] = w->nstatev;
    list[RST_NPRED] = w->npred;
    list[RST_T] = m->t;
    list[RST_T_ERR] = m->t_err;
    for (int d = 0; d < 3; d++) {
        list[RST_DISP + d] = m->disp[d];
        list[RST_DISP_ERR + d] = m->disp_err[d];
        list[RST_VEL + d] = m->vel[d];
    }
    list[RST_PHI] = m->phi;
    list[RST_PHI_ERR] = m->phi_err;
    list[RST_OMEGA] = m->omega;
    list[RST_TEMP] = w->temp_wall;
    list[RST_DTEMP] = w->dtemp_wall;
    list[RST_HEAT] = all[0];
    for (int d = 0; d < 4; d++)
        list[RST_DISS + d] = all[1 + d];
    /* then the facets' wear (`wear finnie`): its count and the totals */
    const int nw = nwear(w);
    double *wear = list + RST_COUNT;
    wear[0] = nw;
    if (nw) {
        memcpy(wear + 1, w->wear_el, (size_t)nw * sizeof *wear);
        if (w->host.reduce)
            w->host.reduce(w->host.ctx, wear + 1, nw, RS_REDUCE_SUM);
    }
    double *servo = wear + 1 + nw;
    servo[0] = w->servo.sum_err;
    servo[1] = w->servo.old_pv;
    /* then the spin (from version 7): its angle, remainder, rate and the orientation S */
    double *spin = servo + 2;
    spin[0] = m->spin_phi;
    spin[1] = m->spin_phi_err;
    spin[2] = m->spin_omega;
    memcpy(spin + 3, m->S, sizeof m->S);
}

int rs_wall_read_restart(rs_wall *w, const double *list, int n, rs_error *err)
{
    const double version = n > RST_VERSION ? list[RST_VERSION] : 0.0;
    if (!(version >= kRestartOldest && version <= kRestartVersion) ||
        version != (double)(int)version)
        return rs_error_set(err, RS_ERR_ARG,
                            "the restart file holds wall/rigid data of layout version %g; "
                            "this build reads versions %g to %g (write the restart file "
                            "again with a matching build)",
                            version, kRestartOldest, kRestartVersion);
    if (n < RST_COUNT + 1)
        return rs_error_set(err, RS_ERR_ARG,
                            "the restart file's wall/rigid record holds %d values, fewer "
                            "than its layout's %d",
                            n, RST_COUNT + 1);
    w->restart_version = version;
    if ((int)list[RST_NSTATEV] != w->nstatev || (int)list[RST_NPRED] != w->npred)
        return rs_error_set(
            err, RS_ERR_ARG,
            "restart file has %d state variables and %d predef fields; this "
            "fix has %d and %d (keep the law, statev and predef unchanged)",
            (int)list[RST_NSTATEV], (int)list[RST_NPRED], w->nstatev, w->npred);
    /* the contact capacity the run had grown to */
    const int cap = (int)list[RST_CAPACITY];
    if (cap > w->capacity && wall_grow_capacity(w, cap, err) != RS_OK)
        return rs_error_set(err, RS_ERR_CAPACITY,
                            "restart file has %d contact slots per atom; this fix can hold "
                            "at most %d",
                            cap, wall_max_capacity(w));
    rs_motion *m = w->motion;
    m->t = list[RST_T];
    m->t_err = list[RST_T_ERR];
    for (int d = 0; d < 3; d++) {
        m->disp[d] = list[RST_DISP + d];
        m->disp_err[d] = list[RST_DISP_ERR + d];
        if (w->var_vel[d][0])
            m->vel[d] = list[RST_VEL + d];
    }
    m->phi = list[RST_PHI];
    m->phi_err = list[RST_PHI_ERR];
    if (w->var_omega[0])
        m->omega = list[RST_OMEGA];
    /* the spin, when both the file (version 7 on) and this wall have one */
    const int nw = (int)list[RST_COUNT] > 0 ? (int)list[RST_COUNT] : 0;
    if (version >= 7.0 && m->spin_on && n >= RST_COUNT + 1 + nw + 2 + 12) {
        const double *spin = list + RST_COUNT + 1 + nw + 2;
        m->spin_phi = spin[0];
        m->spin_phi_err = spin[1];
        if (w->var_spin[0])
            m->spin_omega = spin[2];
        memcpy(m->S, spin + 3, sizeof m->S);
    }
    /* The pose from the restored phi and D: a zero step with the rates switched off. */
    rs_motion_rates_fn rates = m->rates;
    m->rates = NULL;
    rs_error e;
    rs_error_clear(&e);
    rs_motion_advance(m, 0.0, &e);
    m->rates = rates;
    w->temp_wall = list[RST_TEMP];
    w->dtemp_wall = list[RST_DTEMP];
    w->temp_mst[0] = w->temp_wall;
    w->dtemp_mst[0] = w->dtemp_wall;
    /* Totals live on rank 0; the others add their shares from here on. */
    const int root = w->host.rank == 0;
    w->heat_wall = root ? list[RST_HEAT] : 0.0;
    for (int d = 0; d < 4; d++)
        w->diss[d] = root ? list[RST_DISS + d] : 0.0;
    /* the facets' wear, when both the file and this wall keep it */
    if (w->wear && nw > 0) {
        const int nf = rs_surface_facet_count(w->surf);
        if (nw != nf)
            return rs_error_set(err, RS_ERR_ARG,
                                "restart file has the wear of %d facets; this fix's mesh "
                                "has %d (keep the surface unchanged)",
                                nw, nf);
        double *we = calloc((size_t)nf, sizeof *we);
        if (!we)
            return rs_error_set(err, RS_ERR_NOMEM, "out of memory for the facets' wear");
        if (root)
            memcpy(we, list + RST_COUNT + 1, (size_t)nf * sizeof *we);
        free(w->wear_el);
        w->wear_el = we;
    }
    /* the servo's controller (from version 6) and the rate it set, the same on every
     * rank */
    if (w->servo.on) {
        const double *servo = list + RST_COUNT + 1 + nw;
        w->servo.sum_err = version >= 6.0 ? servo[0] : 0.0;
        w->servo.old_pv = version >= 6.0 ? servo[1] : 0.0;
        for (int d = 0; d < 3; d++)
            m->vel[d] = list[RST_VEL + d];
        m->omega = list[RST_OMEGA];
    }
    return RS_OK;
}
