/* MESH surfaces (src/faceted/): the errors for bad files, each naming the file and what
 * is wrong; the repairs a mesh reports; an Abaqus rigid part; the facets under contacts. */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */
#include "mesh_fixture.h"

/* Bad files: each error names the file and what is wrong. */
static void expect_error(const char *file, const char *content, size_t len, const char *inp,
                         const char *want)
{
    char path[160];
    if (file) {
        snprintf(path, sizeof path, "%s/%s", tmpdir, file);
        FILE *f = fopen(path, "wb");
        if (len)
            fwrite(content, 1, len, f);
        fclose(f);
    }
    rs_surface s;
    rs_error e;
    const int rc = load(inp, &s, &e);
    if (rc == RS_OK || !strstr(e.msg, want)) {
        fprintf(stderr, "expected an error with '%s', got %d: %s\n", want, rc, e.msg);
        rs_test_current_failed = 1;
        if (rc == RS_OK)
            rs_surface_free(&s);
    }
}

static void bad_mesh_files(void)
{
    expect_error("empty.stl", "", 0, "*SURFACE, TYPE=MESH, NAME=a, FILE=empty.stl\n",
                 "empty.stl is empty");
    const char *broken = "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n"
                         "   vertex 1 0\n";
    expect_error("broken.stl", broken, strlen(broken),
                 "*SURFACE, TYPE=MESH, NAME=a, FILE=broken.stl\n", "broken.stl");
    /* a binary STL announcing 10 facets that holds 1 */
    char bin[84 + 50];
    memset(bin, 0, sizeof bin);
    bin[80] = 10;
    expect_error("trunc.stl", bin, sizeof bin,
                 "*SURFACE, TYPE=MESH, NAME=a, FILE=trunc.stl\n", "trunc.stl");
    const char *nanoff = "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n";
    expect_error("nan.off", nanoff, strlen(nanoff),
                 "*SURFACE, TYPE=MESH, NAME=a, FILE=nan.off\n", "nan.off");
    expect_error(NULL, NULL, 0, "*SURFACE, TYPE=MESH, NAME=a, FILE=missing.stl\n",
                 "missing.stl");
    expect_error(NULL, NULL, 0, "*SURFACE, TYPE=MESH, NAME=a, FILE=.\n", "directory");
    const char *tri = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    expect_error("tri.off", tri, strlen(tri),
                 "*SURFACE, TYPE=MESH, NAME=a, FILE=tri.off, SCALE=-1\n", "SCALE > 0");
    expect_error(NULL, NULL, 0, "*SURFACE, TYPE=MESH, NAME=a, FILE=tri.off, SCALE=nan\n",
                 "s.inp:1");
    /* without FILE=, the surface file's own rigid part, here none */
    expect_error(NULL, NULL, 0, "*SURFACE, TYPE=MESH, NAME=a\n", "expected a rigid part");
    { /* text that is no file has no rigid part: FILE= is needed */
        rs_surface s;
        rs_error e;
        ENSURE(rs_surface_parse("*SURFACE, TYPE=MESH, NAME=a\n", "text", NULL, &s, &e) ==
               RS_ERR_PARSE);
        ENSURE(strstr(e.msg, "expected FILE=") != NULL);
    }
    expect_error("tri.xyz", tri, strlen(tri), "*SURFACE, TYPE=MESH, NAME=a, FILE=tri.xyz\n",
                 "unknown mesh format");
    const char *flat = "OFF\n3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n";
    expect_error("flat.off", flat, strlen(flat),
                 "*SURFACE, TYPE=MESH, NAME=a, FILE=flat.off\n",
                 "every facet is degenerate");
    expect_error(NULL, NULL, 0, "*SURFACE, TYPE=MESH, NAME=a, FILE=tri.off\n1, 2, 3\n",
                 "placement");
}

/* An Abaqus rigid part: a unit cube of R3D4 elements whose nodes (numbered from 101)
 * come from an included file answers as the same cube read from OFF; an element naming
 * a missing node, another element type and a node defined twice are errors that name
 * file and line. */
