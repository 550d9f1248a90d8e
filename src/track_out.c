/* The tracker's output arrays: growth (rs_track_out_reserve) and release. */
#include "track_out.h"

#include <stdlib.h>
#include <string.h>

void rs_track_out_free(rs_track_out *o)
{
    free(o->point);
    free(o->feature);
    free(o->slot);
    free(o->dir);
    free(o->rdisp);
    free(o->drdisp);
    free(o->drot);
    free(o->alocaldir);
    free(o->coordslv);
    free(o->coordmst);
    free(o->vrel);
    free(o->curv);
    free(o->share);
    free(o->seeded);
    memset(o, 0, sizeof *o);
}

static int grow(void **p, size_t bytes)
{
    void *q = realloc(*p, bytes);
    if (!q)
        return 0;
    *p = q;
    return 1;
}

int rs_track_out_reserve(rs_track_out *o, int n, rs_error *err)
{
    if (n <= o->cap)
        return RS_OK;
    size_t c = (size_t)n, d = sizeof(double);
    int ok =
        grow((void **)&o->point, c * sizeof(int)) &&
        grow((void **)&o->feature, c * sizeof(int)) &&
        grow((void **)&o->slot, c * sizeof(double *)) &&
        grow((void **)&o->dir, c * sizeof(double *)) &&
        grow((void **)&o->rdisp, 3 * c * d) && grow((void **)&o->drdisp, 3 * c * d) &&
        grow((void **)&o->drot, 4 * c * d) && grow((void **)&o->alocaldir, 9 * c * d) &&
        grow((void **)&o->coordslv, 3 * c * d) && grow((void **)&o->coordmst, 3 * c * d) &&
        grow((void **)&o->vrel, 3 * c * d) && grow((void **)&o->curv, 2 * c * d) &&
        grow((void **)&o->share, c * d) && grow((void **)&o->seeded, c * sizeof(int));
    if (!ok)
        return rs_error_set(err, RS_ERR_NOMEM,
                            "rs_track_update: out of memory for %d contacts", n);
    o->cap = n;
    return RS_OK;
}
