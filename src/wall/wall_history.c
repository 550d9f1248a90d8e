/* The wall's per-particle history: rows (the tracker's directory, the previous temperature
 * and fields), each row's summary (rs_wall.usual) and slot-major slots (particle i's slot j at hist + (j nmax + i) slot_size,
 * so a particle with one contact touches its row and the dense slot-0 array only); their
 * growth with the engine's arrays and with the contacts a particle holds, and the records
 * that carry a particle's history between ranks and into restart files. */
#define _DEFAULT_SOURCE /* posix_memalign, madvise and MADV_HUGEPAGE */
#include "wall_impl.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

/* The per-particle history of a large run walks through megabytes each step: its blocks
 * are offered to the kernel as huge pages (one TLB entry for 32768 hertz slots instead of
 * one per 64), where the kernel gives them on request (transparent_hugepage madvise). */
static const size_t kHugePage = (size_t)2 << 20;

void wall_advise_huge(void *p, size_t bytes)
{
#ifdef MADV_HUGEPAGE
    const uintptr_t page = 4096, a = ((uintptr_t)p + page - 1) & ~(page - 1),
                    b = ((uintptr_t)p + bytes) & ~(page - 1);
    if (p && bytes >= kHugePage && b > a)
        madvise((void *)a, b - a, MADV_HUGEPAGE); /* a hint: its failure changes nothing */
#else
    (void)p, (void)bytes;
#endif
}

/* Slot memory, on 2 MB boundaries when it is that large; freed with free(). */
double *wall_alloc_slots(size_t n)
{
    const size_t bytes = (n > 1 ? n : 1) * sizeof(double);
    void *p = NULL;
    if (posix_memalign(&p, bytes >= kHugePage ? kHugePage : 64, bytes) != 0)
        return NULL;
    wall_advise_huge(p, bytes);
    return p;
}

void wall_clear_row(rs_wall *w, int i)
{
    w->usual[i] = 0;
    double *r = wall_row(w, i);
    rs_track_clear(&w->tracker, r, wall_slot0(w, i), wall_slot_stride(w));
    r[wall_tprev_at(w)] = NAN;
    for (int a = 0; a < w->npred; a++)
        r[wall_pred_at(w) + a] = NAN;
}

int rs_wall_grow(rs_wall *w, int nmax, rs_error *err)
{
    if (nmax <= w->nmax)
        return RS_OK;
    const size_t rs = (size_t)wall_row_size(w);
    double *rows = realloc(w->rows, (size_t)nmax * rs * sizeof *rows);
    if (!rows)
        return rs_error_set(err, RS_ERR_NOMEM,
                            "out of memory for the history of %d particles", nmax);
    w->rows = rows;
    wall_advise_huge(rows, (size_t)nmax * rs * sizeof *rows);
    int *usual = realloc(w->usual, (size_t)nmax * sizeof *usual);
    if (!usual)
        return rs_error_set(err, RS_ERR_NOMEM,
                            "out of memory for the history of %d particles", nmax);
    w->usual = usual;
    /* The slots move: slot j of the old nmax particles to the start of block j. */
    const size_t hs = (size_t)wall_slot_size(w), oldblk = (size_t)w->nmax * hs,
                 blk = (size_t)nmax * hs;
    double *h = wall_alloc_slots((size_t)w->capacity * blk);
    if (!h)
        return rs_error_set(err, RS_ERR_NOMEM,
                            "out of memory for the contact history slots of %d particles",
                            nmax);
    for (int j = 0; j < w->capacity; j++)
        if (oldblk)
            memcpy(h + j * blk, w->hist + j * oldblk, sizeof(double) * oldblk);
    free(w->hist);
    w->hist = h;
    const int old = w->nmax;
    w->nmax = nmax;
    for (int i = old; i < nmax; i++)
        wall_clear_row(w, i);
    return RS_OK;
}

int wall_max_capacity(const rs_wall *w)
{
    if (w->run.exchange_max <= 0)
        return RS_TRACK_MAX_CAPACITY;
    /* 1 (capacity) + capacity (directory) + the rest of the row + capacity slots */
    const int fixed = 1 + wall_row_size(w) - w->capacity;
    const int cap = (w->run.exchange_max - fixed) / (wall_slot_size(w) + 1);
    return cap < RS_TRACK_MAX_CAPACITY ? cap : RS_TRACK_MAX_CAPACITY;
}

