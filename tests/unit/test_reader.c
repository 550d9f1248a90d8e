/* Surface files: the keyword grammar, several surfaces per file, the example files, and
 * bad input (each case gives its own code and a message "ORIGIN:LINE: ..."). Random
 * garbage never crashes the reader. */
#include "rigidsurf/surface.h"
#include "rs_test.h"

#include <math.h>
#include <stdlib.h>

static const char *GOOD =
    "** two surfaces\n"
    "\n"
    "*surface, type=segments, name=Floor\n"
    "start, -1, 0\n"
    "  line , 1.0D0 , 0   \n"
    "**\n"
    "*SURFACE, TYPE=CYLINDER, NAME=chute, SIDES=2, EXTENT=-0.5, 1.5,\n"
    "0,0,0, 1,0,0\r\n"
    "0,0,2\n"
    "START, 0, 1\n"
    "CIRCL, 1, 0, 0, 0\n"
    "PARAB, 1.5, 0.1, 2, 0\n";

static void test_reader_keywords_case_comments_and_names(void)
{
    rs_surface s;
    rs_error e;
    ENSURE(rs_surface_parse(GOOD, "good.inp", NULL, &s, &e) == RS_OK);
    ENSURE(s.kind == RS_SURF_SEGMENTS && strcmp(s.name, "Floor") == 0);
    ENSURE(s.profile.nseg == 1 && s.sides == 1);
    ENSURE(s.profile.seg[0].p1[0] == 1.0);
    rs_surface_free(&s);
    ENSURE(rs_surface_parse(GOOD, "good.inp", "CHUTE", &s, &e) == RS_OK);
    ENSURE(s.kind == RS_SURF_CYLINDER && s.sides == 2 && s.bounded);
    ENSURE(s.zmin == -0.5 && s.zmax == 1.5);
    ENSURE(s.profile.nseg == 2);
    ENSURE(s.profile.seg[0].type == RS_CIRCL && s.profile.seg[1].type == RS_PARAB);
    ENSURE(s.ez[2] == 1.0 && s.ex[0] == 1.0 && s.ey[1] == 1.0);
    rs_surface_free(&s);
    ENSURE(rs_surface_parse(GOOD, "good.inp", "nope", &s, &e) == RS_ERR_NOTFOUND);
    ENSURE(strstr(e.msg, "nope") != NULL);
}

/* CYLINDER axes: x = (b - a)/|b - a|, the generator z = c - a made normal to x (c need
 * not lie on the generator through a), y = z x x. */
static void test_reader_cylinder_c_is_made_normal_to_x(void)
{
    rs_surface s;
    rs_error e;
    ENSURE(rs_surface_parse("*SURFACE, TYPE=CYLINDER, NAME=c\n1, 1, 1, 1, 3, 1\n"
                            "1, 6, -1\nSTART, 0, 0\nLINE, 1, 0\n",
                            "axes.inp", NULL, &s, &e) == RS_OK);
    const double ex[3] = {0, 1, 0}, ez[3] = {0, 0, -1}, ey[3] = {1, 0, 0};
    for (int d = 0; d < 3; d++)
        ENSURE(s.ex[d] == ex[d] && s.ey[d] == ey[d] && s.ez[d] == ez[d]);
    rs_surface_free(&s);
}

/* Each malformed input: code, and the message names ORIGIN:LINE. */
typedef struct bad_case {
    const char *what;
    const char *text;
    int code;
    int line;
    const char *says;
} bad_case;

