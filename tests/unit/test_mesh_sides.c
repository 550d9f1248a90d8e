/* Which side a surface acts on when SIDES= is not given (docs/conventions.md, "Profiles
 * and surfaces"): a MESH from STL, OBJ, OFF or PLY acts on both sides, as LIGGGHTS's mesh
 * walls do; an Abaqus rigid part (an .inp file, or the part in the surface file itself)
 * and every profile kind act on one side; SIDES=1 and SIDES=2 always win. */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */

#include "rigidsurf/surface.h"
#include "rs_test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static char tmpdir[64];

static void write_text(const char *name, const char *text)
{
    char path[160];
    snprintf(path, sizeof path, "%s/%s", tmpdir, name);
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
}

/* The surface of text (written as s.inp in tmpdir), read; its sides, or -1 on error. */
static int sides_of(const char *text, rs_surface *s)
{
    char path[160];
    write_text("s.inp", text);
    snprintf(path, sizeof path, "%s/s.inp", tmpdir);
    rs_error e;
    if (rs_surface_read(path, NULL, s, &e) != RS_OK) {
        fprintf(stderr, "%s\n", e.msg);
        return -1;
    }
    return s->sides;
}

/* The unit square z = 0, wound so that its normal is +z, in four formats. */
static void write_plates(void)
{
    write_text("plate.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
    write_text("plate.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
    write_text("plate.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
                            "property float y\nproperty float z\nelement face 1\n"
                            "property list uchar int vertex_indices\nend_header\n"
                            "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
    write_text("plate.stl", "solid p\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                            "vertex 1 0 0\nvertex 1 1 0\nendloop\nendfacet\n"
                            "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 1 0\n"
                            "vertex 0 1 0\nendloop\nendfacet\nendsolid p\n");
    write_text("plate_part.inp", "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 0\n4, 0, 1, 0\n"
                                 "*ELEMENT, TYPE=R3D4\n1, 1, 2, 3, 4\n");
}

/* The contacts of a sphere of radius 0.1 at (0.5, 0.5, z) within a gap of 0.5. */
static int contacts_at(const rs_surface *s, double z, rs_contacts *c)
{
    double x = 0.5, y = 0.5, r = 0.1;
    rs_query q;
    memset(&q, 0, sizeof q);
    q.n = 1;
    q.slave.x = &x;
    q.slave.y = &y;
    q.slave.z = &z;
    q.slave.radius = &r;
    q.gap_max = 0.5;
    q.dist_min = 0.0;
    c->n = 0;
    rs_error e;
    if (rs_surface_query(s, &q, c, &e) != RS_OK) {
        fprintf(stderr, "query: %s\n", e.msg);
        return -1;
    }
    return c->n;
}

/* STL, OBJ, OFF and PLY meshes act on both sides by default: a sphere below the plate
 * (behind its winding) has one contact, at the same distance as one above, with its
 * normal toward it. */
static void mesh_sides_default_both_for_cad_files(void)
{
    const char *files[] = {"plate.stl", "plate.obj", "plate.off", "plate.ply"};
    for (int k = 0; k < 4; k++) {
        char text[160];
        snprintf(text, sizeof text, "*SURFACE, TYPE=MESH, NAME=p, FILE=%s\n", files[k]);
        rs_surface s;
        ENSURE(sides_of(text, &s) == 2);
        rs_contacts c;
        memset(&c, 0, sizeof c);
        ENSURE(contacts_at(&s, -0.3, &c) == 1);
        ENSURE_NEAR(c.dist[0], 0.3, 1e-12);
        ENSURE_NEAR(c.nrm[2][0], -1.0, 1e-12);
        ENSURE(contacts_at(&s, 0.3, &c) == 1);
        ENSURE_NEAR(c.dist[0], 0.3, 1e-12);
        ENSURE_NEAR(c.nrm[2][0], 1.0, 1e-12);
        rs_contacts_free(&c);
        rs_surface_free(&s);
    }
}

/* SIDES=1 makes a CAD mesh one-sided: the sphere below the plate has no contact. */
static void mesh_sides_1_is_one_sided(void)
{
    rs_surface s;
    ENSURE(sides_of("*SURFACE, TYPE=MESH, NAME=p, FILE=plate.stl, SIDES=1\n", &s) == 1);
    rs_contacts c;
    memset(&c, 0, sizeof c);
    ENSURE(contacts_at(&s, -0.3, &c) == 0);
    ENSURE(contacts_at(&s, 0.3, &c) == 1);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* An Abaqus rigid part is one-sided, as in Abaqus, in a file of its own or in the
 * surface file itself; SIDES=2 makes it two-sided. */
static void mesh_sides_default_one_for_abaqus_parts(void)
{
    rs_surface s;
    ENSURE(sides_of("*SURFACE, TYPE=MESH, NAME=p, FILE=plate_part.inp\n", &s) == 1);
    rs_contacts c;
    memset(&c, 0, sizeof c);
    ENSURE(contacts_at(&s, -0.3, &c) == 0);
    rs_surface_free(&s);
    ENSURE(sides_of("*SURFACE, TYPE=MESH, NAME=p\n*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n"
                    "3, 1, 1, 0\n4, 0, 1, 0\n*ELEMENT, TYPE=R3D4\n1, 1, 2, 3, 4\n",
                    &s) == 1);
    rs_surface_free(&s);
    ENSURE(sides_of("*SURFACE, TYPE=MESH, NAME=p, FILE=plate_part.inp, SIDES=2\n", &s) ==
           2);
    ENSURE(contacts_at(&s, -0.3, &c) == 1);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* The profile kinds are one-sided unless SIDES=2. */
static void profile_sides_default_one(void)
{
    rs_surface s;
    ENSURE(sides_of("*SURFACE, TYPE=SEGMENTS, NAME=f\nSTART, 1, 0\nLINE, 0, 0\n", &s) == 1);
    rs_surface_free(&s);
    ENSURE(sides_of("*SURFACE, TYPE=REVOLUTION, NAME=d\n0, 0, 0, 0, 0, 1\n"
                    "START, 1, -1\nLINE, 1, 1\n",
                    &s) == 1);
    rs_surface_free(&s);
    ENSURE(sides_of("*SURFACE, TYPE=CYLINDER, NAME=c, SIDES=2\n0, 0, 0, 1, 0, 0\n0, 0, 1\n"
                    "START, 1, 0\nLINE, 0, 0\n",
                    &s) == 2);
    rs_surface_free(&s);
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/rs_sides_XXXXXX");
    if (!mkdtemp(tmpdir))
        return 1;
    write_plates();
    RS_RUN(mesh_sides_default_both_for_cad_files);
    RS_RUN(mesh_sides_1_is_one_sided);
    RS_RUN(mesh_sides_default_one_for_abaqus_parts);
    RS_RUN(profile_sides_default_one);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    if (system(cmd) != 0)
        return 1;
    return rs_test_summary();
}