static void abaqus_rigid_part(void)
{
    write_text("cube_nodes.inp",
               "** the nodes\n*NODE, NSET=all\n101, 0, 0, 0\n102, 1, 0, 0\n"
               "103, 1, 1, 0\n104, 0, 1, 0\n105, 0, 0, 1\n106, 1, 0, 1\n"
               "107, 1, 1, 1\n108, 0, 1, 1\n");
    write_text("cube.inp", "*HEADING\nrigid cube\n*INCLUDE, INPUT=cube_nodes.inp\n"
                           "*element, type=r3d4, elset=box\n1, 101, 104, 103, 102\n"
                           "2, 105, 106, 107, 108\n3, 101, 102, 106, 105\n"
                           "4, 103, 104, 108, 107\n5, 102, 103, 107, 106\n"
                           "6, 101, 105, 108, 104\n");
    rs_surface s;
    rs_error e;
    ENSURE(load("*SURFACE, TYPE=MESH, NAME=cube, FILE=cube.inp\n", &s, &e) == RS_OK);
    ENSURE(s.warning[0] == '\0'); /* closed and consistently wound */
    rs_contacts c;
    memset(&c, 0, sizeof c);
    double x = 1.1, y = 0.4, z = 1.2;
    query(&s, 1, &x, &y, &z, NULL, 1.0, &c);
    ENSURE(c.n == 1 && RS_FEATURE_TYPE(c.feature[0]) == RS_FEAT_EDGE);
    ENSURE_NEAR(c.dist[0], hypot(0.1, 0.2), 1e-15);
    x = 0.3, y = 0.6, z = 1.05;
    query(&s, 1, &x, &y, &z, NULL, 1.0, &c);
    ENSURE(c.n == 1 && c.feature[0] == RS_FEATURE(RS_FEAT_FACE, 1)); /* element 2 */
    ENSURE_NEAR(c.dist[0], 0.05, 1e-15);
    /* its facet: the part's node labels, and the unit square's bilinear shape functions
     * (1-x)(1-y), x(1-y), xy, (1-x)y at (0.3, 0.6) */
    {
        const double xm[3] = {c.xm[0][0], c.xm[1][0], c.xm[2][0]};
        int nodes[4];
        double xyz[12], sh[4];
        ENSURE(rs_surface_facet(&s, c.feature[0], xm, nodes, xyz, sh) == 4);
        ENSURE(nodes[0] == 105 && nodes[1] == 106 && nodes[2] == 107 && nodes[3] == 108);
        const double want[4] = {0.7 * 0.4, 0.3 * 0.4, 0.3 * 0.6, 0.7 * 0.6};
        for (int i = 0; i < 4; i++)
            ENSURE_NEAR(sh[i], want[i], 1e-15);
        ENSURE(xyz[3 * 2] == 1.0 && xyz[3 * 2 + 1] == 1.0 && xyz[3 * 2 + 2] == 1.0);
        /* six unit quads with outward axis normals; the contact's facet is element 2 */
        ENSURE(rs_surface_facet_count(&s) == 6);
        ENSURE(rs_surface_facet_index(&s, c.feature[0]) == 1);
        for (int k = 0; k < 6; k++) {
            double a, n[3];
            ENSURE(rs_surface_facet_area(&s, k, &a, n) == 0);
            ENSURE_NEAR(a, 1.0, 1e-15);
            ENSURE_NEAR(fabs(n[0]) + fabs(n[1]) + fabs(n[2]), 1.0, 1e-15);
        }
        double a, n[3];
        ENSURE(rs_surface_facet_area(&s, 1, &a, n) == 0 && n[2] == 1.0); /* the top */
        ENSURE(rs_surface_facet_area(&s, 6, &a, n) == -1);
        /* the display's triangles show their quads: each element twice */
        rs_trimesh tm;
        ENSURE(rs_surface_triangulate(&s, 1.0, 1, &tm, &e) == RS_OK);
        int seen[6] = {0, 0, 0, 0, 0, 0};
        ENSURE(tm.ntri == 12 && tm.cell != NULL);
        for (int t = 0; t < tm.ntri; t++)
            if (tm.cell[t] >= 0 && tm.cell[t] < 6)
                seen[tm.cell[t]]++;
        for (int k = 0; k < 6; k++)
            ENSURE(seen[k] == 2);
        rs_trimesh_free(&tm);
    }
    rs_contacts_free(&c);
    rs_surface_free(&s);
    /* the rigid part in the surface file itself, after its *SURFACE */
    ENSURE(load("*SURFACE, TYPE=MESH, NAME=plate, SIDES=2\n*NODE\n1, 0, 0, 0\n2, 2, 0, 0\n"
                "3, 2, 2, 0\n4, 0, 2, 0\n*ELEMENT, TYPE=R3D4, ELSET=plate\n1, 1, 2, 3, 4\n",
                &s, &e) == RS_OK);
    memset(&c, 0, sizeof c);
    x = 1.5, y = 0.5, z = -0.25;
    query(&s, 1, &x, &y, &z, NULL, 1.0, &c);
    ENSURE(c.n == 1 && c.feature[0] == RS_FEATURE(RS_FEAT_FACE, 0));
    ENSURE_NEAR(c.dist[0], 0.25, 1e-15);
    ENSURE_NEAR(c.nrm[2][0], -1.0, 1e-15);
    rs_contacts_free(&c);
    rs_surface_free(&s);
    write_text("miss.inp", "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 0\n"
                           "*ELEMENT, TYPE=R3D4\n7, 1, 2, 3, 999\n");
    ENSURE(load("*SURFACE, TYPE=MESH, NAME=m, FILE=miss.inp\n", &s, &e) != RS_OK);
    ENSURE(strstr(e.msg, "miss.inp:6: element 7 names node 999") != NULL);
    write_text("solid.inp", "*NODE\n1, 0, 0, 0\n*ELEMENT, TYPE=C3D8\n");
    ENSURE(load("*SURFACE, TYPE=MESH, NAME=m, FILE=solid.inp\n", &s, &e) != RS_OK);
    ENSURE(strstr(e.msg, "solid.inp:3:") && strstr(e.msg, "TYPE=C3D8"));
    write_text("twice.inp", "*NODE\n1, 0, 0, 0\n1, 1, 0, 0\n2, 0, 1, 0\n"
                            "*ELEMENT, TYPE=R3D3\n1, 1, 2, 1\n");
    ENSURE(load("*SURFACE, TYPE=MESH, NAME=m, FILE=twice.inp\n", &s, &e) != RS_OK);
    ENSURE(strstr(e.msg, "node 1 defined twice") != NULL);
}