static const bad_case BAD[] = {
    {"wrong number of values", "*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, 0, 0\nLINE, 1\n",
     RS_ERR_PARSE, 3, "LINE takes 2"},
    {"too many values", "*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, 0, 0, 0\nLINE, 1, 0\n",
     RS_ERR_PARSE, 2, "START takes 2"},
    {"non-number", "*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, 0, 0\nLINE, 1, x2\n",
     RS_ERR_PARSE, 3, "expected a number"},
    {"nan is not a number", "*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, 0, 0\nLINE, nan, 1\n",
     RS_ERR_PARSE, 3, "number"},
    {"unknown keyword", "*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, 0, 0\n*STEP\n",
     RS_ERR_PARSE, 3, "unknown keyword"},
    {"unknown parameter", "*SURFACE, TYPE=SEGMENTS, NAME=a, COLOR=red\nSTART, 0, 0\n",
     RS_ERR_PARSE, 1, "unknown parameter"},
    {"unknown TYPE", "*SURFACE, TYPE=SPHERE, NAME=a\n", RS_ERR_PARSE, 1, "TYPE"},
    {"missing TYPE", "*SURFACE, NAME=a\nSTART, 0, 0\n", RS_ERR_PARSE, 1, "TYPE"},
    {"unknown profile line", "*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, 0, 0\nARC, 1, 0\n",
     RS_ERR_PARSE, 3, "expected START, LINE, CIRCL or PARAB"},
    {"profile values without commas",
     "*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART 0.015 0.0\nLINE, 1, 0\n", RS_ERR_PARSE, 2,
     "expected commas between values: START, x, y (found 'START 0.015 0.0')"},
    {"a comma missing after the word",
     "*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, 0, 0\ncircl 0, 1, 0, 0\n", RS_ERR_PARSE, 3,
     "expected commas between values: CIRCL, x1, y1, xc, yc"},
    {"points without commas",
     "*SURFACE, TYPE=REVOLUTION, NAME=a\n0 0 0 0 0 1\nSTART, 1, 0\nLINE, 1, 1\n",
     RS_ERR_PARSE, 2, "expected commas between values: ax, ay, az, bx, by, bz"},
    {"point c without commas",
     "*SURFACE, TYPE=CYLINDER, NAME=a\n0, 0, 0, 1, 0, 0\n0 -1 0\nSTART, 0, 0\n",
     RS_ERR_PARSE, 3, "expected commas between values: cx, cy, cz"},
    {"missing START", "*SURFACE, TYPE=SEGMENTS, NAME=a\nLINE, 1, 0\n", RS_ERR_PARSE, 2,
     "expected START"},
    {"START not first",
     "*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, 0, 0\nLINE, 1, 0\nSTART, 2, 0\n",
     RS_ERR_PARSE, 4, "START must be the first"},
    {"arc of 180 degrees",
     "*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, 1, 0\nCIRCL, -1, 0, 0, 0\n", RS_ERR_GEOMETRY,
     3, "180"},
    {"arc over 180 degrees is taken the short way, so a zero-length arc",
     "*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, 1, 0\nCIRCL, 1, 0, 0, 0\n", RS_ERR_GEOMETRY,
     3, "zero-length"},
    {"zero-length LINE", "*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, 1, 2\nLINE, 1, 2\n",
     RS_ERR_GEOMETRY, 3, "zero-length"},
    {"radius mismatch",
     "*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, 1, 0\nCIRCL, 0, 1.001, 0, 0\n",
     RS_ERR_GEOMETRY, 3, "radius mismatch"},
    {"degenerate PARAB",
     "*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, 0, 0\nPARAB, 3, 0, 1, 0\n", RS_ERR_GEOMETRY,
     3, "PARAB"},
    {"coincident a and b",
     "*SURFACE, TYPE=CYLINDER, NAME=a\n1,1,1, 1,1,1\n0,0,1\nSTART,0,0\n"
     "LINE,1,0\n",
     RS_ERR_GEOMETRY, 2, "a and b"},
    {"c coincides with a",
     "*SURFACE, TYPE=CYLINDER, NAME=a\n0,0,0, 1,0,0\n0,0,0\nSTART,0,0\n"
     "LINE,1,0\n",
     RS_ERR_GEOMETRY, 3, "point c"},
    {"c collinear with a, b",
     "*SURFACE, TYPE=CYLINDER, NAME=a\n0,0,0, 1,0,0\n2,0,0\nSTART,0,0\nLINE,1,0\n",
     RS_ERR_GEOMETRY, 3, "point c"},
    {"coincident axis points",
     "*SURFACE, TYPE=REVOLUTION, NAME=a\n0,0,1, 0,0,1\nSTART,0,0\n"
     "LINE,1,0\n",
     RS_ERR_GEOMETRY, 2, "a and b"},
    {"revolution profile r < 0",
     "*SURFACE, TYPE=REVOLUTION, NAME=a\n0,0,0, 0,0,1\nSTART, 1, 0\nLINE, -0.5, 1\n",
     RS_ERR_GEOMETRY, 4, "r >= 0"},
    {"revolution arc dips below r = 0",
     "*SURFACE, TYPE=REVOLUTION, NAME=a\n0,0,0, 0,0,1\nSTART, 0.1, -1\n"
     "CIRCL, 0.1, 1, 0.9, 0\n",
     RS_ERR_GEOMETRY, 4, "r >= 0"},
    {"coordinates missing", "*SURFACE, TYPE=CYLINDER, NAME=a\nSTART, 0, 0\nLINE, 1, 0\n",
     RS_ERR_PARSE, 2, "points a, b"},
    {"c line missing", "*SURFACE, TYPE=CYLINDER, NAME=a\n0,0,0, 1,0,0\nSTART, 0, 0\n",
     RS_ERR_PARSE, 3, "point c"},
    {"empty profile", "*SURFACE, TYPE=SEGMENTS, NAME=a\n** nothing\n", RS_ERR_PARSE, 1,
     "empty profile"},
    {"START only", "*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, 0, 0\n", RS_ERR_PARSE, 1,
     "empty profile"},
    {"EXTENT not for REVOLUTION",
     "*SURFACE, TYPE=REVOLUTION, NAME=a, EXTENT=0, 1\n0,0,0, 0,0,1\nSTART,1,0\nLINE,1,1\n",
     RS_ERR_PARSE, 1, "EXTENT"},
    {"EXTENT without zmax", "*SURFACE, TYPE=CYLINDER, NAME=a, EXTENT=0\n", RS_ERR_PARSE, 1,
     "EXTENT"},
    {"EXTENT reversed", "*SURFACE, TYPE=CYLINDER, NAME=a, EXTENT=1, 0\n", RS_ERR_PARSE, 1,
     "zmin < zmax"},
    {"bad SIDES", "*SURFACE, TYPE=SEGMENTS, NAME=a, SIDES=3\n", RS_ERR_PARSE, 1, "SIDES"},
    {"negative fillet", "*SURFACE, TYPE=SEGMENTS, NAME=a, FILLET RADIUS=-1\n", RS_ERR_PARSE,
     1, "FILLET"},
    {"fillet does not fit",
     "*SURFACE, TYPE=SEGMENTS, NAME=a, FILLET RADIUS=5\nSTART, -1, 0\nLINE, 0, 0\n"
     "LINE, 0, 1\n",
     RS_ERR_GEOMETRY, 3, "vertex 1"},
    {"data before *SURFACE", "START, 0, 0\n", RS_ERR_PARSE, 1, "*SURFACE"},
    {"duplicate name",
     "*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART,0,0\nLINE,1,0\n*SURFACE, TYPE=SEGMENTS, "
     "NAME=A\nSTART,0,0\nLINE,1,0\n",
     RS_ERR_PARSE, 4, "twice"},
    {"duplicate parameter", "*SURFACE, TYPE=SEGMENTS, TYPE=SEGMENTS, NAME=a\n",
     RS_ERR_PARSE, 1, "twice"},
    {"empty value", "*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, , 0\n", RS_ERR_PARSE, 2,
     "empty value"},
    {"overflowing coordinates",
     "*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, 1e308, 0\nLINE, -1e308, 0\n", RS_ERR_PARSE, 2,
     "at most 1e100, found '1e308'"},
    {"coordinate whose square overflows",
     "*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, 0, 0\nLINE, 1, -2e154\n", RS_ERR_PARSE, 3,
     "at most 1e100, found '-2e154'"},
    {"LINE of denormal length",
     "*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, 0, 0\nLINE, 1e-310, 0\n", RS_ERR_GEOMETRY, 3,
     "length of at least"},
    {"segment under 1e-12 of the profile's size",
     "*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, 0, 0\nLINE, 1e-13, 0\nLINE, 1, 0\n",
     RS_ERR_GEOMETRY, 3, "of the profile's size"},
    {"cylinder placement beyond 1e100",
     "*SURFACE, TYPE=CYLINDER, NAME=a\n0,0,0, 1e101,0,0\n0,1,0\nSTART,0,0\nLINE,1,0\n",
     RS_ERR_PARSE, 2, "at most 1e100"},
    {"no surface at all", "** only a comment\n", RS_ERR_NOTFOUND, 0, "no *SURFACE"},
};

