/* User routines from source with each argument list the loaders accept, built with
 * gfortran through rs_law_load_*:
 * - a UINTER with the older list (no DVISCOUS, DSTRUCTURAL, FREQR), loaded by
 *   rs_law_load_uinter with no further word, and the same routine with the current
 *   list (free form, lower case, DVISCOUS and DSTRUCTURAL named AMKI and AMSKI): both
 *   see the block's KINC, NDIR, AREA, NODE, NPROPS, DTIME, MCRD, KSTEP and RDISP(1)
 *   where the block put them, and return the same stress;
 * - a VUINTER and a FRIC with Abaqus's lists load;
 * - a list that matches none (issue 32's UINTER: the current list less DVISCOUS and
 *   DSTRUCTURAL; a VUINTER with one argument missing; a FRIC with one too many) is an
 *   error naming the file, the line and the count, and loads nothing;
 * - the compiler's warnings (a REAL DO variable, a REAL array index) reach the law:
 *   their count, the first with its file and line, the log; again when the library
 *   comes from the cache; none for a clean routine; no record for a library. */
#define _GNU_SOURCE
#include "rigidsurf/law.h"
#include "rigidsurf/law_build.h"

#include "rs_test.h"
#include "test_law_fixture.h"

#include <stdlib.h>
#include <unistd.h>

static char dir[64], cache[64];

