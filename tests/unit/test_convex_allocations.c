/* The convex geometry's use of the heap, counted by the link (tests/CMakeLists.txt wraps
 * malloc, calloc, realloc, free and C++'s operator new and delete of this program):
 * - a body's contacts with a MESH ask the heap nothing for a few candidate triangles;
 * - a hull whose allocations fail, each in turn, answers RS_ERR_NOMEM without arrays
 *   and gives back every block from its first C allocation on (its output arrays too,
 *   when a vector throws after them); once none fails it is the hull of the run
 *   that never failed. Under the sanitizers, whose allocators answer an impossible
 *   request by stopping the program, C++'s allocations are not made to fail. */
#include "rigidsurf/convex.h"
#include "rs_test.h"

#include <stddef.h>
#include <stdint.h>

static long n_alloc, n_free; /* calls while counting */
static int counting;
static long n_c, n_new;                 /* C allocations (malloc, calloc), C++ ones (new) */
static long fail_c = -1, fail_new = -1; /* the one of each kind (from 0) that fails */
static long first_c = -1;               /* n_alloc at the call's first C allocation */

void *__real_malloc(size_t n);
void *__real_calloc(size_t k, size_t n);
void *__real_realloc(void *p, size_t n);
void __real_free(void *p);
void *__real__Znwm(size_t n);
void __real__ZdlPv(void *p);
void __real__ZdlPvm(void *p, size_t n);
void *__wrap_malloc(size_t n);
void *__wrap_calloc(size_t k, size_t n);
void *__wrap_realloc(void *p, size_t n);
void __wrap_free(void *p);
void *__wrap__Znwm(size_t n);
void __wrap__ZdlPv(void *p);
void __wrap__ZdlPvm(void *p, size_t n);

/* Counts a C allocation; whether it is to fail. */
static int c_fails(void)
{
    if (!counting)
        return 0;
    if (first_c < 0)
        first_c = n_alloc;
    n_alloc++;
    return n_c++ == fail_c;
}

void *__wrap_malloc(size_t n)
{
    return c_fails() ? NULL : __real_malloc(n);
}
void *__wrap_calloc(size_t k, size_t n)
{
    return c_fails() ? NULL : __real_calloc(k, n);
}
void *__wrap_realloc(void *p, size_t n)
{
    if (!p)
        return c_fails() ? NULL : __real_realloc(p, n);
    return __real_realloc(p, n); /* a block that grows is not a new one */
}
void __wrap_free(void *p)
{
    n_free += counting && p;
    __real_free(p);
}

#if defined(__SANITIZE_ADDRESS__)
#define RS_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RS_SANITIZED 1
#endif
#endif
#ifndef RS_SANITIZED
#define RS_SANITIZED 0
#endif

/* operator new fails as it does when memory runs out: the real one asked for more than
 * any machine has throws std::bad_alloc */
void *__wrap__Znwm(size_t n)
{
    if (counting) {
        n_alloc++;
        if (n_new++ == fail_new)
            return __real__Znwm(SIZE_MAX / 2);
    }
    return __real__Znwm(n);
}
void __wrap__ZdlPv(void *p)
{
    n_free += counting && p;
    __real__ZdlPv(p);
}
void __wrap__ZdlPvm(void *p, size_t n)
{
    n_free += counting && p;
    __real__ZdlPvm(p, n);
}

