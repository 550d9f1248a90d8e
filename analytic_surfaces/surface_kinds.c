/* The kinds that surface files name (TYPE=), in the order messages list them: the
 * analytic kinds (analytic.c) and the triangle meshes (src/faceted/mesh_ops.c). The
 * reader reaches each one's syntax through its table (rs_surface_ops.syntax). */
#include "mesh.h"
#include "profile.h"
#include "surface_file.h"

const rs_surface_ops *rs_surface_kind_at(int i)
{
    switch (i) {
    case 0:
        return rs_analytic_ops(RS_SURF_SEGMENTS);
    case 1:
        return rs_analytic_ops(RS_SURF_CYLINDER);
    case 2:
        return rs_analytic_ops(RS_SURF_REVOLUTION);
    case 3:
        return &rs_mesh_ops;
    default:
        return NULL;
    }
}