/* One particle's history as plain doubles: its row, then its slots in slot order. */
void wall_pack_atom(const rs_wall *w, int i, double *buf)
{
    const int rs = wall_row_size(w), hs = wall_slot_size(w);
    const ptrdiff_t stride = wall_slot_stride(w);
    memcpy(buf, wall_row(w, i), sizeof(double) * rs);
    const double *h = wall_slot0(w, i);
    for (int j = 0; j < w->capacity; j++)
        memcpy(buf + rs + j * hs, h + j * stride, sizeof(double) * hs);
}

void wall_unpack_atom(rs_wall *w, int i, const double *buf)
{
    const int rs = wall_row_size(w), hs = wall_slot_size(w);
    const ptrdiff_t stride = wall_slot_stride(w);
    memcpy(wall_row(w, i), buf, sizeof(double) * rs);
    double *h = wall_slot0(w, i);
    for (int j = 0; j < w->capacity; j++)
        memcpy(h + j * stride, buf + rs + j * hs, sizeof(double) * hs);
}

/* A particle's history packed with capacity buf[0] (at most capacity) into particle i: the
 * directory and slots it has, the rest free. Returns the doubles read. */
static int unpack_sized(rs_wall *w, int i, const double *buf)
{
    const int cin = (int)buf[0];
    const int hs = wall_slot_size(w), rest = wall_row_size(w) - w->capacity;
    const ptrdiff_t stride = wall_slot_stride(w);
    const double *row = buf + 1, *slots = row + cin + rest;
    wall_clear_row(w, i);
    double *r = wall_row(w, i);
    memcpy(r, row, sizeof(double) * cin);                      /* directory */
    memcpy(r + w->capacity, row + cin, sizeof(double) * rest); /* T, fields */
    double *h = wall_slot0(w, i);
    for (int j = 0; j < cin; j++)
        memcpy(h + j * stride, slots + j * hs, sizeof(double) * hs);
    return 1 + cin + rest + cin * hs;
}

/* Grows every particle's history to at least need slots (doubling), keeping what it
 * holds; RS_ERR_CAPACITY when need exceeds wall_max_capacity. */
int wall_grow_capacity(rs_wall *w, int need, rs_error *err)
{
    if (need <= w->capacity)
        return RS_OK;
    const int maxcap = wall_max_capacity(w);
    if (need > maxcap)
        return rs_error_set(err, RS_ERR_CAPACITY, "the slots cannot grow past %d", maxcap);
    int cap = w->capacity;
    while (cap < need)
        cap *= 2;
    cap = cap < maxcap ? cap : maxcap;
    /* every particle's history through the new layout: packed at the old capacity, then
     * unpacked into rows and slots made for the new one */
    const int nmax = w->nmax > 1 ? w->nmax : 1;
    const size_t old_as = 1 + (size_t)wall_atom_size(w);
    double *keep = malloc((size_t)w->nmax * old_as * sizeof *keep + 1);
    if (!keep)
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory growing the contact history");
    for (int i = 0; i < w->nmax; i++) {
        keep[(size_t)i * old_as] = w->capacity;
        wall_pack_atom(w, i, &keep[(size_t)i * old_as + 1]);
    }
    const int old_cap = w->capacity;
    w->capacity = cap;
    w->tracker.capacity = cap;
    const size_t rs = (size_t)wall_row_size(w);
    double *rows = malloc((size_t)nmax * rs * sizeof *rows);
    double *hist = wall_alloc_slots((size_t)cap * (size_t)nmax * (size_t)wall_slot_size(w));
    if (!rows || !hist) {
        free(rows);
        free(hist);
        free(keep);
        w->capacity = w->tracker.capacity = old_cap;
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory growing the contact history");
    }
    free(w->rows);
    free(w->hist);
    w->rows = rows;
    w->hist = hist;
    wall_advise_huge(rows, (size_t)nmax * rs * sizeof *rows);
    for (int i = 0; i < w->nmax; i++)
        unpack_sized(w, i, &keep[(size_t)i * old_as]);
    free(keep);
    /* the block's scratch follows, once a run has made it */
    return w->bcap > 0 ? wall_scratch_contacts(w, err) : RS_OK;
}