/* Repairs are reported: a degenerate facet is dropped by its number, the open edges of a
 * sheet are counted (as information: tests/unit/test_mesh_boundary.c), and a surface
 * without a consistent orientation acts on both sides. */
static void repairs_are_reported(void)
{
    const char *txt = "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n2 0 0\n1 1 0\n"
                      "3 0 1 2\n3 0 1 3\n3 1 4 2\n";
    write_text("rep.off", txt);
    rs_surface s;
    rs_error e;
    ENSURE(load("*SURFACE, TYPE=MESH, NAME=r, FILE=rep.off\n", &s, &e) == RS_OK);
    ENSURE(strstr(s.warning, "dropped 1 degenerate facet (facet 2)") != NULL);
    ENSURE(strstr(s.info, "4 open boundary edges") != NULL);
    rs_surface_free(&s);
    /* a Moebius band: eight quads around a circle, the last joined with a half twist */
    char path[128];
    snprintf(path, sizeof path, "%s/mob.off", tmpdir);
    FILE *f = fopen(path, "w");
    fprintf(f, "OFF\n16 16 0\n");
    for (int i = 0; i < 8; i++)
        for (int k = 0; k < 2; k++) {
            const double u = 2 * RS_PI * i / 8, w = k ? 0.3 : -0.3;
            fprintf(f, "%.17g %.17g %.17g\n", (1 + w * cos(u / 2)) * cos(u),
                    (1 + w * cos(u / 2)) * sin(u), w * sin(u / 2));
        }
    for (int i = 0; i < 8; i++) {
        const int a = 2 * i, b = 2 * i + 1;
        const int c = i < 7 ? 2 * (i + 1) : 1, d = i < 7 ? 2 * (i + 1) + 1 : 0;
        fprintf(f, "3 %d %d %d\n3 %d %d %d\n", a, c, d, a, d, b);
    }
    fclose(f);
    ENSURE(load("*SURFACE, TYPE=MESH, NAME=m, FILE=mob.off\n", &s, &e) == RS_OK);
    ENSURE(s.sides == 2 && strstr(s.warning, "no consistent orientation") != NULL);
    rs_surface_free(&s);
}

/* The facet under each contact (rs_surface_facet): its nodes interpolated with the
 * shape functions give the contact's closest point, the shapes sum to 1 and are not
 * negative, a face's nodes lie in its tangent plane, an edge's facet has two nodes with
 * weight and a vertex's one, at the closest point. Quads (the torus) have 4 nodes,
 * triangles (the rounded box) 3. */
