/* The tracker's history around the law call: the previous stress and state of each
 * entry into the law's arrays (rs_track_load), the law's results back into the slots
 * (rs_track_commit), a particle's slots cleared (rs_track_clear), and a slot carried
 * from one layout to another (rs_track_slot_convert). Slot layout: track.h. */
#include "rigidsurf/track.h"

#include "rs_compiler.h"
#include "rs_v4.h"

#include <string.h>

/* statev(ns, e) <-> the slot's statev for one entry; ns is a constant in the copies
 * for the common counts. */
RS_INLINE void copy_statev(double *restrict dst, const double *restrict src, const int ns)
{
    for (int b = 0; b < ns; b++)
        dst[b] = src[b];
}

#define RS_STATEV_COPY(NS, DST, SRC)                                                       \
    switch (NS) {                                                                          \
    case 1:                                                                                \
        copy_statev(DST, SRC, 1);                                                          \
        break;                                                                             \
    case 2:                                                                                \
        copy_statev(DST, SRC, 2);                                                          \
        break;                                                                             \
    default:                                                                               \
        copy_statev(DST, SRC, NS);                                                         \
    }

/* The previous stress of the n entries (none leaving, ndir = 3), kept at so in the slots,
 * 4 at a time: rows (the value before it, s1, s2, s3) of the slots and the entries' drot
 * to columns, the shear carried by drot, and the rows of stress(3, n). */
RS_INLINE void load_stress3(const rs_track_out *out, int n, int so, double *restrict stress)
{
    int e = 0;
    for (; e + 4 <= n; e += 4) {
        double *const *h = out->slot + e;
        const double *dr = out->drot + (size_t)4 * e;
        double rd[4], s1[4], s2[4], s3[4], d0[4], d1[4], d2[4], d3[4], u2[4], u3[4];
        rs_transpose4(h[0] + so - 1, h[1] + so - 1, h[2] + so - 1, h[3] + so - 1, rd, s1,
                      s2, s3);
        rs_transpose4(dr, dr + 4, dr + 8, dr + 12, d0, d1, d2, d3);
        for (int l = 0; l < 4; l++) {
            u2[l] = d0[l] * s2[l] + d2[l] * s3[l];
            u3[l] = d1[l] * s2[l] + d3[l] * s3[l];
        }
        rs_cols3_to_rows4(s1, u2, u3, stress + (size_t)3 * e);
    }
    for (; e < n; e++) {
        const double *h = out->slot[e], *dr = out->drot + (size_t)4 * e;
        const double s2 = h[so + 1], s3 = h[so + 2];
        stress[3 * e] = h[so];
        stress[3 * e + 1] = dr[0] * s2 + dr[2] * s3;
        stress[3 * e + 2] = dr[1] * s2 + dr[3] * s3;
    }
}

RS_MULTIVERSION
void rs_track_load(const rs_tracker *tr, const rs_track_out *out, double *stress,
                   double *statev)
{
    const int nd = out->ndir, ns = tr->nstatev, n = out->n, sv0 = rs_track_statev_at(tr);
    const int so = rs_track_stress_at(tr);
    if (stress && (tr->drop & RS_DROP_STRESS)) {
        memset(stress, 0, (size_t)nd * (size_t)n * sizeof *stress);
    } else if (stress && nd == 2) {
        for (int e = 0; e < n; e++) {
            const double *h = out->slot[e];
            stress[2 * e] = h[so];
            stress[2 * e + 1] = h[so + 1];
        }
    } else if (stress && out->nleave == 0) {
        /* The shear traction is carried into this increment's basis, as the slip. */
        load_stress3(out, n, so, stress);
    } else if (stress) {
        /* As above; a leaving contact keeps its own. */
        for (int e = 0; e < n; e++) {
            const double *h = out->slot[e], *dr = out->drot + (size_t)4 * e;
            const double s2 = h[so + 1], s3 = h[so + 2];
            const int keep = RS_DIR_IS_LEAVING(*out->dir[e]);
            stress[3 * e] = h[so];
            stress[3 * e + 1] = keep ? s2 : dr[0] * s2 + dr[2] * s3;
            stress[3 * e + 2] = keep ? s3 : dr[1] * s2 + dr[3] * s3;
        }
    }
    if (statev && ns > 0)
        for (int e = 0; e < n; e++)
            RS_STATEV_COPY(ns, statev + (size_t)ns * e, out->slot[e] + sv0)
}

