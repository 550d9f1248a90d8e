/* The query data of a profile (rs_pcache_build): per-segment and per-vertex records for
 * the ownership rules of profile.h, and their index (profile.h: stored records with a
 * bucket index along one profile axis, or the compact tree). */
#include "profile.h"
#include "rs_compiler.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* The larger of two finite numbers (the coordinates here are; fmax is a libm call). */
static inline double max2(double a, double b)
{
    return a > b ? a : b;
}

static void normalize2(double v[2])
{
    double l = hypot(v[0], v[1]);
    v[0] /= l;
    v[1] /= l;
}

/* Bucket range [b0, b1] of the interval [c0, c1] at width 1/inv_w, clamped to the grid;
 * the ends are widened by 1e-6 w against rounding of the bucket of a query point. */
static void bucket_span(const rs_pcache *pc, double c0, double c1, int *b0, int *b1)
{
    double f0 = (c0 - pc->lo) * pc->inv_w - 1e-6, f1 = (c1 - pc->lo) * pc->inv_w + 1e-6;
    double top = (double)(pc->nbucket - 1);
    f0 = f0 > 0.0 ? (f0 < top ? f0 : top) : 0.0;
    f1 = f1 > 0.0 ? (f1 < top ? f1 : top) : 0.0;
    *b0 = (int)f0;
    *b1 = (int)f1;
}

/* The sum over the buckets of the squared list lengths at margin: the cost of scanning
 * a bucket summed over the buckets. The lengths come from a difference array (diff:
 * nbucket + 1 ints), so the cost is O(nseg + nbucket) however crowded the buckets. */
static double bucket_cost(const rs_pcache *pc, double margin, int *diff)
{
    const int nb = pc->nbucket, ax = pc->axis;
    memset(diff, 0, (size_t)(nb + 1) * sizeof(int));
    for (int k = 0; k < pc->nseg; k++) {
        int b0, b1;
        const double *box = pc->ps[k].box + 2 * ax;
        bucket_span(pc, box[0] - margin, box[1] + margin, &b0, &b1);
        diff[b0]++;
        diff[b1 + 1]--;
    }
    double sq = 0.0;
    long run = 0;
    for (int b = 0; b < nb; b++) {
        run += diff[b];
        sq += (double)run * (double)run;
    }
    return sq;
}

/* Entries of one level; with bstart and blist, also the lists (bstart: nbucket + 1
 * offsets; blist: byte offsets of the segments into ps). */
static long bucket_level(const rs_pcache *pc, double margin, int *bstart, int *blist)
{
    int nb = pc->nbucket, ax = pc->axis;
    long total = 0;
    int *cnt = bstart;
    if (cnt)
        memset(cnt, 0, (size_t)(nb + 1) * sizeof(int));
    for (int k = 0; k < pc->nseg; k++) {
        int b0, b1;
        const double *box = pc->ps[k].box + 2 * ax;
        bucket_span(pc, box[0] - margin, box[1] + margin, &b0, &b1);
        total += b1 - b0 + 1;
        if (cnt)
            for (int b = b0; b <= b1; b++)
                cnt[b + 1]++;
    }
    if (!cnt || !blist)
        return total;
    for (int b = 0; b < nb; b++)
        bstart[b + 1] += bstart[b];
    /* bstart[b] is the cursor of bucket b while filling, then the end of bucket b */
    for (int k = 0; k < pc->nseg; k++) {
        int b0, b1;
        const double *box = pc->ps[k].box + 2 * ax;
        bucket_span(pc, box[0] - margin, box[1] + margin, &b0, &b1);
        for (int b = b0; b <= b1; b++)
            blist[bstart[b]++] = k * (int)sizeof(rs_pseg);
    }
    for (int b = nb; b > 0; b--)
        bstart[b] = bstart[b - 1];
    bstart[0] = 0;
    return total;
}

/* Levels of the bucket index: margins w/4, w/2, w, 2w, ... while a level stays within
 * budget entries and its margin is under the profile's extent along the axis. */
