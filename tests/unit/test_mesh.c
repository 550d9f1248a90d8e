/* MESH surfaces (src/faceted/): the query against a brute-force scan of every triangle
 * (mesh_fixture.h), on a UV sphere, a torus of planar quads, a box with rounded edges and
 * a bumpy open height field; frames by the FACETED convention from their definition; one
 * contact on flat regions, exactly above shared vertices and edges; a contact per face in
 * a concave apex; edge and vertex contacts of a box; placement, scale and a pose. The
 * resultant's continuity is in test_mesh_continuity.c, the files' errors, repairs,
 * Abaqus parts and facets in test_mesh_files.c. */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */
#include "mesh_fixture.h"

/* Contacts with shares below 1 among those the list checks of brute_force_case met. */
static int lists_shared;

/* Every point near mesh pm (file name, sides): the nearest contact is the brute-force
 * closest point of all triangles to 1e-12, its normal points from it to the point, and
 * its frame is the FACETED one; every contact is a local minimum (no triangle at its
 * closest point comes nearer), and no feature is counted twice. */
static int brute_force_case(const poly_mesh *pm, const char *name, int sides, double spread,
                            int npts, unsigned long long seed)
{
    char path[128], text[256];
    snprintf(path, sizeof path, "%s/%s.off", tmpdir, name);
    write_off(pm, path);
    snprintf(text, sizeof text, "*SURFACE, TYPE=MESH, NAME=%s, FILE=%s.off%s\n", name, name,
             sides == 2 ? ", SIDES=2" : ", SIDES=1");
    rs_surface s;
    rs_error e;
    if (load(text, &s, &e) != RS_OK) {
        fprintf(stderr, "%s\n", e.msg);
        return 0;
    }
    double(*T)[9] = malloc((size_t)pm->nf * 2 * sizeof *T);
    const int nt = pm_triangles(pm, T);
    int ok = 1;
    rs_contacts c;
    memset(&c, 0, sizeof c);
    for (int k = 0; k < npts && ok; k++) {
        /* a point near a random node */
        const int v = (int)(rs_test_xorshift(&seed) % (unsigned long long)pm->np);
        double p[3];
        for (int d = 0; d < 3; d++)
            p[d] = pm->xyz[3 * v + d] +
                   spread *
                       (2.0 * (double)(rs_test_xorshift(&seed) >> 11) / 9007199254740992.0 -
                        1.0);
        double cb[3];
        const double best = nearest_of_all((const double(*)[9])T, nt, p, cb);
        query(&s, 1, p, p + 1, p + 2, NULL, 1.0, &c);
        /* candidate lists with a margin of 0.05, taken 0.047 away and taken all but the
         * margin away in a random direction, give here the contacts of the whole mesh,
         * for a sphere of radius 0.15 (so with their shares at concave folds) */
        const double rr = 0.15;
        rs_contacts c3;
        memset(&c3, 0, sizeof c3);
        query(&s, 1, p, p + 1, p + 2, &rr, 1.0 - rr, &c3);
        for (int i = 0; i < c3.n; i++)
            lists_shared += c3.share[i] < 1.0;
        double dir[3], l2 = 0.0;
        for (int d = 0; d < 3; d++) {
            dir[d] =
                2.0 * (double)(rs_test_xorshift(&seed) >> 11) / 9007199254740992.0 - 1.0;
            l2 += dir[d] * dir[d];
        }
        const double away[2][3] = {{0.03, -0.03, 0.02},
                                   {0.04999 * dir[0] / sqrt(l2),
                                    0.04999 * dir[1] / sqrt(l2),
                                    0.04999 * dir[2] / sqrt(l2)}};
        for (int w = 0; w < 2 && ok; w++) {
            rs_query q;
            memset(&q, 0, sizeof q);
            const double p0[3] = {p[0] + away[w][0], p[1] + away[w][1], p[2] + away[w][2]};
            q.n = 1;
            q.slave.x = p0;
            q.slave.y = p0 + 1;
            q.slave.z = p0 + 2;
            q.slave.radius = &rr;
            q.gap_max = 1.0 - rr;
            q.dist_min = -INFINITY;
            rs_cands cd;
            memset(&cd, 0, sizeof cd);
            rs_contacts c2;
            memset(&c2, 0, sizeof c2);
            int same = rs_surface_candidates(&s, &q, 0.05, &cd, &e) == RS_OK;
            q.slave.x = p, q.slave.y = p + 1, q.slave.z = p + 2;
            const int *lst = cd.ids, nl = same ? cd.off[1] : 0;
            same = same && rs_surface_query_among(&s, &q, &lst, &nl, &c2, &e) == RS_OK;
            same = same && c2.n == c3.n;
            for (int i = 0; same && i < c3.n; i++) {
                same = c2.feature[i] == c3.feature[i] && c2.dist[i] == c3.dist[i] &&
                       c2.share[i] == c3.share[i];
                for (int d = 0; d < 3; d++)
                    same = same && c2.xm[d][i] == c3.xm[d][i];
            }
            rs_contacts_free(&c2);
            rs_cands_free(&cd);
            if (!same) {
                fprintf(stderr,
                        "%s: point %d: candidate lists taken %s change the contacts\n",
                        name, k, w ? "at the margin" : "0.047 away");
                ok = 0;
            }
        }
        rs_contacts_free(&c3);
        int kbest = -1;
        for (int i = 0; i < c.n; i++) {
            if (kbest < 0 || fabs(c.dist[i]) < fabs(c.dist[kbest]))
                kbest = i;
            for (int j = 0; j < i; j++)
                if (c.feature[i] == c.feature[j]) {
                    fprintf(stderr, "%s: point %d: feature %d twice\n", name, k,
                            c.feature[i]);
                    ok = 0;
                }
            /* each contact: |dist| = |p - xm|, n along p - xm, a local minimum */
            const double xm[3] = {c.xm[0][i], c.xm[1][i], c.xm[2][i]};
            const double n[3] = {c.nrm[0][i], c.nrm[1][i], c.nrm[2][i]};
            const double dd = dist3(p, xm);
            if (!(fabs(dd - fabs(c.dist[i])) <= 1e-12)) {
                fprintf(stderr, "%s: point %d: |p - xm| %.17g, dist %.17g\n", name, k, dd,
                        c.dist[i]);
                ok = 0;
            }
            for (int d = 0; d < 3 && dd > 1e-9; d++)
                if (!(fabs(c.dist[i] * n[d] - (p[d] - xm[d])) <= 1e-12)) {
                    fprintf(stderr, "%s: point %d: normal off p - xm\n", name, k);
                    ok = 0;
                    break;
                }
            for (int t = 0; t < nt; t++) {
                double cp[3];
                if (closest_on_triangle(T[t], xm, cp) > 1e-12)
                    continue; /* triangles at the contact point */
                if (closest_on_triangle(T[t], p, cp) < dd - 1e-12) {
                    fprintf(stderr,
                            "%s: point %d: contact %d at %.17g is no local minimum "
                            "(triangle %d at %.17g)\n",
                            name, k, c.feature[i], dd, t, dist3(p, cp));
                    ok = 0;
                    break;
                }
            }
        }
        if (best > 1.0)
            continue; /* beyond the query's reach */
        if (kbest < 0) {
            fprintf(stderr, "%s: point %d at %.17g from the mesh: no contact\n", name, k,
                    best);
            ok = 0;
            break;
        }
        if (!(fabs(fabs(c.dist[kbest]) - best) <= 1e-12)) {
            fprintf(stderr, "%s: point %d: nearest contact %.17g, brute force %.17g\n",
                    name, k, c.dist[kbest], best);
            ok = 0;
        }
        const double n[3] = {c.nrm[0][kbest], c.nrm[1][kbest], c.nrm[2][kbest]};
        double t1[3], t2[3];
        faceted_t1(n, t1);
        rs_cross3(n, t1, t2);
        for (int d = 0; d < 3; d++)
            if (!(fabs(c.t1[d][kbest] - t1[d]) <= 1e-12 &&
                  fabs(c.t2[d][kbest] - t2[d]) <= 1e-12)) {
                fprintf(stderr, "%s: point %d: frame differs from FACETED\n", name, k);
                ok = 0;
                break;
            }
    }
    rs_contacts_free(&c);
    rs_surface_free(&s);
    free(T);
    return ok;
}

