/* Surfaces built from arrays in memory (rs_surface_make_profile, rs_surface_make_mesh):
 * each kind answers rs_surface_query bit for bit as the same surface read from keyword
 * text or a file, and bad arrays are refused with the reader's messages. */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */
#define RS_TEST_SEED 0x2545F4914F6CDD1Dull

#include "rs_test.h"

#include "rigidsurf/surface.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char tmpdir[64];

enum { NQ = 600 };

/* Spheres and points over the bounds, widened by a fifth (unbounded sides: +-1). */
static void fill_slaves(const rs_surface *s, double *x, double *y, double *z, double *r)
{
    double lo[3], hi[3];
    rs_surface_bounds(s, lo, hi);
    for (int d = 0; d < 3; d++) {
        if (!isfinite(lo[d]))
            lo[d] = -1.0;
        if (!isfinite(hi[d]))
            hi[d] = 1.0;
        const double pad = 0.2 * (hi[d] - lo[d]) + 1e-3;
        lo[d] -= pad;
        hi[d] += pad;
    }
    const double size = fmax(hi[0] - lo[0], fmax(hi[1] - lo[1], hi[2] - lo[2]));
    unsigned long long st = RS_TEST_SEED;
    for (int i = 0; i < NQ; i++) {
        x[i] = lo[0] + (hi[0] - lo[0]) * rs_test_urand(&st);
        y[i] = lo[1] + (hi[1] - lo[1]) * rs_test_urand(&st);
        z[i] = lo[2] + (hi[2] - lo[2]) * rs_test_urand(&st);
        r[i] = size * (0.01 + 0.1 * rs_test_urand(&st));
    }
}

static int same_doubles(const double *a, const double *b, int n)
{
    return n == 0 || memcmp(a, b, (size_t)n * sizeof *a) == 0;
}

/* Both surfaces' contacts with the same spheres and points, compared bit for bit; at
 * least min contacts of spheres and min / 4 of points, so that the comparison is not
 * vacuous. */
static int same_answers(const rs_surface *a, const rs_surface *b, int min)
{
    static double x[NQ], y[NQ], z[NQ], r[NQ];
    fill_slaves(a, x, y, z, r);
    int ok = a->kind == b->kind && a->sides == b->sides && strcmp(a->name, b->name) == 0;
    double la[3], ha[3], lb[3], hb[3];
    rs_surface_bounds(a, la, ha);
    rs_surface_bounds(b, lb, hb);
    ok = ok && same_doubles(la, lb, 3) && same_doubles(ha, hb, 3);
    for (int sph = 0; sph < 2 && ok; sph++) {
        rs_query q = {.n = NQ,
                      .slave = {.x = x, .y = y, .z = z, .radius = sph ? r : NULL},
                      .pose = NULL,
                      .gap_max = 0.05,
                      .dist_min = -INFINITY};
        rs_contacts ca, cb;
        memset(&ca, 0, sizeof ca);
        memset(&cb, 0, sizeof cb);
        rs_error e;
        ok = rs_surface_query(a, &q, &ca, &e) == RS_OK &&
             rs_surface_query(b, &q, &cb, &e) == RS_OK && ca.n == cb.n &&
             ca.n >= (sph ? min : min / 4);
        if (ok && ca.n > 0) {
            const int n = ca.n;
            ok = memcmp(ca.point, cb.point, (size_t)n * sizeof(int)) == 0 &&
                 memcmp(ca.feature, cb.feature, (size_t)n * sizeof(int)) == 0 &&
                 same_doubles(ca.dist, cb.dist, n) && same_doubles(ca.share, cb.share, n);
            for (int d = 0; d < 3 && ok; d++)
                ok = same_doubles(ca.xm[d], cb.xm[d], n) &&
                     same_doubles(ca.nrm[d], cb.nrm[d], n) &&
                     same_doubles(ca.t1[d], cb.t1[d], n) &&
                     same_doubles(ca.t2[d], cb.t2[d], n);
            ok = ok && same_doubles(ca.curv[0], cb.curv[0], n) &&
                 same_doubles(ca.curv[1], cb.curv[1], n);
        }
        if (!ok)
            fprintf(stderr,
                    "same_answers: %s with %d and %d contacts (at least %d) differ\n",
                    sph ? "spheres" : "points", ca.n, cb.n, sph ? min : min / 4);
        rs_contacts_free(&ca);
        rs_contacts_free(&cb);
    }
    return ok;
}