static int bucket_levels(rs_pcache *pc, double extent, long budget, long *entries)
{
    double w = pc->inv_w > 0.0 ? 1.0 / pc->inv_w : 0.0;
    int nl = 0;
    long tot = 0;
    for (double m = 0.25 * w; nl < RS_PC_MAXLEVEL; m *= 2.0) {
        long e = bucket_level(pc, m, NULL, NULL);
        if (e > budget)
            break;
        pc->margin[nl++] = m;
        tot += e;
        if (!(m < extent))
            break;
    }
    *entries = tot;
    return nl;
}

/* The piece that owns, alone, every point of chain bucket b that lies within margin of
 * the chain, or -1. The bucket's band (widened against the rounding of a point's bucket)
 * and the strip |sd| <= margin + 1e-6 size around piece k's line meet in a
 * parallelogram. The ownership tests (dB, dA of profile.h) are linear in the point, so
 * they hold on the whole parallelogram when they hold at its corners: piece k passes
 * both strictly (by tol) and every other piece of the list fails one of them strictly,
 * so the walk of rs_pcache_points finds k and only k for such a point. A point of the
 * bucket farther from the chain is beyond the reach the level serves and gets no face
 * contact from any piece. Buckets 0 and nbucket - 1 take the points beyond the grid and
 * have no owner. */
static int chain_owner(const rs_pcache *pc, double margin, int b, const int *list, int cnt)
{
    const int ax = pc->axis;
    if (b <= 0 || b >= pc->nbucket - 1 || !(pc->inv_w > 0.0))
        return -1;
    const double w = 1.0 / pc->inv_w;
    const double slack = 1e-6 * w + 1e-12 * (fabs(pc->lo) + pc->size);
    const double c0 = pc->lo + b * w - slack, c1 = pc->lo + (b + 1) * w + slack;
    const double strip = margin + 1e-6 * pc->size;
    for (int e = 0; e < cnt; e++) {
        const rs_pseg *q = &pc->ps[rs_pcache_seg(list[e])];
        const double tax = q->t[ax];
        if (!(fabs(tax) > 1e-3))
            continue; /* the strip runs along the band: no bounded region */
        double P[4][2], scale = pc->size;
        for (int c = 0; c < 4; c++) {
            const double d = (c & 1) ? strip : -strip, cc = (c & 2) ? c1 : c0;
            const double t = (cc - q->o[ax] - d * q->nl[ax]) / tax;
            P[c][0] = q->o[0] + t * q->t[0] + d * q->nl[0];
            P[c][1] = q->o[1] + t * q->t[1] + d * q->nl[1];
            scale = max2(scale, max2(fabs(P[c][0]), fabs(P[c][1])));
        }
        const double tol = 1e-9 * scale;
        /* piece e's own test first: most pieces fail it, so a bucket costs O(cnt). The
         * first piece that passes it decides: if another piece does not fail strictly,
         * the bucket gets no owner (a later piece could only pass on a parallelogram
         * that overlaps this one's slab, so it would fail its own check). */
        int ok = 1, own_in = 0;
        for (int i = -1; i < cnt && ok; i++) {
            const int f = i < 0 ? e : i;
            if (i == e)
                continue;
            const rs_pseg *r = &pc->ps[rs_pcache_seg(list[f])];
            int in = 1, before = 1, after = 1;
            for (int c = 0; c < 4; c++) {
                double dB, dA;
                rs_pseg_offsets(r, P[c][0], P[c][1], &dB, &dA);
                in &= dB >= tol && dA <= -tol;
                before &= dB <= -tol;
                after &= dA >= tol;
            }
            ok = f == e ? in : (before || after);
            own_in = own_in || (f == e && in);
        }
        if (ok)
            return rs_pcache_seg(list[e]);
        if (own_in)
            return -1;
    }
    return -1;
}

/* The smaller of two finite numbers. */
static inline double min2(double a, double b)
{
    return a < b ? a : b;
}

static void box_add(double box[4], double x, double y)
{
    box[0] = min2(box[0], x);
    box[1] = max2(box[1], x);
    box[2] = min2(box[2], y);
    box[3] = max2(box[3], y);
}