void rs_wall_copy(rs_wall *w, int i, int j)
{
    const int hs = wall_slot_size(w);
    const ptrdiff_t stride = wall_slot_stride(w);
    memcpy(wall_row(w, j), wall_row(w, i), sizeof(double) * wall_row_size(w));
    w->usual[j] = w->usual[i];
    for (int s = 0; s < w->capacity; s++)
        memcpy(wall_slot0(w, j) + s * stride, wall_slot0(w, i) + s * stride,
               sizeof(double) * hs);
}

void rs_wall_clear(rs_wall *w, int i)
{
    wall_clear_row(w, i);
}

int rs_wall_pack_size(const rs_wall *w)
{
    return 1 + wall_atom_size(w);
}

/* Exchange and restart records: the capacity, then the particle's history. A particle
 * from a rank whose capacity grew further grows this rank's first. */
int rs_wall_pack(const rs_wall *w, int i, double *buf)
{
    buf[0] = w->capacity;
    wall_pack_atom(w, i, buf + 1);
    return 1 + wall_atom_size(w);
}

int rs_wall_unpack(rs_wall *w, int i, const double *buf, rs_error *err)
{
    const int cin = (int)buf[0];
    if (cin > w->capacity && wall_grow_capacity(w, cin, err) != RS_OK) {
        rs_error_set(err, RS_ERR_CAPACITY,
                     "a particle arrived with more contact slots than this rank can hold");
        return -1;
    }
    return unpack_sized(w, i, buf);
}

/* A restart record: written under this wall's slot layout, or (files of earlier builds)
 * with every field of the contact's last call kept, or with the slip and rdisp1 this law
 * does not read; the fields this law does not read are left out. Files of layout version
 * 5 had directory entries one less than RS_DIR_LIVE(f). */
int rs_wall_unpack_restart(rs_wall *w, int i, const double *rec, int n, rs_error *err)
{
    const int cin = (int)rec[0];
    const int rest = wall_row_size(w) - w->capacity;
    const int hs = wall_slot_size(w);
    const int want = 1 + rest + cin * (1 + hs);
    const unsigned layouts[2] = {0u, w->tracker.drop & ~(unsigned)RS_DROP_SLIP};
    double *compact = NULL;
    for (int v = 0; v < 2 && cin >= 1 && n != want && !compact; v++) {
        rs_tracker from = w->tracker;
        from.drop = layouts[v];
        const int fs = rs_track_slot_size(&from);
        if (fs == hs || n != 1 + rest + cin * (1 + fs))
            continue;
        compact = malloc((size_t)(1 + cin + rest + cin * hs) * sizeof *compact);
        if (!compact)
            return rs_error_set(err, RS_ERR_NOMEM,
                                "out of memory reading a restart record");
        memcpy(compact, rec, (size_t)(1 + cin + rest) * sizeof *compact);
        for (int j = 0; j < cin; j++)
            rs_track_slot_convert(&w->tracker, from.drop,
                                  rec + 1 + cin + rest + (size_t)j * fs,
                                  compact + 1 + cin + rest + (size_t)j * hs);
    }
    if (compact) {
        rec = compact;
    } else if (cin < 1 || n != want) {
        return rs_error_set(err, RS_ERR_ARG,
                            "restart file has %d history values per atom for %d contact "
                            "slots; this fix needs %d (keep the law, statev and predef "
                            "unchanged)",
                            n, cin, want);
    }
    int rc = RS_OK;
    if (cin > w->capacity && wall_grow_capacity(w, cin, err) != RS_OK)
        rc = rs_error_set(err, RS_ERR_CAPACITY,
                          "the restart file has more contact slots per atom than this fix "
                          "can hold");
    else if (w->restart_version == 0.0)
        rc =
            rs_error_set(err, RS_ERR_ARG,
                         "the restart file holds wall/rigid history per atom but no global "
                         "record with its layout version");
    if (rc == RS_OK) {
        unpack_sized(w, i, rec);
        /* version 5: a directory entry was the feature f (empty -1, leaving -2 - f), one
         * less than RS_DIR_LIVE(f) (RS_DIR_EMPTY, RS_DIR_LEAVING(f)) */
        if (w->restart_version < 6.0)
            for (int j = 0; j < cin; j++)
                wall_row(w, i)[j] += 1.0;
    }
    free(compact);
    return rc;
}

double rs_wall_memory(const rs_wall *w)
{
    return (double)w->nmax * wall_atom_size(w) * sizeof(double);
}
