/* The Abaqus utility routines (librigidsurf_abaqus) and the build of user routines from
 * source (rs_law_build_cached through rs_law_load_vuinter):
 * - XPLB_ABQERR's substitutions, written out by hand;
 * - a VUINTER written as for Abaqus (vuinter_util.f: upper-case include, tabs, lines past
 *   column 72, argument mismatches) built from its source, run on a block, and what the
 *   utilities answered it, checked against the host and block it was given;
 * - the severities: information and warning lines reach the host's message hook, -2
 *   fails the law call with the routine's text, -3, VGETVRM end the run through the
 *   host's fatal hook;
 * - the cache: one library per text, rebuilt when the text or an INCLUDEd file
 *   changes, one compile when two processes build the same routine at once;
 * - failures: a compile error names the file, the line and the compiler's message; a
 *   missing file and a missing compiler say so. */
#define _GNU_SOURCE
#include "rigidsurf/abaqus_util.h"
#include "rigidsurf/law.h"
#include "rigidsurf/law_build.h"

#include "rs_test.h"

#include <dirent.h>
#include <setjmp.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#ifndef RS_ABAQUS_TEST_DIR
#error "RS_ABAQUS_TEST_DIR: the folder of vuinter_util.f"
#endif

/* The Fortran entry points, called from C with their hidden lengths. */
void xplb_abqerr_(const int *lop, const char *string, const int *intv, const double *realv,
                  const char *charv, size_t lstring, size_t lcharv);
void STDB_ABQERR(const int *lop, const char *string, const int *intv, const double *realv,
                 const char *charv, size_t lstring, size_t lcharv);
void xit_(void);
void XPLB_EXIT(void);
void getjobname_(char *jobname, int *len, size_t ljobname);
void GETOUTDIR(char *outdir, int *len, size_t loutdir);
void getnumcpus_(int *n);
void GETRANK(int *k);
void getpartinfo_(const int *num, const int *jtyp, char *part, int *loc, int *jrcd,
                  size_t lpart);

/* ------------------------------------------------------------ a host that records */

static char messages[8][600];
static int nmessages, message_severity[8];
static char fatal_text[600];
static jmp_buf fatal_jump;

static void on_message(void *ctx, int severity, const char *text)
{
    (void)ctx;
    if (nmessages < 8) {
        snprintf(messages[nmessages], sizeof messages[0], "%s", text);
        message_severity[nmessages] = severity;
    }
    ++nmessages;
}

static void on_fatal(void *ctx, const char *text)
{
    (void)ctx;
    snprintf(fatal_text, sizeof fatal_text, "%s", text);
    longjmp(fatal_jump, 1);
}

static void set_host(void)
{
    rs_abq_host h;
    memset(&h, 0, sizeof h);
    h.message = on_message;
    h.fatal = on_fatal;
    h.jobname = "myjob";
    h.outdir = "/some/out/dir";
    h.rank = 3;
    h.ncpus = 5;
    rs_abq_set_host(&h);
    nmessages = 0;
    fatal_text[0] = '\0';
}

static char cache[256];

/* A fresh cache folder for the builds of one test. */
static void fresh_cache(void)
{
    snprintf(cache, sizeof cache, "/tmp/rs_abq_cache_XXXXXX");
    if (!mkdtemp(cache))
        cache[0] = '\0';
    setenv("RIGIDSURF_CACHE", cache, 1);
}

static int count_files(const char *dir, const char *suffix)
{
    DIR *d = opendir(dir);
    if (!d)
        return -1;
    int n = 0;
    size_t ls = strlen(suffix);
    for (struct dirent *e; (e = readdir(d));) {
        size_t l = strlen(e->d_name);
        if (l >= ls && strcmp(e->d_name + l - ls, suffix) == 0)
            ++n;
    }
    closedir(d);
    return n;
}