static void test_reader_bad_input_codes_and_lines(void)
{
    int n = (int)(sizeof BAD / sizeof BAD[0]);
    for (int i = 0; i < n; i++) {
        rs_surface s;
        rs_error e;
        rs_error_clear(&e);
        int rc = rs_surface_parse(BAD[i].text, "bad.inp", NULL, &s, &e);
        char where[64];
        snprintf(where, sizeof where, "bad.inp:%d: ", BAD[i].line);
        int ok = rc == BAD[i].code && e.code == rc && strstr(e.msg, BAD[i].says) &&
                 (BAD[i].line == 0 || strncmp(e.msg, where, strlen(where)) == 0);
        if (!ok)
            fprintf(stderr, "case '%s': rc %d (want %d), msg '%s'\n", BAD[i].what, rc,
                    BAD[i].code, e.msg);
        ENSURE(ok);
        ENSURE(s.profile.seg == NULL && s.impl == NULL); /* nothing leaks on error */
    }
}

static void test_reader_missing_file_names_the_path(void)
{
    rs_surface s;
    rs_error e;
    int rc = rs_surface_read("no/such/dir/surf.inp", NULL, &s, &e);
    ENSURE(rc == RS_ERR_IO && e.code == RS_ERR_IO);
    ENSURE(strstr(e.msg, "no/such/dir/surf.inp") != NULL);
}