void rs_track_commit(const rs_tracker *tr, rs_track_out *out, const double *stress,
                     const double *statev)
{
    const int nd = out->ndir, ns = tr->nstatev, anyleave = out->nleave > 0;
    const int sv0 = rs_track_statev_at(tr), so = rs_track_stress_at(tr);
    if (tr->drop & RS_DROP_STRESS)
        stress = NULL;
    if (!anyleave && nd == 3 && (stress || (statev && ns > 0))) {
        /* The usual call: every entry live, stress(3, n). */
        if (stress)
            for (int e = 0; e < out->n; e++) {
                double *h = out->slot[e];
                const double *se = stress + (size_t)3 * e;
                h[so] = se[0];
                h[so + 1] = se[1];
                h[so + 2] = se[2];
            }
        if (statev && ns > 0)
            for (int e = 0; e < out->n; e++)
                RS_STATEV_COPY(ns, out->slot[e] + sv0, statev + (size_t)ns * e)
        return;
    }
    for (int e = 0; e < out->n; e++) {
        double *h = out->slot[e];
        if (anyleave && RS_DIR_IS_LEAVING(*out->dir[e])) {
            *out->dir[e] = RS_DIR_EMPTY;
            continue;
        }
        if (stress) {
            const double *se = stress + (size_t)nd * e;
            h[so] = se[0];
            h[so + 1] = se[1];
            h[so + 2] = nd == 3 ? se[2] : 0.0;
        }
        if (statev && ns > 0)
            RS_STATEV_COPY(ns, h + sv0, statev + (size_t)ns * e)
    }
}

void rs_track_load_energy(const rs_tracker *tr, const rs_track_out *out, double *sed,
                          double *flux_slv, double *flux_mst)
{
    const int n = out->n;
    if (tr->drop & RS_DROP_ENERGY) {
        memset(sed, 0, (size_t)n * sizeof *sed);
        memset(flux_slv, 0, (size_t)n * sizeof *flux_slv);
        memset(flux_mst, 0, (size_t)n * sizeof *flux_mst);
        return;
    }
    const int en = rs_track_energy_at(tr);
    for (int e = 0; e < n; e++) {
        const double *h = out->slot[e] + en;
        sed[e] = h[0];
        flux_slv[e] = h[1];
        flux_mst[e] = h[2];
    }
}

void rs_track_commit_energy(const rs_tracker *tr, const rs_track_out *out,
                            const double *sed, const double *flux_slv,
                            const double *flux_mst)
{
    if (tr->drop & RS_DROP_ENERGY)
        return;
    const int en = rs_track_energy_at(tr);
    for (int e = 0; e < out->n; e++) {
        double *h = out->slot[e] + en;
        const int live = !RS_DIR_IS_LEAVING(*out->dir[e]);
        h[0] = live ? sed[e] : 0.0;
        h[1] = live ? flux_slv[e] : 0.0;
        h[2] = live ? flux_mst[e] : 0.0;
    }
}

void rs_track_clear(const rs_tracker *tr, double *dir, double *hist, ptrdiff_t stride)
{
    const int hs = rs_track_slot_size(tr);
    for (int j = 0; j < tr->capacity; j++) {
        dir[j] = RS_DIR_EMPTY;
        memset(hist + j * (stride ? stride : hs), 0, (size_t)hs * sizeof *hist);
    }
}

void rs_track_slot_convert(const rs_tracker *tr, unsigned from, const double *src,
                           double *dst)
{
    rs_tracker f = *tr;
    f.drop = from;
    const unsigned both = ~(tr->drop | from);
    memset(dst, 0, (size_t)rs_track_slot_size(tr) * sizeof *dst);
    memcpy(dst + RS_H_N, src + RS_H_N, 6 * sizeof *dst); /* n, t1 */
    if (both & RS_DROP_SLIP)
        memcpy(dst + RS_H_SLIP, src + RS_H_SLIP, 3 * sizeof *dst); /* slip, rdisp1 */
    if (both & RS_DROP_STRESS)
        memcpy(dst + rs_track_stress_at(tr), src + rs_track_stress_at(&f), 3 * sizeof *dst);
    if (tr->nstatev > 0)
        memcpy(dst + rs_track_statev_at(tr), src + rs_track_statev_at(&f),
               (size_t)tr->nstatev * sizeof *dst);
    if (both & RS_DROP_ENERGY)
        memcpy(dst + rs_track_energy_at(tr), src + rs_track_energy_at(&f), 3 * sizeof *dst);
}