static void remove_tree(const char *dir)
{
    char cmd[400];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (dir[0] && strncmp(dir, "/tmp/", 5) == 0 && system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", dir);
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}

/* A fresh folder for routines' sources. */
static int source_dir(char dir[256])
{
    snprintf(dir, 256, "/tmp/rs_abq_src_XXXXXX");
    return mkdtemp(dir) != NULL;
}

/* dir/name as path (size 300); with text, the file is written. */
static void source_file(const char *dir, const char *name, const char *text, char path[300])
{
    snprintf(path, 300, "%s/%s", dir, name);
    if (text)
        write_text(path, text);
}

/* ------------------------------------------------------------ a block of 3 contacts */

enum { NC = 3, NSV = 10 };

typedef struct block3 {
    rs_law_block b;
    double rdisp[3 * NC], drdisp[3 * NC], drot[4 * NC], stiff[NC], cond[NC];
    double coordSlv[3 * NC], coordMst[3 * NC], aloc[9 * NC], props[4];
    double stress[3 * NC], fluxSlv[NC], fluxMst[NC], sed[NC], statev[NSV * NC];
    double sfd[NC], scd[NC], spd[NC], svd[NC], radius[NC], mass[NC];
    int uid[NC], feature[NC];
} block3;

static block3 blk;

static const double gap[NC] = {1e-3, -1e-3, 2e-3};
static const int tags[NC] = {7, 8, 9};

static void block_setup(double stiffness, double limit, double vrm, double stop)
{
    memset(&blk, 0, sizeof blk);
    rs_law_block *b = &blk.b;
    rs_law_block_init(b);
    b->nSlvNod = NC;
    b->nDir = 3;
    b->nSurfDir = 2;
    b->nStateVar = NSV;
    b->nProps = 4;
    b->nTemp = 0;
    b->dTimCur = 1e-6;
    for (int k = 0; k < NC; ++k) {
        blk.rdisp[3 * k] = gap[k];
        blk.drot[4 * k] = blk.drot[4 * k + 3] = 1.0;
        for (int i = 0; i < 3; ++i)
            blk.aloc[9 * k + 4 * i] = 1.0;
        blk.radius[k] = 0.002 * (k + 1);
        blk.mass[k] = 1e-4 * (k + 1);
        blk.uid[k] = tags[k];
        blk.feature[k] = 1;
    }
    blk.props[0] = stiffness;
    blk.props[1] = limit;
    blk.props[2] = vrm;
    blk.props[3] = stop;
    b->jSlvUid = blk.uid;
    b->jConMstid = blk.feature;
    b->rdisp = blk.rdisp;
    b->drdisp = blk.drdisp;
    b->drot = blk.drot;
    b->stiffDflt = blk.stiff;
    b->condDflt = blk.cond;
    b->coordSlv = blk.coordSlv;
    b->coordMst = blk.coordMst;
    b->alocaldir = blk.aloc;
    b->props = blk.props;
    b->stress = blk.stress;
    b->fluxSlv = blk.fluxSlv;
    b->fluxMst = blk.fluxMst;
    b->sed = blk.sed;
    b->statev = blk.statev;
    b->sfd = blk.sfd;
    b->scd = blk.scd;
    b->spd = blk.spd;
    b->svd = blk.svd;
    b->radius = blk.radius;
    b->mass = blk.mass;
    rs_law_block_set_name(b->surfInt, "w");
    rs_law_block_set_name(b->surfSlv, "grains");
    rs_law_block_set_name(b->surfMst, "floor");
}

#define UTIL_F RS_ABAQUS_TEST_DIR "/vuinter_util.f"

/* ------------------------------------------------------------ tests */

static void format_substitutes_in_order(void)
{
    const int iv[3] = {42, -7, 0};
    const double rv[3] = {0.5, 0.1, 2.5e-8};
    const char cv[16] = {'a', 'b', 'c', ' ', ' ', ' ', ' ', ' ',
                         'd', 'e', 'f', 'g', 'h', 'i', 'j', 'k'};
    char out[200];
    const char s[] = "I=%I R=%R D=%D S=%S I=%I S=%S R=%R 100%      ";
    rs_abq_format(out, sizeof out, s, sizeof s - 1, iv, rv, cv);
    ENSURE(strcmp(out, "I=42 R=0.5 D=0.10000000000000001 S=abc I=-7 S=defghijk R=2.5e-08 "
                       "100%") == 0);
    /* no arrays: the codes stay as written */
    rs_abq_format(out, sizeof out, "a %I b %R", 9, NULL, NULL, NULL);
    ENSURE(strcmp(out, "a %I b %R") == 0);
    /* truncation keeps a terminated string */
    rs_abq_format(out, 8, s, sizeof s - 1, iv, rv, cv);
    ENSURE(strlen(out) == 7 && strncmp(out, "I=42 R=", 7) == 0);
}

static void info_and_warning_reach_the_host(void)
{
    set_host();
    const int iv[1] = {12};
    const double rv[1] = {1.5};
    const char cv[8] = {'x', ' ', ' ', ' ', ' ', ' ', ' ', ' '};
    int lop = 1;
    const char s1[] = "n %I r %R s %S";
    rs_law_block b;
    rs_law_block_init(&b);
    rs_abq_call_begin(&b, -1, "VUINTER");
    xplb_abqerr_(&lop, s1, iv, rv, cv, sizeof s1 - 1, 8);
    lop = -1;
    xplb_abqerr_(&lop, s1, iv, rv, cv, sizeof s1 - 1, 8);
    rs_error err;
    ENSURE(rs_abq_call_end(&err) == RS_OK);
    ENSURE(nmessages == 2);
    ENSURE(message_severity[0] == RS_ABQ_INFO && message_severity[1] == RS_ABQ_WARNING);
    ENSURE(strcmp(messages[0],
                  "rigidsurf INFO [rank 3] VUINTER (XPLB_ABQERR): n 12 r 1.5 s x") == 0);
    ENSURE(strcmp(messages[1],
                  "rigidsurf WARNING [rank 3] VUINTER (XPLB_ABQERR): n 12 r 1.5 s x") == 0);
    ENSURE(rs_abq_rank() == 3 && rs_abq_ncpus() == 5);
}

static void an_unknown_severity_ends_the_run(void)
{
    set_host();
    int lop = 7;
    const char s[] = "odd";
    if (setjmp(fatal_jump) == 0) {
        xplb_abqerr_(&lop, s, NULL, NULL, NULL, sizeof s - 1, 8);
        ENSURE(0); /* the fatal hook must have been called */
    }
    ENSURE(strstr(fatal_text, "LOP = 7") != NULL);
    ENSURE(strstr(fatal_text, "odd") != NULL);
}

/* The Standard forms and the upper-case C names answer as the V-forms do; XIT and
 * XPLB_EXIT end the run through the host. */
static void standard_forms_and_c_names(void)
{
    set_host();
    char name[256], dir[256], part[80];
    int len = -1, n = -1, loc = -1, jrcd = -1;
    getjobname_(name, &len, sizeof name);
    ENSURE(len == 5 && memcmp(name, "myjob", 5) == 0 && name[5] == ' ' && name[255] == ' ');
    GETOUTDIR(dir, &len, sizeof dir);
    ENSURE(len == 13 && memcmp(dir, "/some/out/dir", 13) == 0);
    getnumcpus_(&n);
    ENSURE(n == 5);
    GETRANK(&n);
    ENSURE(n == 3);
    /* GETPARTINFO: a node of the current call; an element (JTYP = 1) is none */
    block_setup(1.0, 0.0, 0.0, 0.0);
    rs_abq_call_begin(&blk.b, 1, "UINTER");
    const int node = tags[2], zero = 0, one = 1;
    getpartinfo_(&node, &zero, part, &loc, &jrcd, sizeof part);
    ENSURE(jrcd == 0 && loc == tags[2] && memcmp(part, "grains ", 7) == 0);
    getpartinfo_(&node, &one, part, &loc, &jrcd, sizeof part);
    ENSURE(jrcd == 1 && loc == 0);
    const int other = 12345;
    getpartinfo_(&other, &zero, part, &loc, &jrcd, sizeof part);
    ENSURE(jrcd == 1);
    int lop = 1;
    const char s[] = "standard";
    STDB_ABQERR(&lop, s, NULL, NULL, NULL, sizeof s - 1, 8);
    ENSURE(nmessages == 1);
    ENSURE(strcmp(messages[0], "rigidsurf INFO [rank 3] UINTER (STDB_ABQERR): standard") ==
           0);
    rs_error err;
    ENSURE(rs_abq_call_end(&err) == RS_OK);
    if (setjmp(fatal_jump) == 0) {
        xit_();
        ENSURE(0);
    }
    ENSURE(strstr(fatal_text, "called XIT") != NULL);
    fatal_text[0] = '\0';
    if (setjmp(fatal_jump) == 0) {
        XPLB_EXIT();
        ENSURE(0);
    }
    ENSURE(strstr(fatal_text, "called XPLB_EXIT") != NULL);
}

static void routine_from_source_answers_from_host_and_block(void)
{
    set_host();
    fresh_cache();
    rs_law law;
    rs_error err;
    int rc = rs_law_load_vuinter(UTIL_F, &law, &err);
    if (rc)
        fprintf(stderr, "%s\n", err.msg);
    ENSURE(rc == RS_OK);
    ENSURE(count_files(cache, ".so") == 1);
    const double K = 1.0e5;
    block_setup(K, 0.0, 0.0, 0.0);
    rc = rs_law_call(&law, &blk.b, &err);
    if (rc)
        fprintf(stderr, "%s\n", err.msg);
    ENSURE(rc == RS_OK);
    for (int k = 0; k < NC; ++k) {
        const double *sv = blk.statev + NSV * k;
        ENSURE(blk.stress[3 * k] == (gap[k] > 0.0 ? K * gap[k] : 0.0));
        ENSURE(sv[0] == 1.0);
        ENSURE(sv[1] == 3.0 && sv[2] == 5.0);     /* rank, rank count */
        ENSURE(sv[3] == tags[k] && sv[4] == 0.0); /* VGETPARTINFO: tag, JRCD */
        ENSURE(sv[5] == 6.0);                     /* "grains" */
        ENSURE(sv[6] == blk.radius[k] && sv[7] == blk.mass[k]);
        ENSURE(sv[8] == 5.0); /* "myjob" */
        ENSURE(sv[9] == (double)strlen("/some/out/dir"));
    }
    ENSURE(nmessages == NC);
    for (int k = 0; k < NC; ++k) {
        char want[300];
        snprintf(want, sizeof want,
                 "rigidsurf INFO [rank 3] VUINTER (XPLB_ABQERR): job myjob ranks 5 rank 3 "
                 "part grains node %d dem 0 radius %g mass %g",
                 tags[k], blk.radius[k], blk.mass[k]);
        if (strcmp(messages[k], want) != 0)
            fprintf(stderr, "got  %s\nwant %s\n", messages[k], want);
        ENSURE(strcmp(messages[k], want) == 0);
    }
    /* seen contacts stay quiet */
    nmessages = 0;
    ENSURE(rs_law_call(&law, &blk.b, &err) == RS_OK);
    ENSURE(nmessages == 0);
    /* the same text loads from the cache: no second library */
    rs_law again;
    ENSURE(rs_law_load_vuinter(UTIL_F, &again, &err) == RS_OK);
    ENSURE(count_files(cache, ".so") == 1);
    rs_law_unload(&again);
    rs_law_unload(&law);
    remove_tree(cache);
}

static void error_severity_fails_the_call(void)
{
    set_host();
    fresh_cache();
    rs_law law;
    rs_error err;
    ENSURE(rs_law_load_vuinter(UTIL_F, &law, &err) == RS_OK);
    /* limit 1.5e-3: contact 1 (1e-3) is past half of it, contact 3 (2e-3) beyond it */
    block_setup(1.0e5, 1.5e-3, 0.0, 0.0);
    for (int k = 0; k < NC; ++k)
        blk.statev[NSV * k] = 1.0; /* no information lines */
    int rc = rs_law_call(&law, &blk.b, &err);
    ENSURE(rc == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "VUINTER raised an error") != NULL);
    ENSURE(strstr(err.msg, "penetration 0.002 exceeds the limit 0.0015 at node 9") != NULL);
    ENSURE(nmessages == 1);
    ENSURE(strcmp(messages[0],
                  "rigidsurf WARNING [rank 3] VUINTER (XPLB_ABQERR): penetration "
                  "0.001 is past half the limit 0.0015 at node 7") == 0);
    /* the error does not outlive its call */
    block_setup(1.0e5, 0.0, 0.0, 0.0);
    for (int k = 0; k < NC; ++k)
        blk.statev[NSV * k] = 1.0;
    ENSURE(rs_law_call(&law, &blk.b, &err) == RS_OK);
    rs_law_unload(&law);
    remove_tree(cache);
}