/* ---- the analytic kinds --------------------------------------------------------- */

/* The hopper of examples/surfaces/hopper.inp, with its fillets, as arrays. */
static void hopper_from_arrays_is_the_file(void)
{
    const rs_profile_item items[] = {{RS_WORD_START, {0.03, -0.10}},
                                     {RS_WORD_LINE, {0.03, -0.007846}},
                                     {RS_WORD_LINE, {0.15, 0.20}},
                                     {RS_WORD_LINE, {0.15, 0.50}}};
    rs_profile_def def = {0};
    def.kind = RS_SURF_REVOLUTION;
    def.name = "hopper_round";
    def.fillet = 0.01;
    def.b[2] = 1.0;
    rs_surface fa, fr;
    rs_error e;
    ENSURE(rs_surface_make_profile(&def, items, 4, &fa, &e) == RS_OK);
    ENSURE(e.code == RS_OK && e.msg[0] == '\0');
    ENSURE(rs_surface_read("../examples/surfaces/hopper.inp", "hopper_round", &fr, &e) ==
           RS_OK);
    ENSURE(fa.sides == 1 && fa.profile.nseg == 5); /* two fillets added */
    const int same = same_answers(&fa, &fr, 50);
    rs_surface_free(&fa);
    rs_surface_free(&fr);
    ENSURE(same);
}

/* The keyword text of def and items, every number to 17 digits (exact round trip). */
static void profile_text(const rs_profile_def *def, const rs_profile_item *items, int n,
                         char *buf, size_t cap)
{
    static const char *const kinds[] = {"", "SEGMENTS", "CYLINDER", "REVOLUTION"};
    static const char *const words[] = {"START", "LINE", "CIRCL", "PARAB"};
    size_t u = (size_t)snprintf(buf, cap, "*SURFACE, TYPE=%s, NAME=%s", kinds[def->kind],
                                def->name);
    if (def->sides)
        u += (size_t)snprintf(buf + u, cap - u, ", SIDES=%d", def->sides);
    if (def->fillet > 0.0)
        u += (size_t)snprintf(buf + u, cap - u, ", FILLET RADIUS=%.17g", def->fillet);
    if (def->bounded)
        u += (size_t)snprintf(buf + u, cap - u, ", EXTENT=%.17g, %.17g", def->zmin,
                              def->zmax);
    u += (size_t)snprintf(buf + u, cap - u, "\n");
    if (def->kind != RS_SURF_SEGMENTS)
        u += (size_t)snprintf(buf + u, cap - u,
                              "%.17g, %.17g, %.17g, %.17g, %.17g, %.17g\n", def->a[0],
                              def->a[1], def->a[2], def->b[0], def->b[1], def->b[2]);
    if (def->kind == RS_SURF_CYLINDER)
        u += (size_t)snprintf(buf + u, cap - u, "%.17g, %.17g, %.17g\n", def->c[0],
                              def->c[1], def->c[2]);
    for (int k = 0; k < n; k++) {
        const int nv = items[k].word <= RS_WORD_LINE ? 2 : 4;
        u += (size_t)snprintf(buf + u, cap - u, "%s", words[items[k].word]);
        for (int i = 0; i < nv; i++)
            u += (size_t)snprintf(buf + u, cap - u, ", %.17g", items[k].v[i]);
        u += (size_t)snprintf(buf + u, cap - u, "\n");
    }
}

/* Arrays and their text: the same surface, or the same error (code and message). */
static int arrays_match_text(const rs_profile_def *def, const rs_profile_item *items, int n,
                             int min, rs_error *ea)
{
    char text[4096];
    profile_text(def, items, n, text, sizeof text);
    rs_surface sa, st;
    rs_error et;
    const int ra = rs_surface_make_profile(def, items, n, &sa, ea);
    const int rt =
        rs_surface_parse(text, def->origin ? def->origin : "<arrays>", NULL, &st, &et);
    int ok = ra == rt;
    if (ok && ra == RS_OK)
        ok = same_answers(&sa, &st, min);
    else if (ok)
        ok = strcmp(ea->msg, et.msg) == 0 && sa.ops == NULL;
    if (!ok)
        fprintf(stderr, "arrays: %d '%s'\ntext:   %d '%s'\n%s", ra, ra ? ea->msg : "", rt,
                rt ? et.msg : "", text);
    if (ra == RS_OK)
        rs_surface_free(&sa);
    if (rt == RS_OK)
        rs_surface_free(&st);
    return ok;
}