static void box_union(double box[4], const double b[4])
{
    box[0] = min2(box[0], b[0]);
    box[1] = max2(box[1], b[1]);
    box[2] = min2(box[2], b[2]);
    box[3] = max2(box[3], b[3]);
}

void rs_pcache_vertex(const rs_pcache *pc, int j, rs_pvert *v)
{
    const int n = pc->nseg;
    const rs_segment *seg = pc->seg;
    memset(v, 0, sizeof *v);
    v->sa = j > 0 ? j - 1 : (pc->closed ? n - 1 : -1);
    v->sb = j < n ? j : -1;
    const double *pos = v->sb >= 0 ? seg[v->sb].p0 : seg[v->sa].p1;
    v->v[0] = pos[0];
    v->v[1] = pos[1];
    if (v->sa >= 0)
        rs_segment_end_tangent(&seg[v->sa], 1, v->ta);
    if (v->sb >= 0)
        rs_segment_end_tangent(&seg[v->sb], 0, v->tb);
    v->kind = pc->vk[j];
    if (v->kind == RS_VTX_SMOOTH) {
        double t[2] = {v->ta[0] + v->tb[0], v->ta[1] + v->tb[1]};
        normalize2(t);
        v->ta[0] = v->tb[0] = t[0];
        v->ta[1] = v->tb[1] = t[1];
    }
    v->na[0] = -v->ta[1];
    v->na[1] = v->ta[0];
    v->nb[0] = -v->tb[1];
    v->nb[1] = v->tb[0];
    if (v->sa < 0) {
        v->nfb[0] = v->nb[0];
        v->nfb[1] = v->nb[1];
    } else if (v->sb < 0) {
        v->nfb[0] = v->na[0];
        v->nfb[1] = v->na[1];
    } else {
        double b[2] = {v->na[0] + v->nb[0], v->na[1] + v->nb[1]};
        if (hypot(b[0], b[1]) > 1e-6) {
            normalize2(b);
        } else {
            b[0] = v->ta[0];
            b[1] = v->ta[1];
        }
        v->nfb[0] = b[0];
        v->nfb[1] = b[1];
    }
    v->seg_owns_edge =
        pc->revolution && v->kind == RS_VTX_END && fabs(v->v[0]) <= 1e-12 * pc->size;
}

void rs_pcache_box(const rs_pcache *pc, int k, double box[4])
{
    const rs_segment *g = &pc->seg[k];
    const double tol = 1e-12 * pc->size;
    box[0] = box[2] = INFINITY;
    box[1] = box[3] = -INFINITY;
    box_add(box, g->p0[0], g->p0[1]);
    box_add(box, g->p1[0], g->p1[1]);
    if (g->type == RS_CIRCL) {
        /* An arc under 180 degrees lies inside the circle on its chord (Thales). */
        double bc[2] = {0.5 * (g->p0[0] + g->p1[0]), 0.5 * (g->p0[1] + g->p1[1])};
        double br = 0.5 * hypot(g->p1[0] - g->p0[0], g->p1[1] - g->p0[1]);
        box_add(box, bc[0] - br, bc[1] - br);
        box_add(box, bc[0] + br, bc[1] + br);
    } else if (g->type == RS_PARAB) {
        /* The curve lies in the hull of its Bezier points p0, 2 pm - (p0 + p1)/2, p1. */
        box_add(box, 2.0 * g->pm[0] - 0.5 * (g->p0[0] + g->p1[0]),
                2.0 * g->pm[1] - 0.5 * (g->p0[1] + g->p1[1]));
    }
    for (int i = 0; i < 4; i++)
        box[i] += (i & 1 ? 1.0 : -1.0) * (1e-12 * fabs(box[i]) + tol);
}

