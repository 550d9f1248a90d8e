/* Convex bodies against an analytic surface (SEGMENTS, CYLINDER, REVOLUTION), the analytic
 * kinds' body operation (rs_surface_ops.body): per owning feature, the body's deepest
 * point along the feature's normal, found as a fixed point (convex.h,
 * rs_body_surface_contacts; docs/conventions.md, "Convex bodies"). The surface is asked
 * through its own point and sphere query (closest) only, for a block of bodies at once:
 * one query of their reach spheres, then one query of every body's iterate per step of
 * the fixed point. */
#include "convex_internal.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { BODY_ITER_MAX = 100 };

/* The contact of the query's entry j as a body contact with witness p. */
static void take(rs_body_contact *o, const rs_contacts *pc, int j, const double p[3],
                 int it)
{
    o->feature = pc->feature[j];
    o->depth = -pc->dist[j];
    o->iterations = it;
    for (int d = 0; d < 3; d++) {
        o->normal[d] = pc->nrm[d][j];
        o->xm[d] = pc->xm[d][j];
        o->xs[d] = p[d];
        o->t1[d] = pc->t1[d][j];
        o->t2[d] = pc->t2[d][j];
    }
    o->curv[0] = pc->curv[0][j];
    o->curv[1] = pc->curv[1][j];
}

/* The fixed point of one feature near one body. */
typedef struct fixed {
    int body, want, it, conv, found; /* found: a contact at the last iterate (-1: none) */
    double nrm[3], p[3];
    rs_body_contact best, got; /* the deepest iterate; the settled one */
} fixed;

/* One step of fixed point f with the contact c its iterate f->p has on the feature it
 * follows, else its deepest one (c->feature < 0: none, the body's deepest point meets no
 * feature here); 1 when f goes on. */
static int step(fixed *f, const rs_body_contact *c)
{
    f->found = c->feature;
    if (c->feature < 0)
        return 0;
    const double turn = fabs(c->normal[0] - f->nrm[0]) + fabs(c->normal[1] - f->nrm[1]) +
                        fabs(c->normal[2] - f->nrm[2]);
    f->conv = turn <= 1e-13 && RS_FEATURE_BASE(c->feature) == f->want;
    if (!f->conv && c->depth > f->best.depth) { /* (read only where none settles) */
        f->best = *c;
        f->best.iterations = -1;
    }
    f->want = RS_FEATURE_BASE(c->feature);
    memcpy(f->nrm, c->normal, sizeof f->nrm);
    f->it++;
    if (f->conv) {
        if (c != &f->got) /* (the kind's answer is made there) */
            f->got = *c;
        f->got.iterations = f->it;
    }
    return !f->conv && f->it < BODY_ITER_MAX;
}

int rs_body_fixed_point(const rs_surface *s, const rs_pose *pose, const rs_body *body,
                        int n, double gap_max, int lenient, rs_body_contacts *out,
                        rs_error *err)
{
    return rs_body_fixed_point_with(s, pose, body, n, gap_max, lenient, NULL, NULL, out,
                                    err);
}

int rs_body_fixed_point_with(const rs_surface *s, const rs_pose *pose, const rs_body *b,
                             int n, double gap_max, int lenient, rs_body_face_fn face,
                             const void *ctx, rs_body_contacts *out, rs_error *err)
{
    rs_body_fixed_work w;
    memset(&w, 0, sizeof w);
    const int rc = rs_body_fixed_point_run(s, pose, b, NULL, n, gap_max, lenient, face, ctx,
                                           out, &w, err);
    rs_body_fixed_work_free(&w);
    return rc;
}

void rs_body_fixed_work_free(rs_body_fixed_work *w)
{
    rs_contacts_free(&w->pc);
    free(w->mem);
    free(w->fx);
    memset(w, 0, sizeof *w);
}

/* Room for bytes in the block *mem of *have bytes (its contents not kept); 0, -1. */
static int room(void **mem, size_t *have, size_t bytes)
{
    if (bytes <= *have)
        return 0;
    free(*mem);
    *have = 0;
    if (!(*mem = malloc(bytes)))
        return -1;
    *have = bytes;
    return 0;
}

