/* The CGAL side of the faceted surfaces, behind a C interface: reading a polygon soup
 * from STL (ASCII and binary), OBJ, OFF or PLY, and the AABB tree of a mesh's triangles
 * in its reference configuration. C++ stays inside cgal_mesh.cpp. */
#ifndef RS_CGAL_MESH_H
#define RS_CGAL_MESH_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/// Polygons as read: points (3 * np) and polygons (corner indices idx[off[k] ..
/// off[k + 1]) of polygon k). Arrays are malloc'ed; free with rs_soup_free.
typedef struct rs_soup {
    int np, nf;
    double *xyz;
    int *off;
    int *idx;
    int *label; ///< np: user node numbers (an Abaqus part's *NODE labels), or NULL
} rs_soup;

/// Reads the polygon soup of path by its extension (.stl, .obj, .off, .ply; case
/// ignored). Returns 0, or -1 with a one-line reason in msg (what was expected).
int rs_cgal_read_soup(const char *path, rs_soup *soup, char *msg, size_t cap);
void rs_soup_free(rs_soup *soup);

/// An AABB tree over triangles tri (3 * nt vertex indices into xyz). NULL when out of
/// memory. The tree keeps copies; xyz and tri may be freed afterwards.
void *rs_cgal_tree_new(int nt, const double *xyz, const int *tri);
void rs_cgal_tree_free(void *tree);
/// The triangles of the tree's leaves whose boxes meet the box [lo, hi]: every triangle
/// that meets it, and a few more near it (a leaf's box holds one or two triangles; they
/// are not tested one by one). Writes up to cap indices to ids and returns how many
/// there are (call again with a larger cap when it exceeds cap).
int rs_cgal_tree_box(const void *tree, const double lo[3], const double hi[3], int *ids,
                     int cap);

/// Distance from p to the nearest triangle (-1 on failure).
double rs_cgal_tree_nearest(const void *tree, const double p[3]);

#ifdef __cplusplus
}
#endif
#endif