void rs_pcache_segment(const rs_pcache *pc, int k, const rs_pvert *v0, const rs_pvert *v1,
                       rs_pseg *q)
{
    const rs_segment *g = &pc->seg[k];
    memset(q, 0, sizeof *q);
    q->type = g->type;
    q->self = k;
    rs_pcache_box(pc, k, q->box);
    switch (g->type) {
    case RS_LINE:
        q->o[0] = g->p0[0];
        q->o[1] = g->p0[1];
        q->e[0] = g->p1[0] - g->p0[0];
        q->e[1] = g->p1[1] - g->p0[1];
        q->inv_len2 = 1.0 / (q->e[0] * q->e[0] + q->e[1] * q->e[1]);
        q->t[0] = q->e[0];
        q->t[1] = q->e[1];
        normalize2(q->t);
        break;
    case RS_CIRCL:
        q->sgn = g->sweep > 0.0 ? 1.0 : -1.0;
        q->o[0] = g->pm[0];
        q->o[1] = g->pm[1];
        q->rad = g->radius;
        break;
    case RS_PARAB:
        q->o[0] = g->pm[0];
        q->o[1] = g->pm[1];
        for (int i = 0; i < 2; i++) {
            q->B[i] = 0.5 * (g->p1[i] - g->p0[i]);
            q->C[i] = 0.5 * (g->p0[i] + g->p1[i]) - g->pm[i];
        }
        break;
    }
    /* the ownership tests of its two vertices */
    q->start_incl =
        v0->kind == RS_VTX_SMOOTH || v0->kind == RS_VTX_CONCAVE || v0->seg_owns_edge;
    q->end_incl = v1->seg_owns_edge;
    q->vtx_start = v0->kind != RS_VTX_SMOOTH;
    q->vtx_end = k == pc->nseg - 1 && !pc->closed;
    q->nl[0] = -q->t[1];
    q->nl[1] = q->t[0];
    for (int i = 0; i < 2; i++) {
        q->v0[i] = v0->v[i];
        q->tb0[i] = v0->tb[i];
        q->v1[i] = v1->v[i];
        q->ta1[i] = v1->ta[i];
    }
}

/* Vertex kinds: END at the ends of an open profile, else the profile's own (from
 * rs_profile_finish) or, without them, from the angle between the two tangents. */
static void vertex_kinds(const rs_profile *p, rs_pcache *pc)
{
    const int n = pc->nseg;
    for (int j = 0; j < pc->nvert; j++) {
        const int sa = j > 0 ? j - 1 : (pc->closed ? n - 1 : -1), sb = j < n ? j : -1;
        int kind;
        if (sa < 0 || sb < 0) {
            kind = RS_VTX_END;
        } else if (p->vkind && j < p->nvert) {
            kind = p->vkind[j];
        } else {
            double ta[2], tb[2];
            rs_segment_end_tangent(&p->seg[sa], 1, ta);
            rs_segment_end_tangent(&p->seg[sb], 0, tb);
            double c = ta[0] * tb[1] - ta[1] * tb[0];
            double d = ta[0] * tb[0] + ta[1] * tb[1];
            double ang = atan2(c, d);
            kind = fabs(ang) <= RS_SMOOTH_ANGLE           ? RS_VTX_SMOOTH
                   : fabs(ang) >= RS_PI - RS_SMOOTH_ANGLE ? RS_VTX_CONVEX
                   : ang > 0.0                            ? RS_VTX_CONCAVE
                                                          : RS_VTX_CONVEX;
        }
        pc->vk[j] = (unsigned char)kind;
    }
}

/* The tree of boxes (profile.h): the boxes of the runs of RS_PC_LEAF segments, then each
 * level from the one below; the root's is the profile's box. */
static void build_tree(rs_pcache *pc)
{
    const int n = pc->nseg;
    double *t = pc->tree;
    for (int k = 0; k < n; k++) {
        double *leaf = t + 4 * (size_t)(k / RS_PC_LEAF), box[4];
        rs_pcache_box(pc, k, box);
        if (k % RS_PC_LEAF == 0)
            memcpy(leaf, box, sizeof box);
        else
            box_union(leaf, box);
    }
    for (int l = 1; l < pc->ntlev; l++) {
        const int below = pc->tlev[l - 1], cnt_below = pc->tlev[l] - below;
        for (int i = 0; i < pc->tlev[l + 1] - pc->tlev[l]; i++) {
            double *b = t + 4 * ((size_t)pc->tlev[l] + (size_t)i);
            memcpy(b, t + 4 * ((size_t)below + 2 * (size_t)i), 4 * sizeof(double));
            if (2 * i + 1 < cnt_below)
                box_union(b, t + 4 * ((size_t)below + 2 * (size_t)i + 1));
        }
    }
    memcpy(pc->box, t + 4 * (size_t)pc->tlev[pc->ntlev - 1], sizeof pc->box);
}