int rs_body_fixed_point_run(const rs_surface *s, const rs_pose *pose, const rs_body *b,
                            const double *R, int n, double gap_max, int lenient,
                            rs_body_face_fn face, const void *ctx, rs_body_contacts *out,
                            rs_body_fixed_work *w, rs_error *err)
{
    /* each body's R (where not given), reach, centre (x, y, z) and window */
    const size_t nb = (size_t)(n > 0 ? n : 1);
    if (room(&w->mem, &w->bytes, nb * (R ? 5 : 14) * sizeof(double)))
        return rs_error_set(err, RS_ERR_NOMEM, "body contacts: out of memory");
    int rc = RS_OK;
    double *rot = R ? NULL : w->mem;
    const double *Rb = R ? R : rot;
    double *reach = (double *)w->mem + (R ? 0 : 9 * (size_t)n);
    double *ask_xyz = NULL;
    int *off = NULL, *live = NULL;
    fixed *fx = NULL;
    rs_contacts pc = w->pc; /* the reach spheres' contacts, then each step's */
    for (int i = 0; rc == RS_OK && i < n; i++) {
        reach[i] = rs_body_reach(b + i);
        if (rot)
            rs_body_rotation(b + i, rot + 9 * i);
    }
    /* The features near each body: a sphere of its reach about its centre (its centre
     * sought as deep as twice its reach: a body deeper lies behind the wall). Each body's
     * window, win: its centre's depth limit, then its iterates' gap and depth limit; the
     * block is asked over the widest, and each body keeps what lies in its own. */
    double *x = reach + n, *y = x + n, *z = y + n, *win = z + n, far = gap_max;
    for (int i = 0; rc == RS_OK && i < n; i++) {
        x[i] = b[i].x[0], y[i] = b[i].x[1], z[i] = b[i].x[2];
        const double w = 2.0 * reach[i] + gap_max;
        win[i] = w > gap_max ? w : gap_max; /* (no NaN) */
        far = win[i] > far ? win[i] : far;
    }
    /* room for a few features a body at once: the query then grows no list */
    if (rc == RS_OK)
        rc = rs_contacts_reserve(&pc, 2 * n + 64, err);
    if (rc == RS_OK)
        rc = rs_body_closest(s, pose, n, x, y, z, reach, gap_max, far, &pc, err);
    const int npc = pc.n;
    if (rc == RS_OK && npc > 0) {
        /* the fixed points, the iterates asked (x, y, z), off and live in one block */
        if (room(&w->fx, &w->fxbytes,
                 (size_t)npc * (sizeof *fx + 3 * sizeof(double) + 3 * sizeof(int)) +
                     sizeof(int)))
            rc = rs_error_set(err, RS_ERR_NOMEM, "body contacts: out of memory");
        else {
            fx = w->fx;
            ask_xyz = (double *)(fx + npc);
            off = (int *)(ask_xyz + 3 * (size_t)npc);
            live = off + npc + 1;
        }
        if (rc == RS_OK)
            rc = rs_contacts_reserve(&pc, 2 * npc + 64, err);
    }
    int nf = 0; /* the features within their body's own depth limit */
    for (int k = 0; rc == RS_OK && k < npc; k++) {
        if (!(pc.dist[k] >= -win[pc.point[k]]))
            continue; /* (the test of the kinds' closest, dist >= dist_min) */
        const int kf = nf++;
        fixed *f = fx + kf;
        f->body = pc.point[k];
        f->want = RS_FEATURE_BASE(pc.feature[k]);
        f->it = f->conv = 0;
        f->found = -1;
        f->best.depth = -INFINITY;
        for (int d = 0; d < 3; d++)
            f->nrm[d] = pc.nrm[d][k];
        live[kf] = kf;
    }
    /* Each step: every unsettled iterate's point, the body's support along -n, asked in
     * one query, or of the kind's own answer where it has one; n the normal of its
     * feature's contact there (the feature it follows, else the deepest). */
    int nact = rc == RS_OK ? nf : 0;
    while (rc == RS_OK && nact > 0) {
        for (int a = 0; a < nact; a++) {
            fixed *f = fx + live[a];
            const double down[3] = {-f->nrm[0], -f->nrm[1], -f->nrm[2]};
            rs_body_support_at(b + f->body, Rb + 9 * f->body, down, f->p);
        }
        /* the kind's answers first; the rest (ask) keep their order for the query */
        int still = 0, nask = 0;
        for (int a = 0; a < nact; a++) {
            fixed *f = fx + live[a];
            rs_body_contact *c = &f->got; /* kept where it settles (step) */
            if (face && face(ctx, f->want, f->p, win[f->body], c)) {
                memcpy(c->xs, f->p, sizeof c->xs);
                if (step(f, c))
                    live[still++] = live[a];
            } else
                live[nact + nask++] = live[a]; /* live has room for 2 nf */
        }
        if (nask == 0) {
            nact = still;
            continue;
        }
        x = ask_xyz, y = x + nask, z = y + nask;
        const int *ask = live + nact;
        double gap = 0.0; /* the widest window of those asked */
        for (int a = 0; a < nask; a++) {
            const fixed *f = fx + ask[a];
            x[a] = f->p[0], y[a] = f->p[1], z[a] = f->p[2];
            gap = win[f->body] > gap ? win[f->body] : gap;
        }
        rc = rs_body_closest(s, pose, nask, x, y, z, NULL, gap, gap, &pc, err);
        if (rc != RS_OK)
            break;
        rs_contacts_offsets(&pc, nask, off);
        for (int a = 0; a < nask; a++) {
            fixed *f = fx + ask[a];
            const double g = win[f->body];
            const int j = rs_contacts_pick(&pc, off[a], off[a + 1], f->want, -g, g);
            rs_body_contact c;
            c.feature = -1;
            if (j >= 0)
                take(&c, &pc, j, f->p, 0);
            if (step(f, &c))
                live[still++] = ask[a];
        }
        nact = still;
    }
    /* One contact per owning feature of each body, the deepest, in the order found. */
    for (int k = 0; rc == RS_OK && k < nf; k++) {
        const fixed *f = fx + k;
        if (f->found < 0)
            continue;
        const rs_body_contact *got = &f->got;
        if (!f->conv) {
            if (!lenient) {
                rc = rs_error_set(err, RS_ERR_GEOMETRY,
                                  "body contacts: the deepest point on feature %d of '%s' "
                                  "did not settle in %d iterations (a wall curved more "
                                  "sharply than the body?)",
                                  f->want, s->name, BODY_ITER_MAX);
                break;
            }
            got = &f->best;
        }
        if (!(-got->depth <= gap_max))
            continue;
        rs_body_contacts *l = out + f->body;
        int slot = -1;
        for (int j = 0; j < l->n; j++)
            if (l->c[j].feature == got->feature)
                slot = j;
        if (slot < 0)
            rc = rs_body_contacts_push(l, got, err);
        else if (l->c[slot].depth < got->depth)
            l->c[slot] = *got;
    }
    w->pc = pc;
    return rc;
}
