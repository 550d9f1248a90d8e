/* A hull's vertex graph (convex_internal.h): its adjacency, the support found by hill
 * climbing over it, and the vertices farthest along a direction found by a best-first
 * walk from the support. On a convex polytope a linear function has no local maximum
 * but the global one, and the vertices above any level are connected, so both walks
 * find what a scan of every vertex finds, touching only the vertices near the answer.
 * Hulls of up to RS_HULL_SCAN vertices are scanned. */
#include "convex_internal.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int cmp_int(const void *a, const void *b)
{
    const int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

int rs_hull_adjacency(rs_shape *s)
{
    const int nv = s->nv, nt = s->nt;
    int *deg = calloc((size_t)nv + 1, sizeof *deg);
    int *adj = malloc(6 * (size_t)nt * sizeof *adj);
    if (!deg || !adj) {
        free(deg);
        free(adj);
        return -1;
    }
    /* each triangle's corner j gives j's two neighbours in it; every edge twice over */
    for (int t = 0; t < 3 * nt; t++)
        deg[s->tris[t] + 1] += 2;
    for (int v = 0; v < nv; v++)
        deg[v + 1] += deg[v];
    int *fill = malloc((size_t)nv * sizeof *fill);
    if (!fill) {
        free(deg);
        free(adj);
        return -1;
    }
    memcpy(fill, deg, (size_t)nv * sizeof *fill);
    for (int t = 0; t < nt; t++)
        for (int j = 0; j < 3; j++) {
            const int v = s->tris[3 * t + j];
            adj[fill[v]++] = s->tris[3 * t + (j + 1) % 3];
            adj[fill[v]++] = s->tris[3 * t + (j + 2) % 3];
        }
    /* each neighbour once, in order */
    int w = 0;
    for (int v = 0; v < nv; v++) {
        const int b = deg[v], e = deg[v + 1];
        qsort(adj + b, (size_t)(e - b), sizeof *adj, cmp_int);
        deg[v] = w;
        for (int k = b; k < e; k++)
            if (k == b || adj[k] != adj[k - 1])
                adj[w++] = adj[k];
    }
    deg[nv] = w;
    free(fill);
    s->adj0 = deg;
    s->adj = adj;
    return 0;
}

/* The cell of a cube's faces that direction d points through: the face of d's largest
 * part (axis a, its sign), and on it the cell of d's other two parts over that one, each
 * in RS_HULL_CELLS equal steps of [-1, 1]. 0 for a direction without a finite largest
 * part. */
static int cell_of(const double d[3])
{
    const double ax = fabs(d[0]), ay = fabs(d[1]), az = fabs(d[2]);
    const int a = ax >= ay ? (ax >= az ? 0 : 2) : (ay >= az ? 1 : 2);
    const double top = a == 0 ? ax : a == 1 ? ay : az;
    if (!(top > 0.0) || !(top < INFINITY))
        return 0;
    const int b = (a + 1) % 3, c = (a + 2) % 3, K = RS_HULL_CELLS;
    const double fu = (d[b] / top + 1.0) * 0.5 * K, fv = (d[c] / top + 1.0) * 0.5 * K;
    const int i = fu >= 1.0 ? (fu < K ? (int)fu : K - 1) : 0;
    const int j = fv >= 1.0 ? (fv < K ? (int)fv : K - 1) : 0;
    return ((2 * a + (d[a] < 0.0)) * K + i) * K + j;
}

void rs_hull_hints(rs_shape *s)
{
    const int K = RS_HULL_CELLS;
    for (int a = 0; a < 3; a++)
        for (int sg = 0; sg < 2; sg++)
            for (int i = 0; i < K; i++)
                for (int j = 0; j < K; j++) {
                    double dir[3];
                    dir[a] = sg ? -1.0 : 1.0;
                    dir[(a + 1) % 3] = -1.0 + (2.0 * i + 1.0) / K;
                    dir[(a + 2) % 3] = -1.0 + (2.0 * j + 1.0) / K;
                    int best = 0;
                    double bd = -INFINITY;
                    for (int v = 0; v < s->nv; v++) {
                        const double p = rs_dot3(s->verts + 3 * v, dir);
                        if (p > bd)
                            bd = p, best = v;
                    }
                    s->hint[((2 * a + sg) * K + i) * K + j] = best;
                }
}

int rs_hull_support(const rs_shape *s, const double d[3])
{
    const double *v = s->verts;
    if (s->nv <= RS_HULL_SCAN) {
        int best = 0;
        double bd = -INFINITY;
        for (int i = 0; i < s->nv; i++) {
            const double p = rs_dot3(v + 3 * i, d);
            if (p > bd) {
                bd = p;
                best = i;
            }
        }
        return best;
    }
    /* from the extreme vertex of the cell d points through, up the graph: to a higher
     * neighbour, or an equal one of a lower index (so that it ends) */
    int best = s->hint[cell_of(d)];
    double bd = rs_dot3(v + 3 * best, d);
    for (int moved = 1; moved;) {
        moved = 0;
        for (int k = s->adj0[best], e = s->adj0[best + 1]; k < e; k++) {
            const int w = s->adj[k];
            const double p = rs_dot3(v + 3 * w, d);
            if (p > bd || (p == bd && w < best)) {
                bd = p;
                best = w;
                moved = 1;
            }
        }
    }
    return best;
}

/* Is (ka, a) before (kb, b): farther along d, then the lower index? */
static int before(double ka, int a, double kb, int b)
{
    return ka > kb || (ka == kb && a < b);
}

int rs_hull_farthest(const rs_shape *s, const double d[3], int cap, int *out)
{
    const double *v = s->verts;
    int n = 0;
    if (s->nv <= RS_HULL_SCAN) { /* the cap farthest, by insertion (ties: lower index) */
        double key[RS_HULL_FARTHEST_MAX];
        for (int i = 0; i < s->nv; i++) {
            const double kv = rs_dot3(v + 3 * i, d);
            if (n == cap && !before(kv, i, key[n - 1], out[n - 1]))
                continue;
            int at = n < cap ? n++ : n - 1;
            for (; at > 0 && before(kv, i, key[at - 1], out[at - 1]); at--) {
                key[at] = key[at - 1];
                out[at] = out[at - 1];
            }
            key[at] = kv;
            out[at] = i;
        }
        return n;
    }
    /* best-first from the support: the frontier (a small heap by key) and the vertices
     * seen (few: the cap and their neighbours), in a small open-addressed set */
    enum { SEEN = 16 * RS_HULL_FARTHEST_MAX, SET = 2 * SEEN };
    _Static_assert((SET & (SET - 1)) == 0, "the seen set's size is a power of two");
    int heap[SEEN], set[SET], nh = 0, ns = 0;
    double hk[SEEN];
    const unsigned mask = SET - 1;
    memset(set, 0xff, sizeof set); /* all -1 */
    const int s0 = rs_hull_support(s, d);
    heap[nh] = s0, hk[nh++] = rs_dot3(v + 3 * s0, d);
    set[(unsigned)s0 * 2654435761u & mask] = s0, ns++;
    while (nh > 0 && n < cap) {
        const int top = heap[0];
        out[n++] = top;
        /* pop: the last to the root, sifted down */
        nh--;
        heap[0] = heap[nh], hk[0] = hk[nh];
        for (int i = 0;;) {
            int c = 2 * i + 1;
            if (c >= nh)
                break;
            if (c + 1 < nh && before(hk[c + 1], heap[c + 1], hk[c], heap[c]))
                c++;
            if (!before(hk[c], heap[c], hk[i], heap[i]))
                break;
            const int ti = heap[i];
            const double tk = hk[i];
            heap[i] = heap[c], hk[i] = hk[c];
            heap[c] = ti, hk[c] = tk;
            i = c;
        }
        for (int k = s->adj0[top], e = s->adj0[top + 1]; k < e; k++) {
            const int w = s->adj[k];
            unsigned h = (unsigned)w * 2654435761u & mask;
            while (set[h] >= 0 && set[h] != w)
                h = (h + 1) & mask;
            if (set[h] == w || ns == SEEN || nh == SEEN)
                continue;
            set[h] = w, ns++;
            /* push, sifted up */
            int i = nh++;
            heap[i] = w, hk[i] = rs_dot3(v + 3 * w, d);
            while (i > 0 && before(hk[i], heap[i], hk[(i - 1) / 2], heap[(i - 1) / 2])) {
                const int p = (i - 1) / 2, ti = heap[i];
                const double tk = hk[i];
                heap[i] = heap[p], hk[i] = hk[p];
                heap[p] = ti, hk[p] = tk;
                i = p;
            }
        }
    }
    return n;
}
