/* The geometry a face's clear zone is checked with (mesh_zone_sat.c): the zone's convex
 * pieces, the regions where the mesh's faces, edges and vertices own points by the
 * query's tests, and the separating-axis tests between them. Private to src/faceted/. */
#ifndef RS_FACETED_MESH_ZONE_SAT_H
#define RS_FACETED_MESH_ZONE_SAT_H

#include "mesh.h"

/* One piece: nc (3 or 4) corners at its base (the plane's side), as many at its top,
 * corner k and nc + k above one another. */
typedef struct zpiece {
    double c[8][3];
    int nc;
} zpiece;

/* A piece's face normals (its base and top, its nc sides) and edge directions (nc along
 * its base, nc from base to top), the axes the separating-axis tests take. */
typedef struct zaxes {
    double fn[5][3], ed[8][3];
    int nf, ne;
} zaxes;

/* The most rays and planes a region keeps: a node of more neighbours is not tested (its
 * distance bounds the zone instead). */
#define RS_ZONE_MAX_W 24
#define RS_ZONE_MAX_RAYS 64

/* A convex region where a feature owns points, by the query's tests, closed: the hull of
 * its points (a node, an edge's two nodes, a triangle's three) plus the cone of its rays,
 * bounded by the half-spaces g.x <= c (g[k][0 .. 2], c = g[k][3]). */
typedef struct region {
    double v[3][3];
    int nv;
    double ray[RS_ZONE_MAX_RAYS][3];
    int nray;
    double g[RS_ZONE_MAX_W + 2][4];
    double gl[RS_ZONE_MAX_W + 2]; /* |g[k][0 .. 2]| */
    int ng;
} region;

/* The piece's axes: its base's normal n, its sides' normals and its edges. */
void rs_zone_piece_axes(const zpiece *P, const double n[3], zaxes *x);
/* Is P beyond one of R's planes by more than margin? */
int rs_zone_planes_out(const zpiece *P, const region *R, double margin);
/* Is region R apart from piece P (axes X) by more than margin? One of R's planes
 * (rs_zone_planes_out), or an axis of P or across the edges of both (rs_zone_axes_out,
 * which alone reads R's rays). */
int rs_zone_region_out(const zpiece *P, const zaxes *X, const region *R, double margin);
int rs_zone_axes_out(const zpiece *P, const zaxes *X, const region *R, double margin);
/* A lower bound of the distance between P and the hull of points T[0 .. nt). */
double rs_zone_sep_bound(const zpiece *P, const zaxes *X, const double *const *T, int nt);
/* The regions of the face of triangle tp, of edge e and of node v (vertex: 0 when it has
 * more neighbours than a region keeps or they lie on one line; 2, without its rays, when
 * its planes alone keep every piece P[s] with live[s] out by margin). */
void rs_zone_face_region(const rs_mesh *m, int tp, region *R);
void rs_zone_edge_region(const rs_mesh *m, int e, double scale, region *R);
/* The rays of a face's or an edge's region, once its planes are made by the function
 * above (which leaves it none): asked for only where its planes keep a piece in. */
void rs_zone_face_rays(const rs_mesh *m, int tp, region *R);
void rs_zone_edge_rays(const rs_mesh *m, int e, region *R);
int rs_zone_vertex_region(const rs_mesh *m, int v, const zpiece P[2], const int live[2],
                          double margin, region *R);

#endif