static void segments_from_arrays_are_the_text(void)
{
    /* a trough: a line, an arc, a parabola and a line, both sides, with fillets */
    const rs_profile_item items[] = {
        {RS_WORD_START, {-2.0, 1.0}},          {RS_WORD_LINE, {-1.0, 0.0}},
        {RS_WORD_LINE, {0.0, -0.2}},           {RS_WORD_CIRCL, {0.8, -0.2, 0.4, -0.5}},
        {RS_WORD_PARAB, {1.2, 0.1, 1.5, 0.8}}, {RS_WORD_LINE, {2.0, 0.5}}};
    rs_profile_def def = {0};
    def.kind = RS_SURF_SEGMENTS;
    def.name = "trough";
    def.sides = 2;
    def.fillet = 0.05;
    rs_error e;
    ENSURE(arrays_match_text(&def, items, 6, 100, &e) && e.code == RS_OK);
    def.sides = 0;
    def.fillet = 0.0;
    ENSURE(arrays_match_text(&def, items, 6, 100, &e) && e.code == RS_OK);
}

static void cylinder_from_arrays_is_the_text(void)
{
    /* a closed rounded box section on a tilted generator, bounded */
    const rs_profile_item items[] = {{RS_WORD_START, {0.5, -0.5}},
                                     {RS_WORD_LINE, {0.5, 0.5}},
                                     {RS_WORD_LINE, {-0.5, 0.5}},
                                     {RS_WORD_CIRCL, {-1.0, 0.0, -0.5, 0.0}},
                                     {RS_WORD_LINE, {0.5, -0.5}}};
    rs_profile_def def = {0};
    def.kind = RS_SURF_CYLINDER;
    def.name = "duct";
    def.origin = "duct.inp";
    def.fillet = 0.1;
    const double a[3] = {0.1, 0.2, 0.3}, b[3] = {1.1, 0.3, 0.2}, c[3] = {0.2, 0.4, 1.5};
    memcpy(def.a, a, sizeof a);
    memcpy(def.b, b, sizeof b);
    memcpy(def.c, c, sizeof c);
    def.bounded = 1;
    def.zmin = -0.5;
    def.zmax = 0.7;
    rs_error e;
    ENSURE(arrays_match_text(&def, items, 5, 100, &e) && e.code == RS_OK);
}

static void revolution_from_arrays_is_the_text(void)
{
    /* a cup: from the axis along the floor, up a parabolic wall, on a tilted axis */
    const rs_profile_item items[] = {{RS_WORD_START, {0.0, 0.0}},
                                     {RS_WORD_LINE, {0.4, 0.0}},
                                     {RS_WORD_PARAB, {0.55, 0.3, 0.6, 0.8}},
                                     {RS_WORD_CIRCL, {0.8, 0.8, 0.7, 0.7}}};
    rs_profile_def def = {0};
    def.kind = RS_SURF_REVOLUTION;
    def.name = "cup";
    def.sides = 1;
    const double a[3] = {1.0, -1.0, 0.5}, b[3] = {1.2, -0.9, 1.5};
    memcpy(def.a, a, sizeof a);
    memcpy(def.b, b, sizeof b);
    rs_error e;
    ENSURE(arrays_match_text(&def, items, 4, 100, &e) && e.code == RS_OK);
}