/* A directory given as the surface file says so. */
static void test_reader_directory_is_named(void)
{
    rs_surface s;
    rs_error e;
    int rc = rs_surface_read(".", NULL, &s, &e);
    ENSURE(rc == RS_ERR_IO && e.code == RS_ERR_IO);
    ENSURE(strstr(e.msg, ".: is a directory (expected a surface file)") != NULL);
    ENSURE(s.profile.seg == NULL && s.impl == NULL);
}

/* Many unnamed surfaces and a name that is not among them: the list of names in the
 * message is bounded (the sanitizer build checks the writes) and ends in "...". */
static void test_reader_many_unnamed_surfaces(void)
{
    enum { NSURF = 60 };
    static char text[NSURF * 64];
    size_t m = 0;
    for (int i = 0; i < NSURF; i++)
        m += (size_t)snprintf(text + m, sizeof text - m,
                              "*SURFACE, TYPE=SEGMENTS\nSTART, 0, %d\nLINE, 1, %d\n", i, i);
    rs_surface s;
    rs_error e;
    int rc = rs_surface_parse(text, "many.inp", "absent", &s, &e);
    ENSURE(rc == RS_ERR_NOTFOUND);
    ENSURE(strstr(e.msg, "surface 'absent' not found (found: (unnamed), (unnamed)") !=
           NULL);
    ENSURE(strstr(e.msg, ", ...)") != NULL);
    ENSURE(strlen(e.msg) < sizeof e.msg - 1);
    /* the first unnamed surface is the one taken without a name */
    ENSURE(rs_surface_parse(text, "many.inp", NULL, &s, &e) == RS_OK);
    ENSURE(s.profile.nseg == 1 && s.profile.seg[0].p0[1] == 0.0);
    rs_surface_free(&s);
}

