/* The SUBROUTINE statement reader (src/law_signature.c) against lists written here with
 * known counts: fixed form (label, column-6 and tab continuations, comment lines, '!'
 * comments, column 132, blanks inside names), free form ('&' continuations, comments,
 * ';'), any case, the routine among others, INCLUDEd files; malformed lists and bad
 * input give errors naming the file and line, never a crash. rs_law_source_list
 * against Abaqus's documented lists: each supported one, one argument missing, one too
 * many, and the repository's own routines. */
#define _GNU_SOURCE
#include "law_signature.h"

#include "rs_test.h"

#include <stdlib.h>
#include <unistd.h>

static rs_fsub sub;
static rs_error err;

static int scan_fixed(const char *text, const char *name)
{
    return rs_fsub_scan(text, strlen(text), 0, "t.f", name, &sub, &err);
}

static int scan_free(const char *text, const char *name)
{
    return rs_fsub_scan(text, strlen(text), 1, "t.f90", name, &sub, &err);
}

static void fixed_form_continuations_and_comments(void)
{
    const char *text = "C     a comment line\n"
                       "c     another\n"
                       "*     and another\n"
                       "!     and one more\n"
                       "\n"
                       "      subroutine Uinter(STRESS, ddsddr, ! the first two\n"
                       "     1 FLUX,\n"
                       "C     a comment between continuation lines\n"
                       "\n"
                       "     & DdFdDt ,\n"
                       "     * STATEV)\n"
                       "      INCLUDE 'ABA_PARAM.INC'\n"
                       "      END\n";
    ENSURE(scan_fixed(text, "uinter") == RS_OK);
    ENSURE(sub.nargs == 5 && sub.line == 6 && strcmp(sub.file, "t.f") == 0);
    ENSURE(scan_fixed(text, "UINTER") == RS_OK && sub.nargs == 5);
    /* a label in columns 1-5, '!' in column 6 continues, '0' in column 6 does not */
    text = "  100 SUBROUTINE FRIC(A,\n"
           "     !B,C)\n";
    ENSURE(scan_fixed(text, "fric") == RS_OK && sub.nargs == 3 && sub.line == 1);
    text = "      SUBROUTINE FRIC(A,\n"
           "     0B,C)\n";
    ENSURE(scan_fixed(text, "fric") == RS_ERR_PARSE);
    ENSURE(strstr(err.msg, "t.f:1:") && strstr(err.msg, "not closed"));
}

static void fixed_form_tabs_columns_and_blanks(void)
{
    /* a tab starts the statement; a tab and a digit 1-9 continue it (DEC's form) */
    ENSURE(scan_fixed("\tSUBROUTINE VUINTER(A,\n\t1B,\n  10\t2C)\n", "vuinter") == RS_OK);
    ENSURE(sub.nargs == 3 && sub.line == 1);
    /* text past column 132 is not read */
    char longline[400];
    snprintf(longline, sizeof longline, "%-132s,EXTRA\n     1 )\n",
             "      SUBROUTINE FRIC(A,B");
    ENSURE(scan_fixed(longline, "fric") == RS_OK && sub.nargs == 2);
    /* blanks are not significant in fixed form */
    ENSURE(scan_fixed("      SUB ROUTINE VU INTER (A B, C D)\n", "vuinter") == RS_OK);
    ENSURE(sub.nargs == 2);
    /* a CRLF file */
    ENSURE(scan_fixed("      SUBROUTINE FRIC(A,\r\n     1 B)\r\n", "fric") == RS_OK);
    ENSURE(sub.nargs == 2);
}

static void free_form_continuations_and_comments(void)
{
    const char *text = "! a free-form routine\n"
                       "module m\n"
                       "contains\n"
                       "  subroutine helper(x)\n"
                       "  end subroutine helper\n"
                       "  Subroutine VUinter(sfd, scd, & ! energies\n"
                       "     ! a comment line inside the statement\n"
                       "\n"
                       "     & spd, svd, &\n"
                       "     stress)\n"
                       "  end subroutine vuinter\n"
                       "end module m\n";
    ENSURE(scan_free(text, "vuinter") == RS_OK);
    ENSURE(sub.nargs == 5 && sub.line == 6);
    /* ';' separates statements; strings hide '!', ';' and '&' */
    text = "x = 'a ! b ; c &'; recursive subroutine fric(lm, tau); implicit none\n";
    ENSURE(scan_free(text, "fric") == RS_OK && sub.nargs == 2 && sub.line == 1);
    /* blanks are significant in free form, so they split names */
    ENSURE(scan_free("subroutine fric (a, b c)\n", "fric") == RS_OK && sub.nargs == 2);
    /* a routine without arguments */
    ENSURE(scan_free("subroutine fric\nend\n", "fric") == RS_OK && sub.nargs == 0);
    ENSURE(scan_free("subroutine fric()\nend\n", "fric") == RS_OK && sub.nargs == 0);
}