/* The four meshes, each queried two-sided and, where closed, one-sided as well. */
static void brute_force_meshes(void)
{
    static const struct {
        const char *name;
        int sides;
        double spread;
        unsigned long long seed;
    } cases[] = {{"sphere", 2, 0.3, 11}, {"torus", 2, 0.25, 12}, {"torus1", 1, 0.25, 16},
                 {"rbox", 2, 0.3, 13},   {"rbox1", 1, 0.3, 17},  {"hfield", 2, 0.3, 15}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        poly_mesh m;
        const char c = cases[k].name[1];
        if (c == 'p')
            uv_sphere(&m, 16, 32);
        else if (c == 'o')
            torus(&m, 32, 16, 1.0, 0.3);
        else if (c == 'b')
            rounded_box(&m, 8, 0.3);
        else
            height_field(&m, 20, 14);
        const int ok = brute_force_case(&m, cases[k].name, cases[k].sides, cases[k].spread,
                                        600, cases[k].seed);
        pm_free(&m);
        ENSURE(ok);
    }
    ENSURE(lists_shared > 0);
}

/* Candidate lists keep the concave folds that shorten the shares of a sphere anywhere
 * within their margin: a sphere of radius 0.15 placed 0.9 of its radius from each node
 * of a bumpy height field (two-sided; valleys, ridges and saddles), on either side, with
 * its list taken all but the margin (0.05) farther from the node, gets the contacts and
 * the shares of the tree query, value for value. */
