/* The standalone driver's history storage as it grows (driver_history.c). Private to the
 * contact core. */
#ifndef RS_DRIVER_HISTORY_H
#define RS_DRIVER_HISTORY_H

#include "rigidsurf/driver.h"

/// Doubles the history slots of every node (d->capacity, at most RS_TRACK_MAX_CAPACITY),
/// each node keeping its directory entries and slots: as the engine's slots grow when a
/// particle touches a wall at more features than it has room for. RS_ERR_CAPACITY at the
/// tracker's limit, RS_ERR_NOMEM; d is unchanged on error.
int rs_driver_grow_history(rs_driver *d, rs_error *err);

#endif