/* Geometry the reader refuses is refused from arrays with its code and message. */
static void bad_profiles_give_the_readers_messages(void)
{
    rs_profile_def def = {0};
    def.kind = RS_SURF_REVOLUTION;
    def.name = "bad";
    def.b[2] = 1.0;
    rs_error e;
    /* a zero-length line (item 3, line 5 of the text) */
    const rs_profile_item zero[] = {{RS_WORD_START, {1.0, 0.0}},
                                    {RS_WORD_LINE, {1.0, 1.0}},
                                    {RS_WORD_LINE, {1.0, 1.0}}};
    ENSURE(arrays_match_text(&def, zero, 3, 0, &e));
    ENSURE(e.code == RS_ERR_GEOMETRY && strstr(e.msg, "<arrays>:5:"));
    /* an arc of 180 degrees */
    const rs_profile_item half[] = {{RS_WORD_START, {1.0, 0.0}},
                                    {RS_WORD_CIRCL, {1.0, 2.0, 1.0, 1.0}}};
    ENSURE(arrays_match_text(&def, half, 2, 0, &e));
    ENSURE(e.code == RS_ERR_GEOMETRY);
    /* a profile that crosses the axis */
    const rs_profile_item across[] = {{RS_WORD_START, {0.5, 0.0}},
                                      {RS_WORD_LINE, {-0.5, 1.0}}};
    ENSURE(arrays_match_text(&def, across, 2, 0, &e));
    ENSURE(e.code == RS_ERR_GEOMETRY && strstr(e.msg, "r >= 0"));
    /* START only: an empty profile */
    ENSURE(arrays_match_text(&def, zero, 1, 0, &e));
    ENSURE(strstr(e.msg, "empty profile") && strstr(e.msg, "'bad'"));
    /* a second START; a LINE before START */
    const rs_profile_item twice[] = {{RS_WORD_START, {1.0, 0.0}},
                                     {RS_WORD_START, {1.0, 1.0}}};
    ENSURE(arrays_match_text(&def, twice, 2, 0, &e));
    ENSURE(strstr(e.msg, "<arrays>:4: START must be the first"));
    ENSURE(arrays_match_text(&def, zero + 1, 2, 0, &e));
    ENSURE(strstr(e.msg, "expected START before LINE"));
    /* a and b coincide */
    def.b[2] = 0.0;
    ENSURE(arrays_match_text(&def, zero, 2, 0, &e));
    ENSURE(e.code == RS_ERR_GEOMETRY && strstr(e.msg, "<arrays>:2: points a and b"));
    /* CYLINDER: c on the line a-b */
    def.kind = RS_SURF_CYLINDER;
    def.b[0] = 1.0;
    def.c[0] = 2.0;
    ENSURE(arrays_match_text(&def, zero, 2, 0, &e));
    ENSURE(e.code == RS_ERR_GEOMETRY && strstr(e.msg, "<arrays>:3: point c"));
    /* a fillet that does not fit */
    def.c[2] = 1.0;
    def.fillet = 10.0;
    const rs_profile_item corner[] = {{RS_WORD_START, {0.0, 0.0}},
                                      {RS_WORD_LINE, {1.0, 0.0}},
                                      {RS_WORD_LINE, {1.0, 1.0}}};
    ENSURE(arrays_match_text(&def, corner, 3, 0, &e));
    ENSURE(e.code == RS_ERR_GEOMETRY && strstr(e.msg, "FILLET RADIUS=10 does not fit"));
}

/* Values and parameters that keyword text cannot even write: RS_ERR_ARG naming what was
 * expected, the surface left zeroed. */