static void lists_keep_the_folds_of_shares(void)
{
    poly_mesh pm;
    height_field(&pm, 20, 14);
    const int np = pm.np;
    double *node = malloc(3 * (size_t)np * sizeof *node);
    memcpy(node, pm.xyz, 3 * (size_t)np * sizeof *node);
    rs_surface s;
    rs_error e;
    if (load_pm_sides(&pm, "folds", 2, &s) != RS_OK) {
        free(node);
        ENSURE(0);
        return;
    }
    const double R = 0.15, margin = 0.05;
    unsigned long long seed = 29;
    int shared = 0, bad = 0;
    rs_contacts ct, cl;
    memset(&ct, 0, sizeof ct);
    memset(&cl, 0, sizeof cl);
    rs_cands cd;
    memset(&cd, 0, sizeof cd);
    for (int v = 0; v < np; v++)
        for (int side = -1; side <= 1; side += 2) {
            double u[3];
            for (int d = 0; d < 3; d++)
                u[d] = 2.0 * (double)(rs_test_xorshift(&seed) >> 11) / 9007199254740992.0 -
                       1.0;
            u[2] = side * (1.0 + fabs(u[2]));
            const double l = rs_norm3(u);
            double p[3], p0[3];
            for (int d = 0; d < 3; d++) {
                p[d] = node[3 * v + d] + 0.9 * R * u[d] / l;
                p0[d] = p[d] + 0.99998 * margin * u[d] / l;
            }
            rs_query q;
            memset(&q, 0, sizeof q);
            q.n = 1;
            q.slave.x = p0, q.slave.y = p0 + 1, q.slave.z = p0 + 2;
            q.slave.radius = &R;
            q.gap_max = 0.05;
            q.dist_min = -R;
            int ok = rs_surface_candidates(&s, &q, margin, &cd, &e) == RS_OK;
            q.slave.x = p, q.slave.y = p + 1, q.slave.z = p + 2;
            ct.n = cl.n = 0;
            const int *lst = cd.ids, nl = ok ? cd.off[1] : 0;
            ok = ok && rs_surface_query(&s, &q, &ct, &e) == RS_OK &&
                 rs_surface_query_among(&s, &q, &lst, &nl, &cl, &e) == RS_OK &&
                 cl.n == ct.n;
            for (int k = 0; ok && k < ct.n; k++)
                ok = cl.feature[k] == ct.feature[k] && cl.dist[k] == ct.dist[k] &&
                     cl.share[k] == ct.share[k];
            for (int k = 0; k < ct.n; k++)
                shared += ct.share[k] < 1.0;
            if (!ok) {
                fprintf(stderr, "node %d, side %d: the lists change the contacts\n", v,
                        side);
                bad++;
            }
        }
    ENSURE(bad == 0);
    ENSURE(shared > 50);
    free(node);
    rs_cands_free(&cd);
    rs_contacts_free(&ct);
    rs_contacts_free(&cl);
    rs_surface_free(&s);
}

/* A mesh large enough that the list query fetches its candidates' records ahead
 * (mesh_query.c, RS_MESH_PREFETCH_MIN) and 4000 spheres in one query: through candidate
 * lists the contacts are those of the tree query, value for value, and the nearest of
 * each of the first 300 is the brute-force closest point of all triangles. */
