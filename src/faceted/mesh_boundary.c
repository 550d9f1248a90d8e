/* The open boundary of a MESH, as reading reports it: the rim of an open surface (a
 * plate, a belt, a chute, a bin without a lid) is a fact worth one line; holes in a
 * surface that otherwise closes (a drum or a silo with a gap) are a warning, since
 * particles that fit through them leave the container. */
#include "mesh.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int find(int *parent, int v)
{
    while (parent[v] != v) {
        parent[v] = parent[parent[v]];
        v = parent[v];
    }
    return v;
}

int rs_mesh_boundary_report(const rs_mesh *m, const char *origin, char *warn,
                            size_t warncap, char *info, size_t infocap)
{
    int nopen = 0;
    for (int e = 0; e < m->ne; e++)
        nopen += m->edge_kind[e] == RS_EDGE_BOUNDARY;
    if (nopen == 0)
        return 0;
    /* the loops of open edges: their nodes joined by union-find, a box per loop */
    int *parent = malloc((size_t)m->nv * sizeof *parent);
    double *box = malloc(6 * (size_t)m->nv * sizeof *box);
    if (!parent || !box) {
        free(parent);
        free(box);
        return -1;
    }
    for (int v = 0; v < m->nv; v++)
        parent[v] = v;
    for (int e = 0; e < m->ne; e++)
        if (m->edge_kind[e] == RS_EDGE_BOUNDARY) {
            const int a = find(parent, m->edge_v[2 * e]),
                      b = find(parent, m->edge_v[2 * e + 1]);
            parent[a] = b;
        }
    for (int v = 0; v < m->nv; v++)
        for (int d = 0; d < 3; d++) {
            box[6 * v + d] = INFINITY;
            box[6 * v + 3 + d] = -INFINITY;
        }
    for (int e = 0; e < m->ne; e++) {
        if (m->edge_kind[e] != RS_EDGE_BOUNDARY)
            continue;
        for (int k = 0; k < 2; k++) {
            const int v = m->edge_v[2 * e + k];
            double *b = box + 6 * find(parent, v);
            for (int d = 0; d < 3; d++) {
                b[d] = fmin(b[d], m->xyz[3 * v + d]);
                b[3 + d] = fmax(b[3 + d], m->xyz[3 * v + d]);
            }
        }
    }
    int nloop = 0;
    double widest = 0.0;
    for (int v = 0; v < m->nv; v++) {
        if (parent[v] != v || !(box[6 * v] <= box[6 * v + 3]))
            continue;
        const double *b = box + 6 * v;
        const double w[3] = {b[3] - b[0], b[4] - b[1], b[5] - b[2]};
        widest = fmax(widest, sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]));
        nloop++;
    }
    free(parent);
    free(box);
    char *out = info;
    size_t cap = infocap;
    char piece[256];
    if (widest < RS_HOLE_FRACTION * m->size) {
        snprintf(piece, sizeof piece,
                 "%s: %d open boundary edge%s around %d hole%s in a surface that otherwise "
                 "closes, the widest %.3g across: particles that fit through pass through",
                 origin, nopen, nopen == 1 ? "" : "s", nloop, nloop == 1 ? "" : "s",
                 widest);
        out = warn;
        cap = warncap;
    } else {
        snprintf(
            piece, sizeof piece,
            "%s: an open surface: %d open boundary edge%s on %d rim%s, the widest %.3g "
            "across",
            origin, nopen, nopen == 1 ? "" : "s", nloop, nloop == 1 ? "" : "s", widest);
    }
    if (out && cap) {
        const size_t used = strlen(out);
        if (used + 1 < cap)
            snprintf(out + used, cap - used, "%s%s", used ? "; " : "", piece);
    }
    return 0;
}