static void fatal_calls_end_the_run(void)
{
    set_host();
    fresh_cache();
    rs_law law;
    rs_error err;
    ENSURE(rs_law_load_vuinter(UTIL_F, &law, &err) == RS_OK);
    block_setup(1.0e5, 0.0, 1.0, 0.0); /* VGETVRM */
    for (int k = 0; k < NC; ++k)
        blk.statev[NSV * k] = 1.0;
    if (setjmp(fatal_jump) == 0) {
        rs_law_call(&law, &blk.b, &err);
        ENSURE(0);
    }
    ENSURE(strstr(fatal_text, "VGETVRM('SDV')") != NULL);
    ENSURE(strstr(fatal_text, "VUINTER") != NULL);
    block_setup(1.0e5, 0.0, 0.0, 1.0); /* LOP = -3 on the first contact */
    fatal_text[0] = '\0';
    if (setjmp(fatal_jump) == 0) {
        rs_law_call(&law, &blk.b, &err);
        ENSURE(0);
    }
    ENSURE(strstr(fatal_text, "stop now at node 7") != NULL);
    rs_law_unload(&law);
    remove_tree(cache);
}

static void dem_fields_of_the_current_call(void)
{
    double f[8];
    rs_abq_call_end(NULL);
    ENSURE(rs_abq_dem_fields(1, f) == 1); /* no call */
    block_setup(1.0, 0.0, 0.0, 0.0);
    double vrel[3 * NC], curv[2 * NC], reff[NC];
    for (int i = 0; i < 3 * NC; ++i)
        vrel[i] = 0.25 * (i + 1);
    for (int i = 0; i < 2 * NC; ++i)
        curv[i] = 10.0 * (i + 1);
    for (int k = 0; k < NC; ++k)
        reff[k] = 0.5 * blk.radius[k];
    blk.b.vrel = vrel;
    blk.b.curv = curv;
    blk.b.reff = reff;
    rs_abq_call_begin(&blk.b, -1, "VUINTER");
    ENSURE(rs_abq_dem_fields(2, f) == 0);
    const double want[8] = {blk.radius[1], blk.mass[1], reff[1], vrel[3],
                            vrel[4],       vrel[5],     curv[2], curv[3]};
    for (int i = 0; i < 8; ++i)
        ENSURE(f[i] == want[i]);
    ENSURE(rs_abq_dem_fields(0, f) == 1 && rs_abq_dem_fields(NC + 1, f) == 1);
    ENSURE(f[0] == 0.0 && f[1] == 0.0);
    rs_abq_call_end(NULL);
    /* a point-wise routine on contact 2 asks for node 1 */
    rs_abq_call_begin(&blk.b, 2, "FRIC");
    ENSURE(rs_abq_dem_fields(1, f) == 0 && f[0] == blk.radius[2] && f[3] == vrel[6]);
    ENSURE(rs_abq_dem_fields(2, f) == 1);
    rs_abq_call_end(NULL);
}