static int facet_case(poly_mesh *pm, const char *name, int want_nn, int nodes_in_file)
{
    rs_surface s;
    if (load_pm(pm, name, &s) != RS_OK)
        return 0;
    int nnode = -1, ok = 1;
    ok &= rs_surface_facet_size(&s, &nnode) == want_nn;
    ok &= nnode == nodes_in_file;
    enum { NP = 400 };
    double x[NP], y[NP], z[NP], r[NP];
    for (int i = 0; i < NP; i++) {
        x[i] = 2.6 * (2 * urand() - 1);
        y[i] = 2.6 * (2 * urand() - 1);
        z[i] = 1.6 * (2 * urand() - 1);
        r[i] = 0.05;
    }
    rs_contacts c;
    rs_error e;
    memset(&c, 0, sizeof c);
    rs_contacts_reserve(&c, 64, &e);
    query(&s, NP, x, y, z, r, 0.4, &c);
    int counted[3] = {0, 0, 0};
    for (int k = 0; k < c.n && ok; k++) {
        const double xm[3] = {c.xm[0][k], c.xm[1][k], c.xm[2][k]};
        const double n[3] = {c.nrm[0][k], c.nrm[1][k], c.nrm[2][k]};
        int nodes[4];
        double xyz[12], sh[4];
        const int nn = rs_surface_facet(&s, c.feature[k], xm, nodes, xyz, sh);
        const int type = RS_FEATURE_TYPE(c.feature[k]);
        counted[type]++;
        if (nn != want_nn) {
            fprintf(stderr, "%s: contact %d: %d nodes\n", name, k, nn);
            ok = 0;
            break;
        }
        double sum = 0.0, p[3] = {0, 0, 0};
        int weighted = 0;
        for (int i = 0; i < nn; i++) {
            ok &= nodes[i] >= 1 && nodes[i] <= nnode;
            ok &= sh[i] >= -1e-12;
            sum += sh[i];
            weighted += sh[i] > 1e-12;
            for (int d = 0; d < 3; d++)
                p[d] += sh[i] * xyz[3 * i + d];
            if (type == RS_FEAT_FACE) {
                const double off = (xyz[3 * i] - xm[0]) * n[0] +
                                   (xyz[3 * i + 1] - xm[1]) * n[1] +
                                   (xyz[3 * i + 2] - xm[2]) * n[2];
                ok &= fabs(off) < 1e-12;
            }
        }
        ok &= fabs(sum - 1.0) < 1e-12;
        ok &= dist3(p, xm) < 1e-12;
        if (type == RS_FEAT_EDGE)
            ok &= weighted <= 2;
        if (type == RS_FEAT_VERTEX)
            ok &= weighted == 1;
        if (!ok)
            fprintf(stderr,
                    "%s: contact %d (type %d): sum %.17g, |N x - xm| %.3g, %d weighted\n",
                    name, k, type, sum, dist3(p, xm), weighted);
    }
    /* every kind of feature was met */
    ok &= counted[0] > 0 && counted[1] > 0 && counted[2] > 0;
    if (!ok)
        fprintf(stderr, "%s: faces %d, edges %d, vertices %d\n", name, counted[0],
                counted[1], counted[2]);
    rs_contacts_free(&c);
    rs_surface_free(&s);
    return ok;
}

static void facets_under_contacts(void)
{
    poly_mesh m;
    torus(&m, 32, 16, 1.0, 0.3);
    ENSURE(facet_case(&m, "ftorus", 4, 32 * 16));
    rounded_box(&m, 8, 0.3);
    const int shared =
        6 * 9 * 9 - 12 * 9 + 8; /* the faces' grids share edges and corners */
    ENSURE(facet_case(&m, "fbox", 3, shared));
    /* the analytic kinds have no facets */
    rs_surface s;
    rs_error e;
    ENSURE(load("*SURFACE, TYPE=CYLINDER, NAME=p\n0, 0, 0, 1, 0, 0\n0, -1, 0\n"
                "START, -1, 0\nLINE, 1, 0\n",
                &s, &e) == RS_OK);
    int nodes[4];
    double xyz[12], sh[4], xm[3] = {0, 0, 0};
    ENSURE(rs_surface_facet_size(&s, NULL) == 0);
    ENSURE(rs_surface_facet(&s, RS_FEATURE(RS_FEAT_FACE, 0), xm, nodes, xyz, sh) == 0);
    ENSURE(rs_surface_facet_count(&s) == 0);
    ENSURE(rs_surface_facet_index(&s, RS_FEATURE(RS_FEAT_FACE, 0)) == -1);
    rs_surface_free(&s);
}

int main(void)
{
    if (!mesh_fixture_begin("mesh_files"))
        return 1;
    RS_RUN(bad_mesh_files);
    RS_RUN(repairs_are_reported);
    RS_RUN(abaqus_rigid_part);
    RS_RUN(facets_under_contacts);
    if (!mesh_fixture_end())
        return 1;
    return rs_test_summary();
}
