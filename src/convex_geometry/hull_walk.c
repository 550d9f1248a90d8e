/* A hull's vertex graph (convex_internal.h): its adjacency, the support found by hill
 * climbing over it, and the vertices farthest along a direction found by a best-first
 * walk from the support. On a convex polytope a linear function has no local maximum
 * but the global one, and the vertices above any level are connected, so both walks
 * find what a scan of every vertex finds, touching only the vertices near the answer.
 * Hulls of up to RS_HULL_SCAN vertices are scanned. */
#include "convex_internal.h"
#include "rigidsurf/vec.h"

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

/* The 26 directions of a cube's neighbours, (a, b, c) in {-1, 0, 1}^3 less the origin:
 * their extreme vertices are the climb's starts. */
static void hint_dir(int k, double dir[3])
{
    const int m = k < 13 ? k : k + 1; /* skip the centre, 13 */
    dir[0] = m % 3 - 1.0, dir[1] = (m / 3) % 3 - 1.0, dir[2] = m / 9 - 1.0;
}

void rs_hull_hints(rs_shape *s)
{
    for (int k = 0; k < RS_HULL_HINTS; k++) {
        double dir[3];
        hint_dir(k, dir);
        int best = 0;
        double bd = -INFINITY;
        for (int i = 0; i < s->nv; i++) {
            const double p = rs_dot3(s->verts + 3 * i, dir);
            if (p > bd)
                bd = p, best = i;
        }
        s->hint[k] = best;
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
    /* from the hint nearest d (the extreme vertices along 26 directions), up the graph:
     * to a higher neighbour, or an equal one of a lower index (so that it ends) */
    int best = s->hint[0];
    double bd = rs_dot3(v + 3 * best, d);
    for (int k = 1; k < RS_HULL_HINTS; k++) {
        const double p = rs_dot3(v + 3 * s->hint[k], d);
        if (p > bd)
            bd = p, best = s->hint[k];
    }
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
    enum { SEEN = 16 * RS_HULL_FARTHEST_MAX, SET = 4 * SEEN };
    int heap[SEEN], set[SET], nh = 0, ns = 0;
    double hk[SEEN];
    for (int k = 0; k < SET; k++)
        set[k] = -1;
    const int s0 = rs_hull_support(s, d);
    heap[nh] = s0, hk[nh++] = rs_dot3(v + 3 * s0, d);
    set[(unsigned)s0 * 2654435761u % SET] = s0, ns++;
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
            unsigned h = (unsigned)w * 2654435761u % SET;
            while (set[h] >= 0 && set[h] != w)
                h = (h + 1) % SET;
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