static void cache_follows_text_and_includes(void)
{
    set_host();
    fresh_cache();
    char src_dir[256];
    ENSURE(source_dir(src_dir));
    char main_f[300], inc_f[300];
    source_file(src_dir, "law.f", NULL, main_f);
    source_file(src_dir, "consts.inc", "      PARAMETER (AK = 3.0D0)\n", inc_f);
    const char *text = "      SUBROUTINE VUINTER(SFD,SCD,SPD,SVD,STRESS)\n"
                       "      INCLUDE 'VABA_PARAM.INC'\n"
                       "      INCLUDE 'consts.inc'\n"
                       "      STRESS = AK\n"
                       "      END\n";
    write_text(main_f, text);
    char p1[4096], p2[4096], p3[4096];
    rs_error err;
    ENSURE(rs_law_build_cached(main_f, p1, sizeof p1, &err) == RS_OK);
    ENSURE(rs_law_build_cached(main_f, p2, sizeof p2, &err) == RS_OK);
    ENSURE(strcmp(p1, p2) == 0);
    write_text(inc_f, "      PARAMETER (AK = 4.0D0)\n");
    ENSURE(rs_law_build_cached(main_f, p3, sizeof p3, &err) == RS_OK);
    ENSURE(strcmp(p1, p3) != 0);
    ENSURE(count_files(cache, ".so") == 2);
    remove_tree(src_dir);
    remove_tree(cache);
}