/* The example files parse, and their geometry is what their comments say. */
static void test_reader_example_files(void)
{
    rs_surface s;
    rs_error e;
    const char *dir = "../examples/surfaces/";
    char path[256];
    snprintf(path, sizeof path, "%sdrum.inp", dir);
    ENSURE(rs_surface_read(path, "drum", &s, &e) == RS_OK);
    ENSURE(s.kind == RS_SURF_REVOLUTION && s.fillet_radius == 0.005);
    ENSURE(s.profile.nseg == 5); /* three lines and two fillets */
    double x = 0.05, y = 0.0, z = 0.03;
    rs_query q = {.n = 1,
                  .slave = {.x = &x, .y = &y, .z = &z},
                  .pose = NULL,
                  .gap_max = INFINITY,
                  .dist_min = -INFINITY};
    rs_contacts c = {0};
    ENSURE(rs_surface_query(&s, &q, &c, &e) == RS_OK);
    double dmin = INFINITY;
    for (int k = 0; k < c.n; k++)
        dmin = fmin(dmin, c.dist[k]);
    ENSURE_NEAR(dmin, 0.03, 1e-15); /* inside: the caps at 0.03, the mantle at 0.05 */
    rs_surface_free(&s);

    snprintf(path, sizeof path, "%shopper.inp", dir);
    ENSURE(rs_surface_read(path, "hopper", &s, &e) == RS_OK);
    ENSURE(s.profile.nseg == 3);
    ENSURE(s.profile.vkind[1] == RS_VTX_CONVEX && s.profile.vkind[2] == RS_VTX_CONCAVE);
    rs_surface_free(&s);
    ENSURE(rs_surface_read(path, "hopper_round", &s, &e) == RS_OK);
    ENSURE(s.profile.nseg == 5);
    rs_surface_free(&s);

    snprintf(path, sizeof path, "%schute.inp", dir);
    ENSURE(rs_surface_read(path, NULL, &s, &e) == RS_OK);
    ENSURE(s.kind == RS_SURF_CYLINDER && s.bounded && s.profile.vkind[1] == RS_VTX_SMOOTH);
    rs_surface_free(&s);

    snprintf(path, sizeof path, "%splane.inp", dir);
    ENSURE(rs_surface_read(path, "plane", &s, &e) == RS_OK);
    x = 0.2;
    y = 5.0;
    z = 0.3;
    c.n = 0;
    ENSURE(rs_surface_query(&s, &q, &c, &e) == RS_OK);
    ENSURE(c.n == 1);
    ENSURE_NEAR(c.dist[0], 0.3, 1e-15);
    ENSURE_NEAR(c.nrm[2][0], 1.0, 1e-15);
    rs_surface_free(&s);
    rs_contacts_free(&c);
}

static unsigned long long rng_state = 0x2545F4914F6CDD1Dull;
static unsigned rnd(unsigned n)
{
    return (unsigned)((rs_test_xorshift(&rng_state) >> 33) % n);
}

/* Garbage lines and byte mutations: the reader returns a code and a message, never
 * crashes (the sanitizer build checks the memory), and a surface it accepts answers a
 * query. */