static void large_mesh_lists_are_the_tree(void)
{
    poly_mesh pm;
    uv_sphere(&pm, 130, 130); /* 33800 triangles */
    double(*T)[9] = malloc((size_t)pm.nf * 2 * sizeof *T);
    const int ntri = pm_triangles(&pm, T);
    ENSURE(ntri >= 32768);
    rs_surface s;
    if (load_pm(&pm, "large", &s) != RS_OK) {
        ENSURE(0);
        free(T);
        return;
    }
    enum { NP = 4000 };
    static double x[NP], y[NP], z[NP], r[NP];
    unsigned long long seed = 41;
    for (int i = 0; i < NP; i++) {
        double d[3], l2 = 0.0;
        for (int k = 0; k < 3; k++) {
            d[k] = 2.0 * (double)(rs_test_xorshift(&seed) >> 11) / 9007199254740992.0 - 1.0;
            l2 += d[k] * d[k];
        }
        const double u = (double)(rs_test_xorshift(&seed) >> 11) / 9007199254740992.0;
        const double rho = (0.97 + 0.06 * u) / sqrt(l2); /* inside and outside */
        x[i] = rho * d[0], y[i] = rho * d[1], z[i] = rho * d[2];
        r[i] = 0.02;
    }
    rs_query q;
    memset(&q, 0, sizeof q);
    q.n = NP;
    q.slave.x = x, q.slave.y = y, q.slave.z = z, q.slave.radius = r;
    q.gap_max = 0.01;
    q.dist_min = -0.05;
    rs_contacts ct, cl;
    memset(&ct, 0, sizeof ct);
    memset(&cl, 0, sizeof cl);
    rs_cands cd;
    memset(&cd, 0, sizeof cd);
    rs_error e;
    ENSURE(rs_surface_query(&s, &q, &ct, &e) == RS_OK);
    ENSURE(rs_surface_candidates(&s, &q, 0.005, &cd, &e) == RS_OK);
    const int **lists = malloc(NP * sizeof *lists);
    int *counts = malloc(NP * sizeof *counts);
    for (int i = 0; i < NP; i++) {
        lists[i] = cd.ids + cd.off[i];
        counts[i] = cd.off[i + 1] - cd.off[i];
    }
    ENSURE(rs_surface_query_among(&s, &q, lists, counts, &cl, &e) == RS_OK);
    ENSURE(ct.n > NP / 2);
    ENSURE(cl.n == ct.n);
    int same = cl.n == ct.n;
    for (int k = 0; same && k < ct.n; k++) {
        same = cl.point[k] == ct.point[k] && cl.feature[k] == ct.feature[k] &&
               cl.dist[k] == ct.dist[k] && cl.share[k] == ct.share[k];
        for (int d = 0; d < 3; d++)
            same = same && cl.xm[d][k] == ct.xm[d][k] && cl.nrm[d][k] == ct.nrm[d][k];
    }
    ENSURE(same);
    /* the nearest contact of each of the first 300 spheres against all triangles */
    int k = 0, bad = 0;
    for (int i = 0; i < 300; i++) {
        const double p[3] = {x[i], y[i], z[i]};
        double cb[3] = {0, 0, 0};
        const double best = nearest_of_all((const double(*)[9])T, ntri, p, cb);
        int kbest = -1;
        for (; k < cl.n && cl.point[k] == i; k++)
            if (kbest < 0 || fabs(cl.dist[k]) < fabs(cl.dist[kbest]))
                kbest = k;
        if (kbest < 0) { /* none only outside, beyond the gap limit */
            bad += !(sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) > 1.0 &&
                     best >= r[i] + q.gap_max - 1e-9);
            continue;
        }
        const double xm[3] = {cl.xm[0][kbest], cl.xm[1][kbest], cl.xm[2][kbest]};
        if (!(fabs(fabs(cl.dist[kbest]) - best) <= 1e-12 && dist3(xm, cb) <= 1e-9))
            bad++;
    }
    ENSURE(bad == 0);
    free(lists);
    free(counts);
    free(T);
    rs_cands_free(&cd);
    rs_contacts_free(&ct);
    rs_contacts_free(&cl);
    rs_surface_free(&s);
}

/* One-sided, from outside a closed convex mesh: exactly one contact at every point, the
 * brute-force closest point. */
