/* The standalone driver's history slots grow (driver_history.h): per node its directory
 * (capacity entries) then its slots, in one block, as alloc_history (driver.c) lays it
 * out; a zeroed entry is an empty slot. */
#include "driver_history.h"

#include <stdlib.h>
#include <string.h>

int rs_driver_grow_history(rs_driver *d, rs_error *err)
{
    const int old = d->capacity;
    if (old >= RS_TRACK_MAX_CAPACITY)
        return rs_error_set(err, RS_ERR_CAPACITY,
                            "driver: a node touches '%s' at more features than %d history "
                            "slots, the tracker's most",
                            d->surface->name, RS_TRACK_MAX_CAPACITY);
    const int cap = 2 * old < RS_TRACK_MAX_CAPACITY ? 2 * old : RS_TRACK_MAX_CAPACITY;
    const size_t stride = (size_t)rs_track_slot_size(&d->tracker);
    const size_t per = (size_t)cap * (1 + stride);
    double *h = calloc((size_t)d->n * per, sizeof *h);
    if (!h)
        return rs_error_set(err, RS_ERR_NOMEM,
                            "driver: out of memory for %d history slots per node", cap);
    for (int i = 0; i < d->n; i++) {
        double *dir = h + (size_t)i * per, *slots = dir + cap;
        memcpy(dir, d->dir_ptr[i], (size_t)old * sizeof *dir);
        memcpy(slots, d->hist_ptr[i], (size_t)old * stride * sizeof *slots);
        d->dir_ptr[i] = dir;
        d->hist_ptr[i] = slots;
    }
    free(d->hist);
    d->hist = h;
    d->capacity = d->tracker.capacity = cap;
    return RS_OK;
}
