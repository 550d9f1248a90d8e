/* The scratch of the profile searches (rs_pscratch, profile.h): carved from the caller's
 * stack block when it is large enough, else from the heap. */
#include "profile.h"

#include <stdint.h>
#include <stdlib.h>

/* Bytes of scratch for cap near segments (hits: at most 2 cap + 1, profile.h). */
static size_t scratch_bytes(size_t cap)
{
    size_t ints = cap * sizeof(int) + cap;
    ints = (ints + 15) & ~(size_t)15;
    return ints + (3 * cap + 1) * sizeof(rs_hit2) + 64;
}

/* The scratch's capacity: every segment in the stored form, at first RS_PSCRATCH_CAP in
 * the compact one (rs_pscratch_grow). */
static int scratch_cap(const rs_pcache *pc)
{
    return pc->ps || pc->nseg <= RS_PSCRATCH_CAP ? pc->nseg : RS_PSCRATCH_CAP;
}

size_t rs_pscratch_bytes(const rs_pcache *pc)
{
    return scratch_bytes((size_t)scratch_cap(pc));
}

/* The arrays of a scratch of capacity cap in block m. */
static void scratch_carve(rs_pscratch *sc, unsigned char *m, int cap)
{
    m = (unsigned char *)(((uintptr_t)m + 15u) & ~(uintptr_t)15u);
    size_t n = (size_t)cap;
    size_t ints = n * sizeof(int) + n;
    ints = (ints + 15) & ~(size_t)15;
    sc->cap = cap;
    sc->near = (int *)m;
    sc->state = (unsigned char *)(sc->near + n);
    sc->cand = (rs_hit2 *)(m + ints);
    sc->hits = sc->cand + n;
}

int rs_pscratch_init(rs_pscratch *sc, const rs_pcache *pc, void *stack, size_t stack_bytes)
{
    const int cap = scratch_cap(pc);
    size_t need = scratch_bytes((size_t)cap);
    unsigned char *m = stack;
    sc->heap = NULL;
    if (!m || stack_bytes < need) {
        m = malloc(need);
        if (!m)
            return RS_ERR_NOMEM;
        sc->heap = m;
    }
    scratch_carve(sc, m, cap);
    return RS_OK;
}

int rs_pscratch_grow(rs_pscratch *sc, const rs_pcache *pc)
{
    const int cap = sc->cap > pc->nseg / 4 ? pc->nseg : 4 * sc->cap;
    unsigned char *m = malloc(scratch_bytes((size_t)cap));
    if (!m)
        return RS_ERR_NOMEM;
    free(sc->heap);
    sc->heap = m;
    scratch_carve(sc, m, cap);
    return RS_OK;
}

void rs_pscratch_free(rs_pscratch *sc)
{
    free(sc->heap);
    sc->heap = NULL;
}