static void one_contact_outside_convex(void)
{
    poly_mesh m;
    uv_sphere(&m, 12, 24);
    const int ok = brute_force_case(&m, "sphere1", 1, 0.0, 0, 1);
    rs_surface s;
    rs_error e;
    ENSURE(ok);
    ENSURE(load("*SURFACE, TYPE=MESH, NAME=s, FILE=sphere1.off, SIDES=1\n", &s, &e) ==
           RS_OK);
    unsigned long long seed = 5;
    rs_contacts c;
    memset(&c, 0, sizeof c);
    int bad = 0;
    for (int k = 0; k < 2000; k++) {
        double dir[3];
        for (int d = 0; d < 3; d++)
            dir[d] =
                2.0 * (double)(rs_test_xorshift(&seed) >> 11) / 9007199254740992.0 - 1.0;
        const double l = rs_norm3(dir);
        const double rad = 1.02 + 0.2 * k / 2000.0;
        double p[3] = {rad * dir[0] / l, rad * dir[1] / l, rad * dir[2] / l};
        query(&s, 1, p, p + 1, p + 2, NULL, 1.0, &c);
        bad += c.n != 1 || !(c.dist[0] > 0.0);
    }
    rs_contacts_free(&c);
    rs_surface_free(&s);
    pm_free(&m);
    ENSURE(bad == 0);
}

/* Six coplanar triangles around a vertex: a point exactly above the vertex, above each
 * shared edge and anywhere above the fan has one contact, n = +z, dist = height,
 * exactly as on the plane. */