static void test_reader_fuzz_never_crashes(void)
{
    static const char *pieces[] = {"*SURFACE, TYPE=SEGMENTS, NAME=f",
                                   "*SURFACE, TYPE=CYLINDER, NAME=g, EXTENT=0,1",
                                   "*SURFACE, TYPE=REVOLUTION, NAME=h, FILLET RADIUS=0.1",
                                   "*surface",
                                   "START, 0, 0",
                                   "LINE, 1, 0",
                                   "LINE, 1, 1",
                                   "CIRCL, 0, 1, 0.5, 0.5",
                                   "PARAB, 0.5, 2, 0, 1",
                                   "0,0,0, 1,0,0",
                                   "0,0,1",
                                   "**",
                                   "",
                                   ",,,,",
                                   "*",
                                   "=,=,=",
                                   "LINE",
                                   "START,1e308,1e308",
                                   "LINE,-1e308,1e308",
                                   "CIRCL,1,1,1,1",
                                   "\t \t",
                                   "*SURFACE,,,,",
                                   "NAME=x",
                                   "LINE,1e-320,0"};
    const int np = (int)(sizeof pieces / sizeof pieces[0]);
    char buf[4096];
    int accepted = 0;
    for (int it = 0; it < 4000; it++) {
        size_t m = 0;
        if (it % 2 == 0) {
            /* a valid file with one garbage line inserted */
            const char *base = GOOD;
            int at = (int)rnd(14), line = 0;
            for (const char *p = base; *p; p++) {
                if (*p == '\n' && ++line == at) {
                    buf[m++] = '\n';
                    const char *g = pieces[rnd((unsigned)np)];
                    memcpy(buf + m, g, strlen(g));
                    m += strlen(g);
                }
                buf[m++] = *p;
            }
            buf[m] = '\0';
            rs_surface s;
            rs_error e;
            int rc = rs_surface_parse(buf, "fuzz", it % 4 ? "chute" : NULL, &s, &e);
            if (rc == RS_OK) {
                accepted++;
                rs_surface_free(&s);
            } else {
                ENSURE(e.code == rc && e.msg[0] != '\0');
            }
            continue;
        }
        int nl = 1 + (int)rnd(12);
        for (int l = 0; l < nl && m < sizeof buf - 200; l++) {
            if (rnd(5) == 0) {
                int len = (int)rnd(40);
                for (int i = 0; i < len; i++)
                    buf[m++] = (char)(1 + rnd(255));
            } else {
                const char *p = pieces[rnd((unsigned)np)];
                size_t pl = strlen(p);
                memcpy(buf + m, p, pl);
                m += pl;
            }
            buf[m++] = '\n';
        }
        buf[m] = '\0';
        /* flip a few bytes */
        for (int f = (int)rnd(3); f > 0 && m > 0; f--)
            buf[rnd((unsigned)m)] = (char)(1 + rnd(255));
        rs_surface s;
        rs_error e;
        rs_error_clear(&e);
        int rc = rs_surface_parse(buf, "fuzz", NULL, &s, &e);
        if (rc == RS_OK) {
            accepted++;
            double x = 0.3, y = 0.2, z = 0.1;
            rs_query q = {.n = 1,
                          .slave = {.x = &x, .y = &y, .z = &z},
                          .pose = NULL,
                          .gap_max = INFINITY,
                          .dist_min = -INFINITY};
            rs_contacts c = {0};
            ENSURE(rs_surface_query(&s, &q, &c, NULL) == RS_OK);
            for (int k = 0; k < c.n; k++)
                ENSURE(isfinite(c.dist[k]) && isfinite(c.nrm[0][k]));
            rs_contacts_free(&c);
            rs_surface_free(&s);
        } else {
            ENSURE(e.code == rc && e.msg[0] != '\0');
            ENSURE(rc == RS_ERR_NOTFOUND || strncmp(e.msg, "fuzz:", 5) == 0);
        }
    }
    ENSURE(accepted > 100);
}

int main(void)
{
    RS_RUN(test_reader_keywords_case_comments_and_names);
    RS_RUN(test_reader_cylinder_c_is_made_normal_to_x);
    RS_RUN(test_reader_bad_input_codes_and_lines);
    RS_RUN(test_reader_missing_file_names_the_path);
    RS_RUN(test_reader_directory_is_named);
    RS_RUN(test_reader_many_unnamed_surfaces);
    RS_RUN(test_reader_example_files);
    RS_RUN(test_reader_fuzz_never_crashes);
    return rs_test_summary();
}
