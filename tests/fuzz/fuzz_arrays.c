/* The fuzz target's second reading of an input: its bytes as the arrays of a surface
 * built in memory (rs_surface_make_mesh, rs_surface_make_profile). Either the arrays are
 * refused with a code and a message and the surface left zeroed, or the surface answers
 * every query with finite contacts (rs_fuzz_check_surface). */
#include "fuzz_bytes.h"
#include "fuzz_surface.h"

#include "rigidsurf/surface.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

long rs_fuzz_arrays_accepted;

static int verdict(int rc, const rs_error *e, rs_surface *s, const char *what)
{
    if (rc != RS_OK) {
        if (e->code != rc || e->msg[0] == '\0' || s->ops != NULL) {
            fprintf(stderr,
                    "fuzz_arrays: %s refused without a message or a zeroed surface "
                    "(code %d)\n",
                    what, rc);
            return 1;
        }
        return 0;
    }
    rs_fuzz_accepted++;
    rs_fuzz_arrays_accepted++;
    const int fail = rs_fuzz_check_surface(s);
    rs_surface_free(s);
    return fail;
}

static int mesh_arrays(bytes *b)
{
    enum { MAXV = 24, MAXT = 32 };
    double xyz[3 * MAXV];
    int tri[3 * MAXT];
    const int nv = 3 + (int)(next(b) % (MAXV - 2)), nt = 1 + (int)(next(b) % MAXT);
    for (int i = 0; i < 3 * nv; i++)
        xyz[i] = value(b);
    for (int k = 0; k < 3 * nt; k++) {
        const unsigned c = next(b);
        tri[k] = c == 0xfa ? nv : c == 0xf9 ? -1 : (int)(c % (unsigned)nv);
    }
    rs_mesh_def def = RS_MESH_DEF_INIT;
    def.name = "fuzz";
    def.sides = (int)(next(b) % 3);
    if (next(b) % 4 == 0)
        def.scale = value(b);
    def.placed = next(b) % 4 == 0;
    for (int i = 0; i < 9 && def.placed; i++)
        def.abc[i] = value(b);
    rs_surface s;
    rs_error e;
    const int rc = rs_surface_make_mesh(xyz, nv, tri, nt, &def, &s, &e);
    return verdict(rc, &e, &s, "mesh arrays");
}

static int profile_arrays(bytes *b)
{
    enum { MAXI = 10 };
    rs_profile_item items[MAXI];
    rs_profile_def def;
    memset(&def, 0, sizeof def);
    def.kind = (rs_surface_kind)(1 + next(b) % 3);
    def.name = "fuzz";
    def.sides = (int)(next(b) % 3);
    if (next(b) % 4 == 0)
        def.fillet = fabs(value(b)) / 8.0;
    for (int i = 0; i < 3; i++) {
        def.a[i] = value(b);
        def.b[i] = def.a[i] + (next(b) % 2 ? value(b) : i == 2);
        def.c[i] = value(b);
    }
    if (def.kind == RS_SURF_CYLINDER && next(b) % 4 == 0) {
        def.bounded = 1;
        def.zmin = value(b);
        def.zmax = value(b);
    }
    const int n = (int)(next(b) % (MAXI + 1));
    double cur[2] = {0.0, 0.0};
    for (int k = 0; k < n; k++) {
        rs_profile_item *it = &items[k];
        const unsigned w = next(b) % 16;
        it->word = k == 0 || w == 0 ? RS_WORD_START
                   : w < 8          ? RS_WORD_LINE
                   : w < 12         ? RS_WORD_CIRCL
                                    : RS_WORD_PARAB;
        for (int i = 0; i < 4; i++)
            it->v[i] = value(b);
        if (it->word == RS_WORD_CIRCL && next(b) % 4) {
            /* most arcs consistent: the centre on the bisector of the chord */
            const double mx = 0.5 * (cur[0] + it->v[0]), my = 0.5 * (cur[1] + it->v[1]);
            const double t = value(b) / 4.0;
            it->v[2] = mx - t * (it->v[1] - cur[1]);
            it->v[3] = my + t * (it->v[0] - cur[0]);
        }
        const int end = it->word == RS_WORD_PARAB ? 2 : 0;
        cur[0] = it->v[end];
        cur[1] = it->v[end + 1];
    }
    rs_surface s;
    rs_error e;
    const int rc = rs_surface_make_profile(&def, items, n, &s, &e);
    return verdict(rc, &e, &s, "profile arrays");
}

int rs_fuzz_arrays_one(const uint8_t *data, size_t size)
{
    if (size == 0)
        return 0;
    bytes b = {data, size, 0};
    return (data[size / 2] + size) % 2 ? mesh_arrays(&b) : profile_arrays(&b);
}