static void bad_profile_arguments(void)
{
    const rs_profile_item ok[] = {{RS_WORD_START, {1.0, 0.0}}, {RS_WORD_LINE, {1.0, 1.0}}};
    rs_profile_item it[2];
    rs_profile_def def = {0};
    def.kind = RS_SURF_REVOLUTION;
    def.b[2] = 1.0;
    rs_surface s;
    rs_error e;
    ENSURE(rs_surface_make_profile(&def, ok, 2, &s, &e) == RS_OK);
    rs_surface_free(&s);
    ENSURE(rs_surface_make_profile(NULL, ok, 2, &s, &e) == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "NULL definition") && s.ops == NULL);
    ENSURE(rs_surface_make_profile(&def, NULL, 2, &s, &e) == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "found NULL items and nitems = 2"));
    ENSURE(rs_surface_make_profile(&def, ok, -1, &s, &e) == RS_ERR_ARG);
    ENSURE(rs_surface_make_profile(&def, ok, 2, NULL, &e) == RS_ERR_ARG);
    /* coordinates that are not finite or too large, in an item and in a point */
    const double bad[] = {NAN, INFINITY, -INFINITY, 2e100};
    for (int k = 0; k < 4; k++) {
        memcpy(it, ok, sizeof ok);
        it[1].v[k % 2] = bad[k];
        ENSURE(rs_surface_make_profile(&def, it, 2, &s, &e) == RS_ERR_ARG);
        ENSURE(strstr(e.msg, "<arrays>:4: expected a") && strstr(e.msg, "in LINE") &&
               s.ops == NULL);
        rs_profile_def d2 = def;
        d2.a[k % 3] = bad[k];
        ENSURE(rs_surface_make_profile(&d2, ok, 2, &s, &e) == RS_ERR_ARG);
        ENSURE(strstr(e.msg, "<arrays>:2: expected a"));
    }
    /* an unknown word; an unused value is not read */
    memcpy(it, ok, sizeof ok);
    it[1].word = (rs_profile_word)7;
    ENSURE(rs_surface_make_profile(&def, it, 2, &s, &e) == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "<arrays>:4: unknown profile word 7"));
    memcpy(it, ok, sizeof ok);
    it[1].v[3] = NAN;
    ENSURE(rs_surface_make_profile(&def, it, 2, &s, &e) == RS_OK);
    rs_surface_free(&s);
    /* the parameters */
    rs_profile_def d2 = def;
    d2.kind = RS_SURF_FACETED;
    ENSURE(rs_surface_make_profile(&d2, ok, 2, &s, &e) == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "<arrays>:1: unknown kind 4"));
    d2 = def;
    d2.sides = 3;
    ENSURE(rs_surface_make_profile(&d2, ok, 2, &s, &e) == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "SIDES=1 or SIDES=2"));
    d2 = def;
    d2.fillet = -0.1;
    ENSURE(rs_surface_make_profile(&d2, ok, 2, &s, &e) == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "FILLET RADIUS > 0"));
    d2 = def;
    d2.bounded = 1;
    d2.zmax = 1.0;
    ENSURE(rs_surface_make_profile(&d2, ok, 2, &s, &e) == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "EXTENT is only for TYPE=CYLINDER"));
    d2.kind = RS_SURF_CYLINDER;
    d2.b[0] = 1.0;
    d2.c[2] = 1.0;
    d2.zmax = d2.zmin;
    ENSURE(rs_surface_make_profile(&d2, ok, 2, &s, &e) == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "zmin < zmax"));
    d2.zmax = 1.0;
    ENSURE(rs_surface_make_profile(&d2, ok, 2, &s, &e) == RS_OK);
    ENSURE(s.bounded && s.zmax == 1.0);
    rs_surface_free(&s);
    char longname[100];
    memset(longname, 'x', sizeof longname - 1);
    longname[sizeof longname - 1] = '\0';
    d2 = def;
    d2.name = longname;
    ENSURE(rs_surface_make_profile(&d2, ok, 2, &s, &e) == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "1 to 79 characters"));
    d2.name = "tab\there";
    ENSURE(rs_surface_make_profile(&d2, ok, 2, &s, &e) == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "printable"));
}

/* ---- meshes ---------------------------------------------------------------------- */

/* A bumpy open terrain of n x n quads split into triangles (concave and convex folds),
 * normals up, and a closed box on it: two components. */
typedef struct arrays_mesh {
    int nv, nt;
    double xyz[3 * 200];
    int tri[3 * 300];
} arrays_mesh;

static void terrain_and_box(arrays_mesh *m)
{
    const int n = 6;
    m->nv = m->nt = 0;
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= n; i++) {
            double *p = m->xyz + 3 * m->nv++;
            p[0] = i * 0.2;
            p[1] = j * 0.2;
            p[2] = 0.05 * sin(2.1 * i) * cos(1.7 * j);
        }
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            const int t[6] = {a, b, d, a, d, c};
            memcpy(m->tri + 3 * m->nt, t, sizeof t);
            m->nt += 2;
        }
    const int v0 = m->nv;
    for (int k = 0; k < 8; k++) {
        double *p = m->xyz + 3 * m->nv++;
        p[0] = 0.4 + 0.3 * (k & 1);
        p[1] = 0.5 + 0.2 * ((k >> 1) & 1);
        p[2] = 0.2 + 0.25 * ((k >> 2) & 1);
    }
    static const int box[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6},
                                   {0, 1, 4}, {1, 5, 4}, {2, 6, 3}, {3, 6, 7},
                                   {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    for (int t = 0; t < 12; t++)
        for (int k = 0; k < 3; k++)
            m->tri[3 * (m->nt + t) + k] = v0 + box[t][k];
    m->nt += 12;
}