static void the_routine_among_others(void)
{
    const char *text = "      SUBROUTINE UINTER2(A)\n"
                       "      END\n"
                       "      SUBROUTINE HELPER(A)\n"
                       "      CALL UINTER(A, B, C)\n"
                       "      END SUBROUTINE UINTER\n"
                       "      END\n"
                       "      SUBROUTINE UINTER(A, B)\n"
                       "      END\n";
    ENSURE(scan_fixed(text, "uinter") == RS_OK && sub.nargs == 2 && sub.line == 7);
    ENSURE(scan_fixed(text, "uinter2") == RS_OK && sub.nargs == 1 && sub.line == 1);
    ENSURE(scan_fixed(text, "fric") == RS_ERR_NOTFOUND);
    ENSURE(strstr(err.msg, "t.f: no SUBROUTINE FRIC statement") != NULL);
}

static void malformed_lists_name_the_line(void)
{
    /* a continuation mark missing: the list is not closed */
    const char *text = "\n      SUBROUTINE VUINTER(A, B,\n      C)\n";
    ENSURE(scan_fixed(text, "vuinter") == RS_ERR_PARSE);
    ENSURE(strstr(err.msg, "t.f:2: SUBROUTINE VUINTER") && strstr(err.msg, "not closed"));
    ENSURE(scan_fixed("      SUBROUTINE VUINTER(A,,B)\n", "vuinter") == RS_ERR_PARSE);
    ENSURE(strstr(err.msg, "t.f:1:") && strstr(err.msg, "argument 2, empty"));
    ENSURE(scan_fixed("      SUBROUTINE VUINTER(A,B(3))\n", "vuinter") == RS_ERR_PARSE);
    ENSURE(strstr(err.msg, "argument 2") != NULL);
    /* the file ends inside the statement */
    ENSURE(scan_free("subroutine fric(a, &", "fric") == RS_ERR_PARSE);
    ENSURE(scan_free("subroutine fric(a, 'b", "fric") == RS_ERR_PARSE);
    ENSURE(scan_fixed("", "fric") == RS_ERR_NOTFOUND);
    ENSURE(rs_fsub_scan(NULL, 0, 0, "t.f", "fric", &sub, &err) == RS_ERR_NOTFOUND);
    ENSURE(rs_fsub_scan("x", 1, 0, "t.f", "", &sub, &err) == RS_ERR_ARG);
}

static void bad_input_never_crashes(void)
{
    static const char alphabet[] = "SUBROUTINEFRICfric(),&!;'\"\n\t C1#*0\r\0";
    unsigned long long state = 77;
    char text[600];
    for (int round = 0; round < 3000; ++round) {
        size_t n = (size_t)(rs_test_xorshift(&state) % sizeof text);
        for (size_t i = 0; i < n; ++i)
            text[i] = alphabet[rs_test_xorshift(&state) % (sizeof alphabet - 1)];
        if (round % 3 == 0 && n > 30)
            memcpy(text + 5, " SUBROUTINE FRIC(", 17);
        for (int form = 0; form < 2; ++form) {
            int rc = rs_fsub_scan(text, n, form, "t.f", "fric", &sub, &err);
            ENSURE(rc == RS_OK || rc == RS_ERR_NOTFOUND || rc == RS_ERR_PARSE);
            ENSURE(rc != RS_OK || (sub.nargs >= 0 && sub.line >= 1));
            ENSURE(rc == RS_OK || err.msg[0] != '\0');
        }
    }
}

/* ------------------------------------------------------------ files */

static char dir[64];

