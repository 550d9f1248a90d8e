/* The tracker's pass 1 for a particle the fast paths of track.c do not take
 * (rs_track_assign_slots): its contacts matched to its history slots by feature,
 * handovers to adjacent features, new contacts in free slots (a body's seeded with its
 * neighbour's history across a concave fold), leaving slots listed. */
#include "track_slots.h"

#include "rs_compiler.h"

#include <stdint.h>
#include <string.h>

/* A body's new contacts (their slots sl[q] were free: not in active) that begin overlapping
 * beside a held contact of the same manifold point on a face across a concave fold (a facet
 * of a drum that the body moves onto, where the two contacts share its patch) continue that
 * contact's history: its slot is copied into the new one, which is free (so an error
 * later in pass 1 leaves the history as it was), and the entry (e0 + q) is listed in
 * out->seeded for pass 2 to read as live. */
static RS_NOINLINE void seed_body_slots(const rs_surface *s, const rs_particles *p, int i,
                                        const rs_contacts *c, const int *kk, const int *sl,
                                        int nk, uint64_t active, double *h,
                                        ptrdiff_t stride, rs_track_out *out, int e0)
{
    const double rad = p->radius ? p->radius[i] : 0.0;
    for (int q = 0; q < nk; q++) {
        if ((active >> sl[q] & 1u) || !(c->dist[kk[q]] < rad))
            continue;
        for (int r = 0; r < nk; r++)
            if ((active >> sl[r] & 1u) &&
                rs_surface_fold(s, c->feature[kk[r]], c->feature[kk[q]])) {
                memcpy(h + sl[q] * stride, h + sl[r] * stride, (size_t)stride * sizeof *h);
                out->seeded[out->nseeded++] = e0 + q;
                break;
            }
    }
}

int rs_track_assign_slots(const rs_tracker *tr, const rs_surface *s, const rs_particles *p,
                          ptrdiff_t stride, const rs_contacts *c, int i, int kb, int ke,
                          rs_track_out *out, int *ne, rs_error *err)
{
    const int cap = tr->capacity;
    double *h = p->hist[i], *d = p->dir ? p->dir[i] : NULL;
    if (!h || !d)
        return rs_error_set(err, RS_ERR_ARG,
                            "rs_track_update: particle %d has no history storage",
                            p->id ? p->id[i] : i);
    const double rad = p->radius ? p->radius[i] : 0.0;
    int kk[RS_TRACK_MAX_CAPACITY], sl[RS_TRACK_MAX_CAPACITY], fe[RS_TRACK_MAX_CAPACITY];
    int nk = 0, unmatched = 0;
    uint64_t active = 0, used = 0;

    /* One look at the directory: live features (fe[j] is valid where active has bit
     * j), each in one slot only; slots left leaving by an uncommitted call are freed
     * (they were emitted once). */
    for (int j = 0; j < cap; j++) {
        if (RS_DIR_IS_LIVE(d[j])) {
            fe[j] = RS_DIR_FEATURE(d[j]);
            for (int q = 0; q < j; q++)
                if ((active >> q & 1u) && fe[q] == fe[j])
                    return rs_error_set(err, RS_ERR_HISTORY,
                                        "rs_track_update: particle %d holds feature %d in "
                                        "history slots %d and %d of surface '%s'",
                                        p->id ? p->id[i] : i, fe[j], q, j,
                                        s ? s->name : "");
            active |= (uint64_t)1 << j;
        } else if (RS_DIR_IS_LEAVING(d[j])) {
            d[j] = RS_DIR_EMPTY;
        }
    }

    for (int k = kb; k < ke; k++) {
        if (c->dist[k] - rad > tr->tracking)
            continue;
        if (nk == cap)
            goto full;
        int f = c->feature[k], js = -1;
        for (int j = 0; j < cap; j++)
            if (((active & ~used) >> j & 1u) && fe[j] == f) {
                js = j;
                used |= (uint64_t)1 << j;
                break;
            }
        unmatched += js < 0;
        kk[nk] = k;
        sl[nk++] = js;
    }

    if (unmatched) {
        /* Handover: an orphan slot whose feature is adjacent to the new one. */
        for (int q = 0; q < nk && s; q++) {
            if (sl[q] >= 0)
                continue;
            for (int j = 0; j < cap; j++)
                if (((active & ~used) >> j & 1u) &&
                    rs_surface_adjacent(s, fe[j], c->feature[kk[q]])) {
                    sl[q] = j;
                    used |= (uint64_t)1 << j;
                    break;
                }
        }
        /* New contacts take free slots; orphans keep theirs for the leaving call. */
        for (int q = 0; q < nk; q++) {
            if (sl[q] >= 0)
                continue;
            int js = -1;
            for (int j = 0; j < cap && js < 0; j++)
                if (!((active | used) >> j & 1u))
                    js = j;
            if (js < 0)
                goto full;
            sl[q] = js;
            used |= (uint64_t)1 << js;
        }
        if (s && p->body && p->body[i].shape)
            seed_body_slots(s, p, i, c, kk, sl, nk, active, h, stride, out, *ne);
    }

    for (int q = 0; q < nk; q++) {
        out->point[*ne] = kk[q];
        out->slot[*ne] = h + sl[q] * stride;
        out->dir[*ne] = d + sl[q];
        (*ne)++;
    }
    uint64_t leaving = active & ~used;
    for (int j = 0; leaving && j < cap; j++)
        if (leaving >> j & 1u) {
            out->point[*ne] = -1 - i;
            out->slot[*ne] = h + j * stride;
            out->dir[*ne] = d + j;
            (*ne)++;
        }
    return RS_OK;

full:
    return rs_error_set(err, RS_ERR_CAPACITY,
                        "rs_track_update: particle %d touches surface '%s' at more "
                        "features than its history capacity %d (raise the capacity)",
                        p->id ? p->id[i] : i, s ? s->name : "", cap);
}