static void write_source(const char *name, const char *text, char *path, size_t size)
{
    snprintf(path, size, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}

/* What the probe routines below write into STATEV(1:8). */
#define PROBE_BODY                                                                         \
    "      stress(1) = props(1)*max(rdisp(1), 0.d0)\n"                                     \
    "      statev(1) = kinc\n"                                                             \
    "      statev(2) = ndir\n"                                                             \
    "      statev(3) = area\n"                                                             \
    "      statev(4) = node\n"                                                             \
    "      statev(5) = nprops\n"                                                           \
    "      statev(6) = dtime\n"                                                            \
    "      statev(7) = mcrd\n"                                                             \
    "      statev(8) = kstep\n"

static const char *const UINTER_OLDER =
    "c     UINTER, the older list: no DVISCOUS, DSTRUCTURAL, FREQR\n"
    "      subroutine uinter(stress,ddsddr,flux,ddfddt,ddsddt,ddfddr,\n"
    "     1 statev,sed,sfd,spd,svd,scd,pnewdt,rdisp,drdisp,\n"
    "     2 temp,dtemp,predef,dpred,time,dtime,ciname,slname,msname,\n"
    "     3 props,coords,alocaldir,drot,area,chrlngth,node,ndir,nstatv,\n"
    "     4 npred,nprops,mcrd,kstep,kinc,kit,linper,lopenclose,lstate,\n"
    "     5 lsdi,lprint)\n"
    "      include 'aba_param.inc'\n"
    "      character*80 ciname,slname,msname\n"
    "      dimension stress(ndir),rdisp(ndir),statev(nstatv),props(nprops)\n" PROBE_BODY
    "      return\n"
    "      end\n";

static const char *const UINTER_CURRENT_FREE =
    "! UINTER, the current list, with DVISCOUS and DSTRUCTURAL as AMKI and AMSKI\n"
    "subroutine UInter(stress, ddsddr, amki, amski, flux, ddfddt, ddsddt, & ! tangents\n"
    "    ddfddr, statev, sed, sfd, spd, svd, scd, pnewdt, rdisp, drdisp, &\n"
    "    temp, dtemp, predef, dpred, time, dtime, freqr, ciname, slname, msname, &\n"
    "    props, coords, alocaldir, drot, area, chrlngth, node, ndir, nstatv, &\n"
    "    npred, nprops, mcrd, kstep, kinc, kit, linper, lopenclose, lstate, lsdi, lprint)\n"
    "      include 'aba_param.inc'\n"
    "      character*80 ciname,slname,msname\n"
    "      dimension stress(ndir),rdisp(ndir),statev(nstatv),props(nprops)\n" PROBE_BODY
    "end subroutine uinter\n";

/* Runs a probe UINTER on two contacts and checks what it saw. */
static void probe_uinter(const char *src)
{
    rs_law law;
    rs_error err;
    ENSURE(rs_law_load_uinter(src, NULL, &law, &err) == RS_OK);
    static law_fix f;
    const double k = 2.0e4;
    law_fix_init(&f, NULL, &k, 1, 2, 3);
    f.b.nStateVar = law.nstatev + 8; /* the routine's NSTATV = 8, first */
    f.b.kStep = 2;
    f.b.kInc = 3;
    f.b.dTimCur = 2.5e-6;
    const double h[2] = {4e-5, -1e-5};
    for (int c = 0; c < 2; ++c) {
        RS_A2(f.rdisp, 3, 0, c) = h[c];
        f.area[c] = 0.5 + c;
    }
    ENSURE(rs_law_call(&law, &f.b, &err) == RS_OK);
    for (int c = 0; c < 2; ++c) {
        const double *sv = f.statev + (size_t)c * (size_t)f.b.nStateVar;
        ENSURE(RS_A2(f.stress, 3, 0, c) == k * fmax(h[c], 0.0));
        ENSURE(sv[0] == 3.0);       /* KINC */
        ENSURE(sv[1] == 3.0);       /* NDIR */
        ENSURE(sv[2] == 0.5 + c);   /* AREA */
        ENSURE(sv[3] == 100.0 + c); /* NODE: the particle id */
        ENSURE(sv[4] == 1.0);       /* NPROPS */
        ENSURE(sv[5] == 2.5e-6);    /* DTIME */
        ENSURE(sv[6] == 3.0);       /* MCRD */
        ENSURE(sv[7] == 2.0);       /* KSTEP */
    }
    rs_law_unload(&law);
}

static void older_uinter_list_gets_its_adapter(void)
{
    char p[128];
    write_source("uinter_older.f", UINTER_OLDER, p, sizeof p);
    probe_uinter(p);
}

static void current_uinter_list_in_free_form(void)
{
    char p[128];
    write_source("uinter_current.f90", UINTER_CURRENT_FREE, p, sizeof p);
    probe_uinter(p);
}

static const char *const VUINTER_49 =
    "      SUBROUTINE VUINTER(sfd, scd, spd, svd, stress, fluxSlv, fluxMst, sed,\n"
    "     1 statev, kStep, kInc, nFacNod, nSlvNod, nMstNod, nSurfDir, nDir,\n"
    "     2 nStateVar, nProps, nTemp, nPred, numDefTfv, jSlvUid, jMstUid,\n"
    "     3 jConMstid, timStep, timGlb, dTimCur, surfInt, surfSlv, surfMst,\n"
    "     4 rdisp, drdisp, drot, stiffDflt, condDflt, shape, coordSlv, coordMst,\n"
    "     5 alocaldir, props, areaSlv, tempSlv, dtempSlv, preDefSlv, dpreDefSlv,\n"
    "     6 tempMst, dtempMst, preDefMst, dpreDefMst)\n"
    "      INCLUDE 'VABA_PARAM.INC'\n"
    "      CHARACTER*80 surfInt, surfSlv, surfMst\n";

static const char *const FRIC_39 =
    "      SUBROUTINE FRIC(LM,TAU,DDTDDG,DDTDDP,DSLIP,SED,SFD,\n"
    "     1 DDTDDT,PNEWDT,STATEV,DGAM,TAULM,PRESS,DPRESS,DDPDDH,SLIP,\n"
    "     2 KSTEP,KINC,TIME,DTIME,NOEL,CINAME,SLNAME,MSNAME,NPT,NODE,\n"
    "     3 NPATCH,COORDS,RCOORD,DROT,TEMP,PREDEF,NFDIR,MCRD,NPRED,\n"
    "     4 NSTATV,CHRLNGTH,PROPS,NPROPS%s)\n"
    "      INCLUDE 'ABA_PARAM.INC'\n"
    "      LM = 2\n"
    "      END\n";

static void vuinter_and_fric_lists_load(void)
{
    char text[2048], p[128];
    rs_law law;
    rs_error err;
    snprintf(text, sizeof text, "%s      END\n", VUINTER_49);
    write_source("vuinter.f", text, p, sizeof p);
    ENSURE(rs_law_load_vuinter(p, &law, &err) == RS_OK);
    rs_law_unload(&law);
    snprintf(text, sizeof text, FRIC_39, "");
    write_source("fric.f", text, p, sizeof p);
    ENSURE(rs_law_load_fric(p, rs_law_find("linear_softening"), &law, &err) == RS_OK);
    rs_law_unload(&law);
}

/* The law is left zeroed and the message names file, line and counts. */
static void refused(int rc, const rs_law *law, const rs_error *err, const char *where,
                    int found, const char *expected)
{
    ENSURE(rc == RS_ERR_ARG);
    ENSURE(law->update == NULL && law->ctx == NULL);
    char want[200];
    snprintf(want, sizeof want, "%s has %d arguments", where, found);
    ENSURE(strstr(err->msg, want) != NULL);
    ENSURE(strstr(err->msg, expected) != NULL);
}

static void lists_that_match_none_are_refused(void)
{
    char text[2048], p[128], where[200];
    rs_law law;
    rs_error err;
    /* issue 32's routine: the current list less DVISCOUS and DSTRUCTURAL */
    write_source("uinter45.f",
                 "C     a UINTER without DVISCOUS and DSTRUCTURAL, with FREQR\n"
                 "\n"
                 "      SUBROUTINE UINTER(STRESS,DDSDDR,FLUX,DDFDDT,\n"
                 "     1 DDSDDT,DDFDDR,STATEV,SED,SFD,SPD,SVD,SCD,PNEWDT,RDISP,\n"
                 "     2 DRDISP,TEMP,DTEMP,PREDEF,DPRED,TIME,DTIME,FREQR,CINAME,\n"
                 "     3 SLNAME,MSNAME,PROPS,COORDS,ALOCALDIR,DROT,AREA,CHRLNGTH,\n"
                 "     4 NODE,NDIR,NSTATV,NPRED,NPROPS,MCRD,KSTEP,KINC,KIT,LINPER,\n"
                 "     5 LOPENCLOSE,LSTATE,LSDI,LPRINT)\n"
                 "      INCLUDE 'ABA_PARAM.INC'\n"
                 "      END\n",
                 p, sizeof p);
    memset(&law, 0, sizeof law);
    snprintf(where, sizeof where, "%s:3: SUBROUTINE UINTER", p);
    refused(rs_law_load_uinter(p, NULL, &law, &err), &law, &err, where, 45, "with 47 (");
    ENSURE(strstr(err.msg, " or 44 (") != NULL);
    /* a VUINTER with one argument missing (dpreDefMst) */
    snprintf(text, sizeof text, "%s      END\n", VUINTER_49);
    char *gone = strstr(text, ", dpreDefMst");
    memmove(gone, gone + 12, strlen(gone + 12) + 1);
    write_source("vuinter48.f", text, p, sizeof p);
    snprintf(where, sizeof where, "%s:1: SUBROUTINE VUINTER", p);
    refused(rs_law_load_vuinter(p, &law, &err), &law, &err, where, 48, "with 49 (");
    /* a FRIC with one too many */
    snprintf(text, sizeof text, FRIC_39, ",EXTRA");
    write_source("fric40.f", text, p, sizeof p);
    snprintf(where, sizeof where, "%s:1: SUBROUTINE FRIC", p);
    refused(rs_law_load_fric(p, rs_law_find("linear_softening"), &law, &err), &law, &err,
            where, 40, "with 39 (");
}

static void compiler_warnings_reach_the_law(void)
{
    char text[4096], p[128];
    rs_law law;
    rs_error err;
    /* line 12: a REAL DO variable (a deleted feature); line 15: a REAL index */
    snprintf(text, sizeof text,
             "%s"
             "      DIMENSION stress(nDir,nSlvNod), props(nProps)\n"
             "      S = 0.D0\n"
             "      DO R = 1, 3\n"
             "        S = S + R\n"
             "      END DO\n"
             "      stress(1, 1) = props(S / 6.D0)\n"
             "      END\n",
             VUINTER_49);
    write_source("warns.f", text, p, sizeof p);
    for (int pass = 0; pass < 2; ++pass) { /* built, then found in the cache */
        ENSURE(rs_law_load_vuinter(p, &law, &err) == RS_OK);
        const rs_build_warnings *w = rs_law_warnings(&law);
        ENSURE(w != NULL);
        ENSURE(w->count == 2);
        char want[160];
        snprintf(want, sizeof want, "%s:12:", p);
        ENSURE(strncmp(w->first, want, strlen(want)) == 0);
        ENSURE(strstr(w->first, "Warning: Deleted feature: Loop variable") != NULL);
        ENSURE(strncmp(w->log, cache, strlen(cache)) == 0);
        ENSURE(strstr(w->log, "/warns-") && strstr(w->log, ".so.log"));
        ENSURE(access(w->log, R_OK) == 0);
        rs_law_unload(&law);
    }
    /* a clean routine: a record without warnings */
    snprintf(text, sizeof text, "%s      END\n", VUINTER_49);
    write_source("clean.f", text, p, sizeof p);
    ENSURE(rs_law_load_vuinter(p, &law, &err) == RS_OK);
    ENSURE(rs_law_warnings(&law) != NULL && rs_law_warnings(&law)->count == 0);
    ENSURE(rs_law_warnings(&law)->first[0] == '\0');
    rs_law_unload(&law);
    /* a built-in law has no record */
    ENSURE(rs_law_warnings(rs_law_find("hertz")) == NULL);
    ENSURE(rs_law_warnings(NULL) == NULL);
    /* nor has a missing log */
    rs_build_warnings none;
    rs_law_build_read_warnings("/nonexistent/x.so.log", &none);
    ENSURE(none.count == 0 && none.first[0] == '\0');
}

int main(void)
{
    snprintf(dir, sizeof dir, "/tmp/rs_lists_XXXXXX");
    snprintf(cache, sizeof cache, "/tmp/rs_lists_cache_XXXXXX");
    if (!mkdtemp(dir) || !mkdtemp(cache)) {
        perror("mkdtemp");
        return 1;
    }
    setenv("RIGIDSURF_CACHE", cache, 1);
    RS_RUN(older_uinter_list_gets_its_adapter);
    RS_RUN(current_uinter_list_in_free_form);
    RS_RUN(vuinter_and_fric_lists_load);
    RS_RUN(lists_that_match_none_are_refused);
    RS_RUN(compiler_warnings_reach_the_law);
    char cmd[200];
    snprintf(cmd, sizeof cmd, "rm -rf '%s' '%s'", dir, cache);
    if (system(cmd) != 0)
        fprintf(stderr, "could not remove %s, %s\n", dir, cache);
    return rs_test_summary();
}