static void write_off(const char *path, const double *xyz, int nv, const int *tri, int nt)
{
    FILE *f = fopen(path, "w");
    fprintf(f, "OFF\n%d %d 0\n", nv, nt);
    for (int v = 0; v < nv; v++)
        fprintf(f, "%.17g %.17g %.17g\n", xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
    for (int t = 0; t < nt; t++)
        fprintf(f, "3 %d %d %d\n", tri[3 * t], tri[3 * t + 1], tri[3 * t + 2]);
    fclose(f);
}

/* The mesh from arrays against the same OFF file named by a surface text, with def's
 * options as the *SURFACE line's. */
static int mesh_matches_file(const double *xyz, int nv, const int *tri, int nt,
                             const rs_mesh_def *def, const char *file, int min)
{
    char path[128], text[1024];
    snprintf(path, sizeof path, "%s/%s", tmpdir, file);
    write_off(path, xyz, nv, tri, nt);
    int u =
        snprintf(text, sizeof text, "*SURFACE, TYPE=MESH, NAME=%s, FILE=%s, SCALE=%.17g",
                 def->name, path, def->scale);
    if (def->sides)
        u += snprintf(text + u, sizeof text - (size_t)u, ", SIDES=%d", def->sides);
    u += snprintf(text + u, sizeof text - (size_t)u, "\n");
    if (def->placed)
        for (int i = 0; i < 9; i++)
            u += snprintf(text + u, sizeof text - (size_t)u, "%.17g%s", def->abc[i],
                          i < 8 ? ", " : "\n");
    rs_surface sa, sf;
    rs_error e;
    if (rs_surface_make_mesh(xyz, nv, tri, nt, def, &sa, &e) != RS_OK) {
        fprintf(stderr, "arrays: %s\n", e.msg);
        return 0;
    }
    if (rs_surface_parse(text, "t", NULL, &sf, &e) != RS_OK) {
        fprintf(stderr, "file: %s\n", e.msg);
        rs_surface_free(&sa);
        return 0;
    }
    int ok = same_answers(&sa, &sf, min) &&
             rs_surface_facet_count(&sa) == rs_surface_facet_count(&sf);
    rs_surface_free(&sa);
    rs_surface_free(&sf);
    return ok;
}

static void mesh_from_arrays_is_the_file(void)
{
    static arrays_mesh m;
    terrain_and_box(&m);
    rs_mesh_def def = RS_MESH_DEF_INIT;
    def.name = "ground";
    ENSURE(mesh_matches_file(m.xyz, m.nv, m.tri, m.nt, &def, "ground.off", 200));
    /* scaled, placed (turned about a tilted axis) and one-sided */
    def.scale = 2.5;
    def.sides = 1;
    def.placed = 1;
    const double abc[9] = {0.3, -0.2, 1.0, 1.1, 0.4, 1.2, -0.5, 0.9, 0.7};
    memcpy(def.abc, abc, sizeof abc);
    ENSURE(mesh_matches_file(m.xyz, m.nv, m.tri, m.nt, &def, "placed.off", 100));
    /* one box face turned over: the orientation check turns it back in both */
    static arrays_mesh f;
    f = m;
    const int t = m.nt - 3, k = f.tri[3 * t + 1];
    f.tri[3 * t + 1] = f.tri[3 * t + 2];
    f.tri[3 * t + 2] = k;
    def = (rs_mesh_def)RS_MESH_DEF_INIT;
    def.name = "flipped";
    ENSURE(mesh_matches_file(f.xyz, f.nv, f.tri, f.nt, &def, "flipped.off", 200));
    rs_surface sa, sb;
    rs_error e;
    ENSURE(rs_surface_make_mesh(m.xyz, m.nv, m.tri, m.nt, &def, &sa, &e) == RS_OK);
    ENSURE(rs_surface_make_mesh(f.xyz, f.nv, f.tri, f.nt, &def, &sb, &e) == RS_OK);
    int same = same_answers(&sa, &sb, 200);
    rs_surface_free(&sb);
    /* the comparison sees the last bit: a scale one ulp above 1 differs */
    def.scale = nextafter(1.0, 2.0);
    ENSURE(rs_surface_make_mesh(m.xyz, m.nv, m.tri, m.nt, &def, &sb, &e) == RS_OK);
    const int apart = !same_answers(&sa, &sb, 200);
    rs_surface_free(&sa);
    rs_surface_free(&sb);
    ENSURE(same && apart);
}

/* A triangle soup (three points of its own per triangle, as in an STL) is welded into
 * the mesh of shared vertices; a degenerate triangle is dropped with the file's warning. */
static void mesh_soup_is_welded(void)
{
    static arrays_mesh m;
    terrain_and_box(&m);
    static double soup[3 * 3 * 300];
    static int idx[3 * 301];
    for (int k = 0; k < 3 * m.nt; k++) {
        memcpy(soup + 3 * k, m.xyz + 3 * m.tri[k], 3 * sizeof(double));
        idx[k] = k;
    }
    /* a degenerate triangle at the end: three points on a line */
    const int nt = m.nt + 1;
    idx[3 * m.nt] = 0;
    idx[3 * m.nt + 1] = 1;
    idx[3 * m.nt + 2] = 1;
    rs_mesh_def def = RS_MESH_DEF_INIT;
    def.name = "soup";
    def.origin = "terrain";
    rs_surface sw, ss;
    rs_error e;
    ENSURE(rs_surface_make_mesh(m.xyz, m.nv, m.tri, m.nt, &def, &sw, &e) == RS_OK);
    ENSURE(sw.warning[0] == '\0' || strstr(sw.warning, "open boundary"));
    ENSURE(rs_surface_make_mesh(soup, 3 * m.nt, idx, nt, &def, &ss, &e) == RS_OK);
    char want[80];
    snprintf(want, sizeof want, "terrain: dropped 1 degenerate facet (facet %d)", nt);
    ENSURE(strstr(ss.warning, want));
    int nnode = 0;
    rs_surface_facet_size(&ss, &nnode);
    const int same =
        same_answers(&sw, &ss, 200) && nnode == m.nv && rs_surface_facet_count(&ss) == m.nt;
    rs_surface_free(&sw);
    rs_surface_free(&ss);
    ENSURE(same);
    ENSURE(mesh_matches_file(soup, 3 * m.nt, idx, nt, &def, "soup.off", 200));
}

/* A CAD mesh acts on both sides unless asked; an analytic profile on one. */
static void default_sides(void)
{
    const double xyz[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const int tri[] = {0, 1, 2};
    rs_surface s;
    rs_error e;
    ENSURE(rs_surface_make_mesh(xyz, 3, tri, 1, NULL, &s, &e) == RS_OK);
    ENSURE(s.sides == 2 && s.kind == RS_SURF_FACETED && s.name[0] == '\0');
    /* a sphere below the one-sided triangle has no contact; two-sided it has */
    const double x = 0.2, y = 0.2, z = -0.3, r = 0.35;
    rs_query q = {.n = 1,
                  .slave = {.x = &x, .y = &y, .z = &z, .radius = &r},
                  .pose = NULL,
                  .gap_max = 0.0,
                  .dist_min = -r};
    rs_contacts c;
    memset(&c, 0, sizeof c);
    ENSURE(rs_surface_query(&s, &q, &c, &e) == RS_OK && c.n == 1);
    ENSURE_NEAR(c.dist[0], 0.3, 1e-15);
    ENSURE_NEAR(c.nrm[2][0], -1.0, 1e-15);
    rs_surface_free(&s);
    rs_mesh_def def = RS_MESH_DEF_INIT;
    def.sides = 1;
    ENSURE(rs_surface_make_mesh(xyz, 3, tri, 1, &def, &s, &e) == RS_OK && s.sides == 1);
    c.n = 0;
    ENSURE(rs_surface_query(&s, &q, &c, &e) == RS_OK);
    ENSURE(c.n == 0 || c.dist[0] < 0.0); /* behind the one side: a penetration */
    rs_surface_free(&s);
    rs_contacts_free(&c);
}

static void bad_mesh_arguments(void)
{
    const double xyz[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    const int tri[] = {0, 1, 2, 1, 3, 2};
    rs_surface s;
    rs_error e;
    ENSURE(rs_surface_make_mesh(xyz, 4, tri, 2, NULL, &s, &e) == RS_OK);
    rs_surface_free(&s);
    ENSURE(rs_surface_make_mesh(NULL, 4, tri, 2, NULL, &s, &e) == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "<arrays>: NULL vertex array (expected 3 nv coordinates"));
    ENSURE(s.ops == NULL);
    ENSURE(rs_surface_make_mesh(xyz, 4, NULL, 2, NULL, &s, &e) == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "NULL triangle array"));
    ENSURE(rs_surface_make_mesh(xyz, 2, tri, 2, NULL, &s, &e) == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "nv = 2 vertices (expected at least 3)"));
    ENSURE(rs_surface_make_mesh(xyz, 0, tri, 2, NULL, &s, &e) == RS_ERR_ARG);
    ENSURE(rs_surface_make_mesh(xyz, 4, tri, 0, NULL, &s, &e) == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "nt = 0 triangles (expected 1 to"));
    ENSURE(rs_surface_make_mesh(xyz, 4, tri, -3, NULL, &s, &e) == RS_ERR_ARG);
    ENSURE(rs_surface_make_mesh(xyz, 4, tri, 2, NULL, NULL, &e) == RS_ERR_ARG);
    /* indices out of range, either end */
    int bad[6];
    memcpy(bad, tri, sizeof tri);
    bad[4] = 4;
    ENSURE(rs_surface_make_mesh(xyz, 4, bad, 2, NULL, &s, &e) == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "triangle 2 has vertex index 4 (expected 0 to 3"));
    bad[4] = -1;
    ENSURE(rs_surface_make_mesh(xyz, 4, bad, 2, NULL, &s, &e) == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "vertex index -1"));
    /* coordinates that are not finite, or too large once scaled: the file's check */
    double c[12];
    const double nonfinite[] = {NAN, INFINITY, 2e100};
    for (int k = 0; k < 3; k++) {
        memcpy(c, xyz, sizeof xyz);
        c[7] = nonfinite[k];
        ENSURE(rs_surface_make_mesh(c, 4, tri, 2, NULL, &s, &e) == RS_ERR_GEOMETRY);
        ENSURE(strstr(e.msg, "<arrays>: point 3 has coordinate") &&
               strstr(e.msg, "expected finite coordinates"));
    }
    rs_mesh_def def = RS_MESH_DEF_INIT;
    def.scale = 1e99;
    memcpy(c, xyz, sizeof xyz);
    c[0] = 20.0;
    ENSURE(rs_surface_make_mesh(c, 4, tri, 2, &def, &s, &e) == RS_ERR_GEOMETRY);
    /* every triangle degenerate */
    const double line[] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0};
    ENSURE(rs_surface_make_mesh(line, 4, tri, 2, NULL, &s, &e) == RS_ERR_GEOMETRY);
    ENSURE(strstr(e.msg, "every facet is degenerate"));
    /* the parameters */
    def = (rs_mesh_def)RS_MESH_DEF_INIT;
    def.origin = "floor";
    def.scale = 0.0;
    ENSURE(rs_surface_make_mesh(xyz, 4, tri, 2, &def, &s, &e) == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "floor: scale = 0 (expected SCALE > 0"));
    def.scale = NAN;
    ENSURE(rs_surface_make_mesh(xyz, 4, tri, 2, &def, &s, &e) == RS_ERR_ARG);
    def.scale = 1.0;
    def.sides = -1;
    ENSURE(rs_surface_make_mesh(xyz, 4, tri, 2, &def, &s, &e) == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "SIDES=1 or SIDES=2"));
    def.sides = 0;
    def.placed = 1; /* a = b = c = 0 */
    ENSURE(rs_surface_make_mesh(xyz, 4, tri, 2, &def, &s, &e) == RS_ERR_GEOMETRY);
    ENSURE(strstr(e.msg, "floor: points a and b coincide"));
    def.abc[3] = 1.0;
    def.abc[6] = 2.0; /* c on the line a-b */
    ENSURE(rs_surface_make_mesh(xyz, 4, tri, 2, &def, &s, &e) == RS_ERR_GEOMETRY);
    ENSURE(strstr(e.msg, "point c coincides with a or lies on the line a-b"));
    def.abc[7] = INFINITY;
    ENSURE(rs_surface_make_mesh(xyz, 4, tri, 2, &def, &s, &e) == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "placement abc[7] = inf"));
    def = (rs_mesh_def)RS_MESH_DEF_INIT;
    char longname[100];
    memset(longname, 'x', sizeof longname - 1);
    longname[sizeof longname - 1] = '\0';
    def.name = longname;
    ENSURE(rs_surface_make_mesh(xyz, 4, tri, 2, &def, &s, &e) == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "1 to 79 characters") && s.ops == NULL);
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/rs_test_arrays_XXXXXX");
    if (!mkdtemp(tmpdir))
        return 1;
    RS_RUN(hopper_from_arrays_is_the_file);
    RS_RUN(segments_from_arrays_are_the_text);
    RS_RUN(cylinder_from_arrays_is_the_text);
    RS_RUN(revolution_from_arrays_is_the_text);
    RS_RUN(bad_profiles_give_the_readers_messages);
    RS_RUN(bad_profile_arguments);
    RS_RUN(mesh_from_arrays_is_the_file);
    RS_RUN(mesh_soup_is_welded);
    RS_RUN(default_sides);
    RS_RUN(bad_mesh_arguments);
    const char *files[] = {"ground.off", "placed.off", "flipped.off", "soup.off"};
    for (int k = 0; k < 4; k++) {
        char path[128];
        snprintf(path, sizeof path, "%s/%s", tmpdir, files[k]);
        remove(path);
    }
    rmdir(tmpdir);
    return rs_test_summary();
}