static void two_processes_compile_once(void)
{
    fresh_cache();
    char src_dir[256];
    ENSURE(source_dir(src_dir));
    char main_f[300];
    source_file(src_dir, "twice.f",
                "      SUBROUTINE VUINTER(X)\n      INCLUDE 'VABA_PARAM.INC'\n"
                "      X = 1.0D0\n      END\n",
                main_f);
    pid_t kids[2];
    for (int i = 0; i < 2; ++i) {
        kids[i] = fork();
        ENSURE(kids[i] >= 0);
        if (kids[i] == 0) {
            char p[4096];
            rs_error e;
            _exit(rs_law_build_cached(main_f, p, sizeof p, &e) == RS_OK ? 0 : 1);
        }
    }
    for (int i = 0; i < 2; ++i) {
        int status = 0;
        ENSURE(waitpid(kids[i], &status, 0) == kids[i]);
        ENSURE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    }
    /* one library and one compiler log: the second process found the first's result */
    ENSURE(count_files(cache, ".so") == 1);
    ENSURE(count_files(cache, ".so.log") == 1);
    remove_tree(src_dir);
    remove_tree(cache);
}

static void build_failures_say_why(void)
{
    set_host();
    fresh_cache();
    char src_dir[256];
    ENSURE(source_dir(src_dir));
    char bad[300];
    source_file(src_dir, "broken.f",
                "      SUBROUTINE VUINTER(X)\n      INCLUDE 'VABA_PARAM.INC'\n"
                "      X = = 1.0D0\n      END\n",
                bad);
    rs_law law;
    rs_error err;
    ENSURE(rs_law_load_vuinter(bad, &law, &err) == RS_ERR_PARSE);
    ENSURE(strstr(err.msg, "broken.f:3:") != NULL); /* the file and the line */
    ENSURE(strstr(err.msg, "Error") != NULL);       /* the compiler's message */
    ENSURE(count_files(cache, ".so") == 0);

    char missing[300];
    source_file(src_dir, "absent.f", NULL, missing);
    ENSURE(rs_law_load_vuinter(missing, &law, &err) == RS_ERR_IO);
    ENSURE(strstr(err.msg, "absent.f: cannot read") != NULL);

    char good[300];
    /* Abaqus/Explicit's 49 arguments: the loader checks the list */
    source_file(src_dir, "good.f",
                "      SUBROUTINE VUINTER(sfd, scd, spd, svd, stress, fluxSlv, fluxMst,\n"
                "     1 sed, statev, kStep, kInc, nFacNod, nSlvNod, nMstNod, nSurfDir,\n"
                "     2 nDir, nStateVar, nProps, nTemp, nPred, numDefTfv, jSlvUid,\n"
                "     3 jMstUid, jConMstid, timStep, timGlb, dTimCur, surfInt, surfSlv,\n"
                "     4 surfMst, rdisp, drdisp, drot, stiffDflt, condDflt, shape,\n"
                "     5 coordSlv, coordMst, alocaldir, props, areaSlv, tempSlv,\n"
                "     6 dtempSlv, preDefSlv, dpreDefSlv, tempMst, dtempMst, preDefMst,\n"
                "     7 dpreDefMst)\n"
                "      X = 1.0D0\n      END\n",
                good);
    setenv("RIGIDSURF_FC", "/nonexistent/gfortran", 1);
    ENSURE(rs_law_load_vuinter(good, &law, &err) == RS_ERR_IO);
    ENSURE(strstr(err.msg, "/nonexistent/gfortran") != NULL);
    ENSURE(strstr(err.msg, "install gfortran") != NULL);
    unsetenv("RIGIDSURF_FC");
    ENSURE(rs_law_load_vuinter(good, &law, &err) == RS_OK);
    rs_law_unload(&law);
    remove_tree(src_dir);
    remove_tree(cache);
}

int main(void)
{
    RS_RUN(format_substitutes_in_order);
    RS_RUN(info_and_warning_reach_the_host);
    RS_RUN(an_unknown_severity_ends_the_run);
    RS_RUN(standard_forms_and_c_names);
    RS_RUN(routine_from_source_answers_from_host_and_block);
    RS_RUN(error_severity_fails_the_call);
    RS_RUN(fatal_calls_end_the_run);
    RS_RUN(dem_fields_of_the_current_call);
    RS_RUN(cache_follows_text_and_includes);
    RS_RUN(two_processes_compile_once);
    RS_RUN(build_failures_say_why);
    return rs_test_summary();
}