static void write_file(const char *name, const char *text, char *path, size_t size)
{
    snprintf(path, size, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}

static void included_files_are_read(void)
{
    char main_f[128], part[128];
    write_file("part.f",
               "C     the routine itself\n      SUBROUTINE FRIC(A,B,C)\n      END\n", part,
               sizeof part);
    write_file("main.f", "      INCLUDE 'ABA_PARAM.INC'\n      INCLUDE 'part.f'\n", main_f,
               sizeof main_f);
    ENSURE(rs_fsub_read(main_f, "fric", &sub, &err) == RS_OK);
    ENSURE(sub.nargs == 3 && sub.line == 2 && strcmp(sub.file, part) == 0);
    write_file("cpp.F", "#include \"part.f\"\n", main_f, sizeof main_f);
    ENSURE(rs_fsub_read(main_f, "fric", &sub, &err) == RS_OK && sub.nargs == 3);
    /* a file that includes itself ends at the depth limit */
    write_file("self.f", "      INCLUDE 'self.f'\n", main_f, sizeof main_f);
    ENSURE(rs_fsub_read(main_f, "fric", &sub, &err) == RS_ERR_NOTFOUND);
    ENSURE(rs_fsub_read("absent.f", "fric", &sub, &err) == RS_ERR_IO);
    ENSURE(strstr(err.msg, "absent.f: cannot read") != NULL);
    ENSURE(rs_fsub_read(dir, "fric", &sub, &err) == RS_ERR_ARG);
}

/* Abaqus's documented lists (the Abaqus User Subroutines Reference Guide). */
static const char *const VUINTER_ARGS[] = {
    "sfd",       "scd",       "spd",        "svd",       "stress",    "fluxSlv",
    "fluxMst",   "sed",       "statev",     "kStep",     "kInc",      "nFacNod",
    "nSlvNod",   "nMstNod",   "nSurfDir",   "nDir",      "nStateVar", "nProps",
    "nTemp",     "nPred",     "numDefTfv",  "jSlvUid",   "jMstUid",   "jConMstid",
    "timStep",   "timGlb",    "dTimCur",    "surfInt",   "surfSlv",   "surfMst",
    "rdisp",     "drdisp",    "drot",       "stiffDflt", "condDflt",  "shape",
    "coordSlv",  "coordMst",  "alocaldir",  "props",     "areaSlv",   "tempSlv",
    "dtempSlv",  "preDefSlv", "dpreDefSlv", "tempMst",   "dtempMst",  "preDefMst",
    "dpreDefMst"};
static const char *const UINTER_ARGS[] = {
    "STRESS", "DDSDDR",     "DVISCOUS", "DSTRUCTURAL", "FLUX",     "DDFDDT", "DDSDDT",
    "DDFDDR", "STATEV",     "SED",      "SFD",         "SPD",      "SVD",    "SCD",
    "PNEWDT", "RDISP",      "DRDISP",   "TEMP",        "DTEMP",    "PREDEF", "DPRED",
    "TIME",   "DTIME",      "FREQR",    "CINAME",      "SLNAME",   "MSNAME", "PROPS",
    "COORDS", "ALOCALDIR",  "DROT",     "AREA",        "CHRLNGTH", "NODE",   "NDIR",
    "NSTATV", "NPRED",      "NPROPS",   "MCRD",        "KSTEP",    "KINC",   "KIT",
    "LINPER", "LOPENCLOSE", "LSTATE",   "LSDI",        "LPRINT"};
static const char *const FRIC_ARGS[] = {
    "LM",     "TAU",    "DDTDDG", "DDTDDP", "DSLIP",    "SED",    "SFD",    "DDTDDT",
    "PNEWDT", "STATEV", "DGAM",   "TAULM",  "PRESS",    "DPRESS", "DDPDDH", "SLIP",
    "KSTEP",  "KINC",   "TIME",   "DTIME",  "NOEL",     "CINAME", "SLNAME", "MSNAME",
    "NPT",    "NODE",   "NPATCH", "COORDS", "RCOORD",   "DROT",   "TEMP",   "PREDEF",
    "NFDIR",  "MCRD",   "NPRED",  "NSTATV", "CHRLNGTH", "PROPS",  "NPROPS"};
#define COUNT(a) ((int)(sizeof a / sizeof *a))

/* Writes SUBROUTINE routine with args (less those named in drop, a space-separated list,
 * plus extra) in fixed form, four to a continuation line. */
static void write_list(const char *name, const char *routine, const char *const *args,
                       int n, const char *drop, const char *extra, char *path)
{
    char text[4096];
    size_t used = (size_t)snprintf(text, sizeof text, "C     %s\n      SUBROUTINE %s(",
                                   name, routine);
    int written = 0;
    for (int i = 0; i < n; ++i) {
        char key[40];
        snprintf(key, sizeof key, " %s ", args[i]);
        char drops[200];
        snprintf(drops, sizeof drops, " %s ", drop ? drop : "");
        if (strstr(drops, key))
            continue;
        used +=
            (size_t)snprintf(text + used, sizeof text - used, "%s%s%s", written ? "," : "",
                             written && written % 4 == 0 ? "\n     1 " : "", args[i]);
        ++written;
    }
    if (extra)
        used += (size_t)snprintf(text + used, sizeof text - used, ",\n     2 %s", extra);
    snprintf(text + used, sizeof text - used, ")\n      RETURN\n      END\n");
    write_file(name, text, path, 128);
}

static void supported_lists_are_recognised(void)
{
    char p[128];
    rs_arglist list = (rs_arglist)0;
    write_list("v.f", "VUINTER", VUINTER_ARGS, COUNT(VUINTER_ARGS), NULL, NULL, p);
    ENSURE(rs_law_source_list(p, "vuinter", &list, &err) == RS_OK);
    ENSURE(list == RS_ARGS_VUINTER);
    write_list("u.f", "uinter", UINTER_ARGS, COUNT(UINTER_ARGS), NULL, NULL, p);
    ENSURE(rs_law_source_list(p, "uinter", &list, &err) == RS_OK && list == RS_ARGS_UINTER);
    write_list("u6.f", "UINTER", UINTER_ARGS, COUNT(UINTER_ARGS),
               "DVISCOUS DSTRUCTURAL FREQR", NULL, p);
    ENSURE(rs_law_source_list(p, "uinter", &list, &err) == RS_OK);
    ENSURE(list == RS_ARGS_UINTER_OLDER);
    write_list("f.f", "Fric", FRIC_ARGS, COUNT(FRIC_ARGS), NULL, NULL, p);
    ENSURE(rs_law_source_list(p, "FRIC", &list, &err) == RS_OK && list == RS_ARGS_FRIC);
    /* the repository's routines, which the adapter tests run */
    static const struct {
        const char *file, *routine;
        rs_arglist list;
    } repo[] = {{"fortran/vuinter_probe.f", "vuinter", RS_ARGS_VUINTER},
                {"fortran/uinter_probe.f", "uinter", RS_ARGS_UINTER},
                {"fortran/uinter_v6_penalty.f", "uinter", RS_ARGS_UINTER_OLDER},
                {"fortran/fric_probe.f", "fric", RS_ARGS_FRIC},
                {"abaqus/vuinter_util.f", "vuinter", RS_ARGS_VUINTER}};
    for (int i = 0; i < COUNT(repo); ++i) {
        ENSURE(rs_law_source_list(repo[i].file, repo[i].routine, &list, &err) == RS_OK);
        ENSURE(list == repo[i].list);
    }
}

static void other_lists_are_refused(void)
{
    char p[128];
    rs_arglist list;
    /* issue 32's routine: the current list less DVISCOUS and DSTRUCTURAL */
    write_list("u45.f", "UINTER", UINTER_ARGS, COUNT(UINTER_ARGS), "DVISCOUS DSTRUCTURAL",
               NULL, p);
    ENSURE(rs_law_source_list(p, "uinter", &list, &err) == RS_ERR_ARG);
    char want[200];
    snprintf(want, sizeof want, "%s:2: SUBROUTINE UINTER has 45 arguments", p);
    ENSURE(strstr(err.msg, want) != NULL);
    ENSURE(strstr(err.msg, "with 47 (") && strstr(err.msg, " or 44 ("));
    /* one missing, one too many */
    write_list("v48.f", "VUINTER", VUINTER_ARGS, COUNT(VUINTER_ARGS), "shape", NULL, p);
    ENSURE(rs_law_source_list(p, "vuinter", &list, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, ":2: SUBROUTINE VUINTER has 48 arguments") &&
           strstr(err.msg, "with 49 ("));
    write_list("f40.f", "FRIC", FRIC_ARGS, COUNT(FRIC_ARGS), NULL, "EXTRA", p);
    ENSURE(rs_law_source_list(p, "fric", &list, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, ":2: SUBROUTINE FRIC has 40 arguments") &&
           strstr(err.msg, "with 39 ("));
    write_list("u48.f", "UINTER", UINTER_ARGS, COUNT(UINTER_ARGS), NULL, "EXTRA", p);
    ENSURE(rs_law_source_list(p, "uinter", &list, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "has 48 arguments") != NULL);
    /* no statement, an unknown routine */
    ENSURE(rs_law_source_list(p, "fric", &list, &err) == RS_ERR_NOTFOUND);
    ENSURE(rs_law_source_list(p, "umat", &list, &err) == RS_ERR_ARG);
}

int main(void)
{
    snprintf(dir, sizeof dir, "/tmp/rs_sig_XXXXXX");
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    RS_RUN(fixed_form_continuations_and_comments);
    RS_RUN(fixed_form_tabs_columns_and_blanks);
    RS_RUN(free_form_continuations_and_comments);
    RS_RUN(the_routine_among_others);
    RS_RUN(malformed_lists_name_the_line);
    RS_RUN(bad_input_never_crashes);
    RS_RUN(included_files_are_read);
    RS_RUN(supported_lists_are_recognised);
    RS_RUN(other_lists_are_refused);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", dir);
    return rs_test_summary();
}