static void test_a_body_on_a_mesh_asks_the_heap_nothing(void)
{
    const double xyz[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
    const int tri[6] = {0, 1, 2, 0, 2, 3};
    const rs_mesh_def def = RS_MESH_DEF_INIT;
    rs_surface s;
    ENSURE(rs_surface_make_mesh(xyz, 4, tri, 2, &def, &s, NULL) == RS_OK);
    rs_shape box;
    ENSURE(rs_shape_make_box(&box, 0.05, 0.04, 0.02, 0.0, NULL) == RS_OK);
    const double x[3] = {0.01, 0.02, 0.0199}, q[4] = {1, 0, 0, 0};
    rs_body b;
    ENSURE(rs_body_init(&b, &box, 1000.0, x, q, NULL) == RS_OK);
    rs_body_contact c[8];
    int n = 0;
    n_alloc = n_free = n_c = n_new = 0;
    counting = 1;
    const int rc = rs_body_surface_contacts(&s, NULL, &b, 1e-3, c, 8, &n, NULL);
    counting = 0;
    ENSURE(rc == RS_OK && n == 1);
    ENSURE(n_alloc == 0 && n_free == 0);
    rs_surface_free(&s);
}

/* Random points on a sphere of radius 1 (a fixed sequence). */
static void sphere_points(double *xyz, int n)
{
    unsigned long long seed = 5;
    for (int i = 0; i < n; i++) {
        double d[3], l;
        do {
            for (int k = 0; k < 3; k++)
                d[k] = 2.0 * (double)(rs_test_xorshift(&seed) >> 11) / 9007199254740992.0 -
                       1.0;
            l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        } while (l > 1.0 || l < 1e-3);
        for (int k = 0; k < 3; k++)
            xyz[3 * i + k] = d[k] / l;
    }
}

/* Makes the hull of xyz with allocation number fail of a kind (C or C++) failing: 1 when
 * it succeeded (the allocation was past the last), 0 when it failed as it should (out of
 * memory, no arrays, and every block given back from the first C allocation on: those
 * are the hull's own; CGAL's containers may keep a block when one of their own
 * allocations throws), -1 otherwise. */
static int hull_failing(const double *xyz, int n, int cxx, long fail, const rs_shape *ref)
{
    rs_shape s;
    rs_error e;
    n_alloc = n_free = n_c = n_new = 0;
    first_c = -1;
    fail_c = cxx ? -1 : fail;
    fail_new = cxx ? fail : -1;
    counting = 1;
    const int rc = rs_shape_make_polyhedron(&s, xyz, n, 0.0, &e);
    counting = 0;
    fail_c = fail_new = -1;
    if (rc == RS_OK) {
        const int same = s.nv == ref->nv && s.nt == ref->nt &&
                         !memcmp(s.verts, ref->verts, 3 * (size_t)s.nv * sizeof *s.verts) &&
                         !memcmp(s.tris, ref->tris, 3 * (size_t)s.nt * sizeof *s.tris);
        rs_shape_free(&s);
        return same && fail >= (cxx ? n_new : n_c) ? 1 : -1;
    }
    const int ours = first_c >= 0 && (cxx ? first_c < n_alloc - 1 : 1);
    const int ok = rc == RS_ERR_NOMEM && strstr(e.msg, "memory") && !s.verts && !s.tris &&
                   (!ours || n_alloc - 1 == n_free);
    if (!ok)
        fprintf(stderr, "%s allocation %ld: code %d, %ld allocated, %ld given back\n",
                cxx ? "C++" : "C", fail, rc, n_alloc, n_free);
    return ok ? 0 : -1;
}

static void test_a_hull_out_of_memory_leaks_nothing(void)
{
    enum { N = 200 };
    static double xyz[3 * N];
    sphere_points(xyz, N);
    rs_shape ref;
    ENSURE(rs_shape_make_polyhedron(&ref, xyz, N, 0.0, NULL) == RS_OK);
    int failed[2] = {0, 0}, r;
    for (long k = 0; (r = hull_failing(xyz, N, 0, k, &ref)) == 0; k++)
        failed[0]++;
    ENSURE(r == 1);
    ENSURE(failed[0] >= 3); /* the vertices, the triangles, the moments' arrays */
    for (long k = 0; !RS_SANITIZED && (r = hull_failing(xyz, N, 1, k, &ref)) == 0; k++)
        failed[1]++;
    ENSURE(r == 1);
    ENSURE(RS_SANITIZED || failed[1] > 100);
    rs_shape_free(&ref);
}

int main(void)
{
    RS_RUN(test_a_body_on_a_mesh_asks_the_heap_nothing);
    RS_RUN(test_a_hull_out_of_memory_leaks_nothing);
    return rs_test_summary();
}
