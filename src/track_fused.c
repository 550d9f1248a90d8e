/* A law's fused kernel on a block (track_fused.h): rs_track_update's pass 1, the block's
 * qualification, then the law's one pass, or pass 2 for the staged calls. */
#include "track_fused.h"

/* Whether the block takes the kernel: see track_fused.h. */
RS_INLINE int qualifies(const rs_tracker *tr, const rs_law *law, const master_rates *mr,
                        const rs_particles *p, const rs_contacts *c,
                        const rs_track_out *out, int ne, const double *props, int ident)
{
    return ident && ne <= RS_FUSED_MAX && law->fused->takes(tr, props, law->nprops) &&
           !mr->belt && p->radius && p->mass && !p->body && !(c->witness && c->xs[0]) &&
           !out->shared && out->nseeded == 0;
}

int rs_track_fused(const rs_tracker *tr, const rs_law *law, const rs_surface *s,
                   const rs_motion *m, double dt, const rs_particles *p,
                   const rs_contacts *c, rs_track_out *out, const double *props,
                   const double origin[3], const rs_load_rows *rows, rs_wall_load *w,
                   int *done, rs_error *err)
{
    *done = 0;
    master_rates mr;
    int ne = 0, ident = 0;
    int rc = rs_track_match(tr, s, m, p, c, out, &mr, &ne, &ident, err);
    if (rc)
        return rc;
    if (!c || !law->fused || !qualifies(tr, law, &mr, p, c, out, ne, props, ident)) {
        rs_track_emit(tr, &mr, dt, p, c, out, ne, ident);
        return RS_OK;
    }
    rc = law->fused->pass(tr, &mr, dt, p, c, out, ne, props, origin, rows, w, err);
    if (rc == RS_OK)
        *done = 1;
    return rc;
}

int rs_track_fused_usual(const rs_tracker *tr, const rs_law *law, const rs_motion *m,
                         double dt, const rs_particles *p, const rs_contacts *c,
                         rs_track_out *out, const double *props, const double origin[3],
                         const rs_load_rows *rows, rs_wall_load *w, rs_error *err)
{
    if (!tr || !law || !law->fused || !p || !c || !out || !props || c->n != p->n)
        return rs_error_set(
            err, RS_ERR_ARG,
            "rs_track_fused_usual: expected a law with a fused kernel and a "
            "block with one contact per particle");
    int off = 0;
    for (int k = 0; k < c->n; k++)
        off |= c->point[k] ^ k;
    if (off)
        return rs_error_set(err, RS_ERR_ARG,
                            "rs_track_fused_usual: contact k must name particle k");
    master_rates mr;
    int rc = rs_track_match_usual(tr, m, p, out, &mr, err);
    if (rc)
        return rc;
    if (!qualifies(tr, law, &mr, p, c, out, p->n, props, 1))
        return rs_error_set(
            err, RS_ERR_ARG,
            "rs_track_fused_usual: the block does not take the fused kernel "
            "(a surface velocity, bodies, no radius or mass, more than %d "
            "particles, or a tracker or properties the law's kernel does "
            "not take)",
            RS_FUSED_MAX);
    return law->fused->pass(tr, &mr, dt, p, c, out, p->n, props, origin, rows, w, err);
}