int rs_pcache_build(const rs_surface *s, rs_pcache **out, rs_error *err)
{
    return rs_pcache_build_as(s, s->profile.nseg > RS_PC_LARGE, out, err);
}

int rs_pcache_build_as(const rs_surface *s, int compact, rs_pcache **out, rs_error *err)
{
    const rs_profile *p = &s->profile;
    int n = p->nseg;
    *out = NULL;
    if (n < 1 || !p->seg)
        return rs_error_set(err, RS_ERR_ARG, "surface '%s' has no profile segments",
                            s->name);
    const rs_segment *last = &p->seg[n - 1];
    int closed = p->vkind ? p->closed
                          : (n >= 2 && last->p1[0] == p->seg[0].p0[0] &&
                             last->p1[1] == p->seg[0].p0[1]);
    int nv = closed ? n : n + 1;
    /* the header and the vertex kinds, the records (stored form), then the tree; the
     * stored form's bucket index is sized from the records and added after */
    const size_t head = (sizeof(rs_pcache) + (size_t)nv + 15) & ~(size_t)15;
    int tlev[RS_PC_MAXDEPTH + 1] = {0}, ntlev = 0;
    for (int cnt = (n + RS_PC_LEAF - 1) / RS_PC_LEAF;; cnt = (cnt + 1) / 2) {
        tlev[ntlev + 1] = tlev[ntlev] + cnt;
        ntlev++;
        if (cnt == 1)
            break;
    }
    const size_t recs =
        compact ? 0 : (size_t)n * sizeof(rs_pseg) + (size_t)nv * sizeof(rs_pvert);
    const size_t body = recs + (size_t)tlev[ntlev] * 4 * sizeof(double);
    const size_t whole = (head + body + 15) & ~(size_t)15;
    unsigned char *blk = calloc(1, whole);
    if (!blk)
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory for the query data");
    rs_pcache *pc = (rs_pcache *)blk;
    pc->vk = blk + sizeof(rs_pcache);
    pc->nseg = n;
    pc->nvert = nv;
    pc->closed = closed;
    pc->sides = s->sides == 2 ? 2 : 1;
    pc->revolution = s->kind == RS_SURF_REVOLUTION;
    pc->size = rs_profile_size(p);
    pc->seg = p->seg;
    vertex_kinds(p, pc);
    pc->tree = (double *)(blk + head + recs);
    pc->ntlev = ntlev;
    memcpy(pc->tlev, tlev, (size_t)(ntlev + 1) * sizeof(int));
    build_tree(pc);
    if (compact) {
        *out = pc;
        return RS_OK;
    }
    pc->ps = (rs_pseg *)(blk + head);
    pc->pv = (rs_pvert *)(blk + head + (size_t)n * sizeof(rs_pseg));
    for (int j = 0; j < nv; j++)
        rs_pcache_vertex(pc, j, &pc->pv[j]);
    for (int k = 0; k < n; k++)
        rs_pcache_segment(pc, k, &pc->pv[k], &pc->pv[k + 1 == nv ? 0 : k + 1], &pc->ps[k]);

    /* Bucket axis: the one whose finest level costs less to scan (a drum's mantle
     * pieces spread along z, not along r). */
    const double lo[2] = {pc->box[0], pc->box[2]}, hi[2] = {pc->box[1], pc->box[3]};
    double best = -1.0;
    int best_axis = 0;
    const int nb = n * RS_PC_BUCKETS_PER_SEG;
    pc->nbucket = nb;
    int *cnt = n > 1 ? malloc((size_t)(nb + 1) * sizeof(int)) : NULL;
    for (int a = 0; a < 2 && cnt; a++) {
        double ext = hi[a] - lo[a];
        if (!(ext > 0.0) || !isfinite(ext))
            continue;
        pc->axis = a;
        pc->lo = lo[a];
        pc->inv_w = (double)nb / ext;
        const double sq = bucket_cost(pc, 0.25 * ext / nb, cnt);
        if (best < 0.0 || sq < best) {
            best = sq;
            best_axis = a;
        }
    }
    free(cnt);
    long entries = 0;
    if (best < 0.0) {
        /* one bucket that lists every segment at any reach */
        pc->axis = 0;
        pc->nbucket = 1;
        pc->lo = 0.0;
        pc->inv_w = 0.0;
        pc->nlevel = 1;
        pc->margin[0] = INFINITY;
        entries = n;
    } else {
        pc->axis = best_axis;
        pc->lo = lo[best_axis];
        pc->inv_w = (double)nb / (hi[best_axis] - lo[best_axis]);
        pc->nlevel =
            bucket_levels(pc, hi[best_axis] - lo[best_axis], 32L * nb + 64, &entries);
    }
    size_t ints =
        (size_t)pc->nlevel * (size_t)(2 * pc->nbucket + 1) + (size_t)entries + (size_t)n;
    unsigned char *nblk = realloc(blk, whole + ints * sizeof(int));
    if (!nblk) {
        free(blk);
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory for the query data");
    }
    blk = nblk;
    pc = (rs_pcache *)blk;
    pc->vk = blk + sizeof(rs_pcache);
    pc->ps = (rs_pseg *)(blk + head);
    pc->pv = (rs_pvert *)(blk + head + (size_t)n * sizeof(rs_pseg));
    pc->tree = (double *)(blk + head + recs);
    pc->bstart = (int *)(blk + whole);
    pc->boff = pc->bstart + (size_t)pc->nlevel * (size_t)(pc->nbucket + 1);
    pc->all_at = (int)entries;
    pc->bchain = pc->boff + entries + n;
    for (int k = 0; k < n; k++)
        pc->boff[entries + k] = k * (int)sizeof(rs_pseg);
    long off = 0;
    for (int l = 0; l < pc->nlevel; l++) {
        int *bs = pc->bstart + (size_t)l * (size_t)(pc->nbucket + 1);
        if (pc->nbucket == 1 && !isfinite(pc->margin[l])) {
            bs[0] = (int)off;
            bs[1] = (int)off + n;
            for (int k = 0; k < n; k++)
                pc->boff[off + k] = k * (int)sizeof(rs_pseg);
            off += n;
            continue;
        }
        long e = bucket_level(pc, pc->margin[l], bs, pc->boff + off);
        for (int b = 0; b <= pc->nbucket; b++)
            bs[b] += (int)off;
        off += e;
    }
    /* A LINE chain: a list of consecutive LINE segments joined by SMOOTH vertices (so
     * collinear). Their slabs partition the chain's neighbourhood and no vertex inside
     * can own a point; the segments outside the list are beyond reach. A point in such
     * a bucket is owned by one face or by none (then an end or corner vertex decides,
     * which the per-point path answers). When one piece owns every point of the bucket
     * within the level's margin (chain_owner), the bucket names it: 2 + k. */
    for (int l = 0; l < pc->nlevel; l++)
        for (int b = 0; b < pc->nbucket; b++) {
            const int *bs = pc->bstart + (size_t)l * (size_t)(pc->nbucket + 1);
            int chain = bs[b + 1] > bs[b];
            for (int e = bs[b]; chain && e < bs[b + 1]; e++) {
                const int k = rs_pcache_seg(pc->boff[e]);
                chain = pc->ps[k].type == RS_LINE &&
                        (e == bs[b] || (k == rs_pcache_seg(pc->boff[e - 1]) + 1 &&
                                        pc->vk[k] == RS_VTX_SMOOTH));
            }
            if (chain) {
                const int own =
                    chain_owner(pc, pc->margin[l], b, pc->boff + bs[b], bs[b + 1] - bs[b]);
                chain = own >= 0 ? 2 + own : 1;
            }
            pc->bchain[(size_t)l * (size_t)pc->nbucket + b] = chain;
        }
    *out = pc;
    return RS_OK;
}