static void flat_fan_one_contact(void)
{
    poly_mesh m;
    apex_fan(&m, 6, 1.0, 0.0);
    rs_surface s;
    ENSURE(load_pm(&m, "fan", &s) == RS_OK);
    rs_contacts c;
    memset(&c, 0, sizeof c);
    const double h = 0.0123;
    double x = 0, y = 0, z = h;
    query(&s, 1, &x, &y, &z, NULL, 0.1, &c);
    ENSURE(c.n == 1);
    ENSURE(c.dist[0] == h && c.nrm[2][0] == 1.0 && c.xm[2][0] == 0.0);
    /* above each shared edge, at several places along it */
    for (int k = 0; k < 6; k++)
        for (int j = 1; j < 5; j++) {
            x = 0.2 * j * cos(RS_PI * k / 3.0);
            y = 0.2 * j * sin(RS_PI * k / 3.0);
            query(&s, 1, &x, &y, &z, NULL, 0.1, &c);
            ENSURE(c.n == 1);
            ENSURE_NEAR(c.dist[0], h, 1e-15);
            ENSURE_NEAR(c.nrm[2][0], 1.0, 1e-15);
        }
    unsigned long long seed = 3;
    for (int k = 0; k < 5000; k++) {
        x = 1.6 * (double)(rs_test_xorshift(&seed) >> 11) / 9007199254740992.0 - 0.8;
        y = 1.6 * (double)(rs_test_xorshift(&seed) >> 11) / 9007199254740992.0 - 0.8;
        if (hypot(x, y) > 0.85)
            continue;
        query(&s, 1, &x, &y, &z, NULL, 0.1, &c);
        ENSURE(c.n == 1);
        ENSURE_NEAR(c.dist[0], h, 1e-15);
    }
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* Inside the apex of a 12-facet cone (half angle 30 deg), a point on the axis has one
 * contact per facet, each at its closed-form distance z sin(30 deg) (apex at the
 * origin, the point at height z). */
static void cone_apex_contact_per_face(void)
{
    poly_mesh m;
    apex_fan(&m, 12, tan(RS_PI / 6.0), 1.0); /* normals toward the inside (the axis) */
    rs_surface s;
    ENSURE(load_pm(&m, "cone", &s) == RS_OK);
    rs_contacts c;
    memset(&c, 0, sizeof c);
    double x = 0, y = 0, z = 0.3, r = 0.2;
    query(&s, 1, &x, &y, &z, &r, 0.0, &c);
    ENSURE(c.n == 12);
    /* a facet's plane is at angle 30 deg to the axis only at its middle; its distance
     * from the axis point is z sin(a) with tan(a) = tan(30 deg) cos(15 deg) */
    const double a = atan(tan(RS_PI / 6.0) * cos(RS_PI / 12.0));
    for (int k = 0; k < 12; k++) {
        ENSURE(RS_FEATURE_TYPE(c.feature[k]) == RS_FEAT_FACE);
        ENSURE_NEAR(c.dist[k], z * sin(a), 1e-14);
    }
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* A unit cube of quads: at a convex edge one edge contact, beyond a corner one vertex
 * contact, above a face one face contact; inside near an edge only the shallower face
 * (a penetration). */
static void cube_edges_and_corners(void)
{
    const char *cube =
        "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
        "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n4 0 4 7 3\n";
    write_text("cube.off", cube);
    rs_surface s;
    rs_error e;
    ENSURE(load("*SURFACE, TYPE=MESH, NAME=cube, FILE=cube.off, SIDES=1\n", &s, &e) ==
           RS_OK);
    rs_contacts c;
    memset(&c, 0, sizeof c);
    double x = 1.1, y = 0.4, z = 1.2; /* beyond the edge x = 1, z = 1 */
    query(&s, 1, &x, &y, &z, NULL, 1.0, &c);
    ENSURE(c.n == 1 && RS_FEATURE_TYPE(c.feature[0]) == RS_FEAT_EDGE);
    ENSURE_NEAR(c.dist[0], hypot(0.1, 0.2), 1e-15);
    /* the edge x = 1, z = 1 belongs to elements 2 (top) and 5 (x = 1): its facet is one
     * of them */
    {
        const int k = rs_surface_facet_index(&s, c.feature[0]);
        ENSURE(k == 1 || k == 4);
    }
    x = 1.1, y = 1.2, z = 1.3; /* beyond the corner (1, 1, 1) */
    query(&s, 1, &x, &y, &z, NULL, 1.0, &c);
    ENSURE(c.n == 1 && RS_FEATURE_TYPE(c.feature[0]) == RS_FEAT_VERTEX);
    ENSURE_NEAR(c.dist[0], sqrt(0.01 + 0.04 + 0.09), 1e-15);
    x = 0.3, y = 0.6, z = 1.05; /* above the top face, off its diagonal */
    query(&s, 1, &x, &y, &z, NULL, 1.0, &c);
    ENSURE(c.n == 1 && RS_FEATURE_TYPE(c.feature[0]) == RS_FEAT_FACE);
    ENSURE_NEAR(c.dist[0], 0.05, 1e-15);
    x = 0.98, y = 0.5, z = 0.95; /* inside, nearer the side x = 1 */
    query(&s, 1, &x, &y, &z, NULL, 0.0, &c);

    ENSURE(c.n == 1 && RS_FEATURE_TYPE(c.feature[0]) == RS_FEAT_FACE);
    ENSURE_NEAR(c.dist[0], -0.02, 1e-15);
    ENSURE_NEAR(c.nrm[0][0], 1.0, 1e-15);
    { /* the same with every face within reach: the deeper faces give no contact */
        rs_query q;
        memset(&q, 0, sizeof q);
        q.n = 1;
        q.slave.x = &x;
        q.slave.y = &y;
        q.slave.z = &z;
        q.gap_max = 0.0;
        q.dist_min = -1.5;
        c.n = 0;
        ENSURE(rs_surface_query(&s, &q, &c, &e) == RS_OK);
        ENSURE(c.n == 1);
        ENSURE_NEAR(c.dist[0], -0.02, 1e-15);
    }
    /* history passes from a face to its own edge, not to a far one */
    const int f0 = c.feature[0];
    x = 1.1, y = 0.4, z = 1.2;
    query(&s, 1, &x, &y, &z, NULL, 1.0, &c);
    ENSURE(rs_surface_adjacent(&s, f0, c.feature[0]) == 1);
    x = -0.1, y = 0.4, z = -0.2;
    query(&s, 1, &x, &y, &z, NULL, 1.0, &c);
    ENSURE(c.n == 1 && rs_surface_adjacent(&s, f0, c.feature[0]) == 0);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* SCALE and the placement line: a unit quad scaled by 2 and placed with its x axis along
 * global y at (1, 2, 3) gives the plane x = 1 with normal +x... from its winding. */
static void scale_and_placement(void)
{
    const char *quad = "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
    write_text("quad.off", quad);
    rs_surface s;
    rs_error e;
    /* a = (1,2,3); local x along global y; local y along global z: local z = global x */
    ENSURE(load("*SURFACE, TYPE=MESH, NAME=q, FILE=quad.off, SCALE=2, SIDES=1\n"
                "1, 2, 3, 1, 3, 3, 1, 2, 4\n",
                &s, &e) == RS_OK);
    double lo[3], hi[3];
    rs_surface_bounds(&s, lo, hi);
    ENSURE(lo[0] == 1.0 && hi[0] == 1.0 && lo[1] == 2.0 && hi[1] == 4.0 && lo[2] == 3.0 &&
           hi[2] == 5.0);
    rs_contacts c;
    memset(&c, 0, sizeof c);
    double x = 1.5, y = 3.0, z = 4.0;
    query(&s, 1, &x, &y, &z, NULL, 1.0, &c);
    ENSURE(c.n == 1);
    ENSURE_NEAR(c.dist[0], 0.5, 1e-15);
    ENSURE_NEAR(c.nrm[0][0], 1.0, 1e-15);
    /* the FACETED frame: x is the normal, so t1 = global z projected, t2 = n x t1 */
    ENSURE_NEAR(c.t1[2][0], 1.0, 1e-15);
    ENSURE_NEAR(c.t2[1][0], -1.0, 1e-15);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* A pose moves the mesh rigidly: the query of a moved point against the moved mesh is
 * the reference query moved. */
static void pose_moves_the_mesh(void)
{
    poly_mesh m;
    torus(&m, 16, 8, 1.0, 0.3);
    char path[128];
    snprintf(path, sizeof path, "%s/tp.off", tmpdir);
    write_off(&m, path);
    pm_free(&m);
    rs_surface s;
    rs_error e;
    ENSURE(load("*SURFACE, TYPE=MESH, NAME=t, FILE=tp.off, SIDES=1\n", &s, &e) == RS_OK);
    rs_pose pose;
    const double ax[3] = {0.3, -0.5, 0.8};
    const double l = rs_norm3(ax);
    const double u[3] = {ax[0] / l, ax[1] / l, ax[2] / l};
    rs_rotation_matrix(u, 0.7, pose.R);
    pose.T[0] = 0.4;
    pose.T[1] = -1.0;
    pose.T[2] = 2.0;
    const double X[3] = {1.25, 0.1, 0.2};
    double x[3];
    rs_pose_to_global(&pose, X, x);
    rs_contacts c0, c1;
    memset(&c0, 0, sizeof c0);
    memset(&c1, 0, sizeof c1);
    query(&s, 1, X, X + 1, X + 2, NULL, 1.0, &c0);
    rs_query q;
    memset(&q, 0, sizeof q);
    q.n = 1;
    q.slave.x = x;
    q.slave.y = x + 1;
    q.slave.z = x + 2;
    q.pose = &pose;
    q.gap_max = 1.0;
    q.dist_min = -INFINITY;
    ENSURE(rs_surface_query(&s, &q, &c1, &e) == RS_OK);
    ENSURE(c0.n >= 1 && c0.n == c1.n);
    for (int k = 0; k < c0.n; k++) {
        ENSURE(c0.feature[k] == c1.feature[k]);
        ENSURE_NEAR(c0.dist[k], c1.dist[k], 1e-14);
        const double xm0[3] = {c0.xm[0][k], c0.xm[1][k], c0.xm[2][k]};
        const double n0[3] = {c0.nrm[0][k], c0.nrm[1][k], c0.nrm[2][k]};
        double xm[3], n[3];
        rs_pose_to_global(&pose, xm0, xm);
        rs_pose_rotate(&pose, n0, n);
        for (int d = 0; d < 3; d++) {
            ENSURE_NEAR(c1.xm[d][k], xm[d], 1e-14);
            ENSURE_NEAR(c1.nrm[d][k], n[d], 1e-14);
        }
    }
    rs_contacts_free(&c0);
    rs_contacts_free(&c1);
    rs_surface_free(&s);
}

int main(void)
{
    if (!mesh_fixture_begin("mesh"))
        return 1;
    RS_RUN(brute_force_meshes);
    RS_RUN(large_mesh_lists_are_the_tree);
    RS_RUN(lists_keep_the_folds_of_shares);
    RS_RUN(one_contact_outside_convex);
    RS_RUN(flat_fan_one_contact);
    RS_RUN(cone_apex_contact_per_face);
    RS_RUN(cube_edges_and_corners);
    RS_RUN(scale_and_placement);
    RS_RUN(pose_moves_the_mesh);
    if (!mesh_fixture_end())
        return 1;
    return rs_test_summary();
}
