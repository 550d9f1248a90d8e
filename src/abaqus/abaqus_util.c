/* The Abaqus utility routines for user subroutines, and the bracket that tells them
 * which call they serve (include/rigidsurf/abaqus_util.h).
 *
 * Every routine has its Fortran name (gfortran: lower case and a trailing underscore,
 * CHARACTER lengths as hidden size_t arguments at the end) and an upper-case C name
 * with the same argument list.
 *
 * Numbers in the answers: GETNUMCPUS and GETRANK are the host's MPI rank count and rank.
 * GETPARTINFO / VGETPARTINFO map a particle (its LIGGGHTS tag, the node number the
 * routine sees in jSlvUid or NODE) to the slave surface (the particle group) and the tag
 * itself; element numbers (JTYP = 1) do not exist and return JRCD = 1. VGETVRM has no
 * material point to read from and ends the run with an error that says so. */
#define _POSIX_C_SOURCE 200809L

#include "rigidsurf/abaqus_util.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#if defined(__GNUC__)
#define RS_ABQ_EXPORT __attribute__((visibility("default")))
#define RS_ABQ_ALIAS(name) __attribute__((alias(name), visibility("default")))
#else
#error "librigidsurf_abaqus needs GCC or clang (symbol aliases)"
#endif

/* ------------------------------------------------------------------- host */

static struct {
    void (*message)(void *ctx, int severity, const char *text);
    void (*fatal)(void *ctx, const char *text);
    void *ctx;
    char jobname[256];
    char outdir[1024];
    int rank;
    int ncpus;
} host = {NULL, NULL, NULL, "rigidsurf", "", 0, 1};

void rs_abq_set_host(const rs_abq_host *h)
{
    host.message = h ? h->message : NULL;
    host.fatal = h ? h->fatal : NULL;
    host.ctx = h ? h->ctx : NULL;
    snprintf(host.jobname, sizeof host.jobname, "%s",
             h && h->jobname && h->jobname[0] ? h->jobname : "rigidsurf");
    snprintf(host.outdir, sizeof host.outdir, "%s", h && h->outdir ? h->outdir : "");
    host.rank = h && h->rank > 0 ? h->rank : 0;
    host.ncpus = h && h->ncpus > 1 ? h->ncpus : 1;
}

int rs_abq_rank(void)
{
    return host.rank;
}

int rs_abq_ncpus(void)
{
    return host.ncpus;
}

static void host_message(int severity, const char *text)
{
    if (host.message) {
        host.message(host.ctx, severity, text);
        return;
    }
    fprintf(stderr, "%s\n", text);
    fflush(stderr);
}

static void host_fatal(const char *text)
{
    if (host.fatal)
        host.fatal(host.ctx, text);
    fprintf(stderr, "ERROR: %s\n", text);
    fflush(NULL);
    exit(1);
}

/* ------------------------------------------------------------ the current call */

static _Thread_local struct {
    const rs_law_block *b;
    int k;
    const char *routine;
    int quiet; ///< a setup call: information and warning lines are not printed
    int failed;
    char error[400];
} cur;

void rs_abq_call_begin(const rs_law_block *b, int k, const char *routine)
{
    cur.b = b;
    cur.k = k;
    cur.routine = routine ? routine : "user routine";
    cur.quiet = b && b->setup;
    cur.failed = 0;
    cur.error[0] = '\0';
}

int rs_abq_call_end(rs_error *err)
{
    const int failed = cur.failed;
    const char *routine = cur.routine ? cur.routine : "user routine";
    cur.b = NULL;
    cur.k = -1;
    cur.quiet = 0;
    cur.failed = 0;
    if (!failed)
        return RS_OK;
    if (err) {
        err->code = RS_ERR_ARG;
        snprintf(err->msg, sizeof err->msg, "%s raised an error: %s", routine, cur.error);
    }
    return RS_ERR_ARG;
}

/* The contact of the current call that knode (1-based) names, or -1. */
static int current_contact(int knode)
{
    if (!cur.b)
        return -1;
    if (cur.k >= 0)
        return knode == 1 ? cur.k : -1;
    return knode >= 1 && knode <= cur.b->nSlvNod ? knode - 1 : -1;
}

int rs_abq_dem_fields(int knode, double out[8])
{
    for (int i = 0; i < 8; ++i)
        out[i] = 0.0;
    const int k = current_contact(knode);
    if (k < 0)
        return 1;
    const rs_law_block *b = cur.b;
    const int nd = b->nDir;
    out[0] = b->radius ? b->radius[k] : 0.0;
    out[1] = b->mass ? b->mass[k] : 0.0;
    out[2] = b->reff ? b->reff[k] : 0.0;
    for (int i = 0; i < nd && i < 3; ++i)
        out[3 + i] = b->vrel ? RS_A2(b->vrel, nd, i, k) : 0.0;
    out[6] = b->curv ? b->curv[2 * k] : 0.0;
    out[7] = b->curv ? b->curv[2 * k + 1] : 0.0;
    return 0;
}

/* ------------------------------------------------------------ strings */

/* Length of a blank-padded Fortran string without its trailing blanks. */
static size_t trimmed(const char *s, size_t len)
{
    if (!s)
        return 0;
    while (len > 0 && (s[len - 1] == ' ' || s[len - 1] == '\0'))
        --len;
    return len;
}

/* Copies text into a Fortran string of length len, blank-padded; returns the characters
 * copied (at most len). */
static int to_fortran(char *dst, size_t len, const char *text)
{
    size_t n = strlen(text);
    if (n > len)
        n = len;
    memcpy(dst, text, n);
    memset(dst + n, ' ', len - n);
    return (int)n;
}

/* Appends to out[*used..size) (always NUL-terminated). */
static void append(char *out, size_t size, size_t *used, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

static void append(char *out, size_t size, size_t *used, const char *fmt, ...)
{
    if (*used + 1 >= size)
        return;
    va_list ap;
    va_start(ap, fmt);
    int w = vsnprintf(out + *used, size - *used, fmt, ap);
    va_end(ap);
    if (w < 0)
        return;
    *used += (size_t)w < size - *used ? (size_t)w : size - *used - 1;
}

void rs_abq_format(char *out, size_t size, const char *string, size_t len, const int *intv,
                   const double *realv, const char *charv)
{
    if (!out || size == 0)
        return;
    out[0] = '\0';
    size_t used = 0, n = trimmed(string, len);
    int ni = 0, nr = 0, ns = 0;
    for (size_t i = 0; i < n; ++i) {
        const char c = string[i];
        const char d = i + 1 < n ? string[i + 1] : '\0';
        if (c == '%' && (d == 'I' || d == 'i') && intv) {
            append(out, size, &used, "%d", intv[ni++]);
            ++i;
        } else if (c == '%' && (d == 'R' || d == 'r') && realv) {
            append(out, size, &used, "%g", realv[nr++]);
            ++i;
        } else if (c == '%' && (d == 'D' || d == 'd') && realv) {
            append(out, size, &used, "%.17g", realv[nr++]);
            ++i;
        } else if (c == '%' && (d == 'S' || d == 's') && charv) {
            const char *s = charv + 8 * ns++;
            append(out, size, &used, "%.*s", (int)trimmed(s, 8), s);
            ++i;
        } else {
            append(out, size, &used, "%c", c);
        }
    }
}

/* ------------------------------------------------------------ messages */

static void abqerr(const char *who, int lop, const char *string, const int *intv,
                   const double *realv, const char *charv, size_t lstring)
{
    char text[300];
    rs_abq_format(text, sizeof text, string, lstring, intv, realv, charv);
    const char *routine = cur.routine ? cur.routine : "user routine";
    char line[600];
    if (lop == RS_ABQ_INFO || lop == RS_ABQ_WARNING) {
        if (cur.quiet)
            return;
        snprintf(line, sizeof line, "rigidsurf %s [rank %d] %s (%s): %s",
                 lop == RS_ABQ_INFO ? "INFO" : "WARNING", host.rank, routine, who, text);
        host_message(lop, line);
    } else if (lop == RS_ABQ_ERROR && cur.b) {
        if (!cur.failed) {
            cur.failed = 1;
            snprintf(cur.error, sizeof cur.error, "[rank %d] %s: %s", host.rank, who, text);
        }
    } else if (lop == RS_ABQ_ERROR || lop == RS_ABQ_FATAL) {
        snprintf(line, sizeof line, "[rank %d] %s raised an error (%s): %s", host.rank,
                 routine, who, text);
        host_fatal(line);
    } else {
        snprintf(line, sizeof line,
                 "[rank %d] %s called %s with LOP = %d; expected 1 (information), -1 "
                 "(warning), -2 (error) or -3 (error, stop now). Message: %s",
                 host.rank, routine, who, lop, text);
        host_fatal(line);
    }
}

RS_ABQ_EXPORT void xplb_abqerr_(const int *lop, const char *string, const int *intv,
                                const double *realv, const char *charv, size_t lstring,
                                size_t lcharv)
{
    (void)lcharv; /* CHARACTER*8 entries */
    abqerr("XPLB_ABQERR", *lop, string, intv, realv, charv, lstring);
}
RS_ABQ_EXPORT void XPLB_ABQERR(const int *lop, const char *string, const int *intv,
                               const double *realv, const char *charv, size_t lstring,
                               size_t lcharv) RS_ABQ_ALIAS("xplb_abqerr_");

RS_ABQ_EXPORT void stdb_abqerr_(const int *lop, const char *string, const int *intv,
                                const double *realv, const char *charv, size_t lstring,
                                size_t lcharv)
{
    (void)lcharv;
    abqerr("STDB_ABQERR", *lop, string, intv, realv, charv, lstring);
}
RS_ABQ_EXPORT void STDB_ABQERR(const int *lop, const char *string, const int *intv,
                               const double *realv, const char *charv, size_t lstring,
                               size_t lcharv) RS_ABQ_ALIAS("stdb_abqerr_");

static void stop_run(const char *who)
{
    char line[200];
    snprintf(line, sizeof line, "[rank %d] %s called %s: the run stops", host.rank,
             cur.routine ? cur.routine : "a user routine", who);
    host_fatal(line);
}

RS_ABQ_EXPORT void xplb_exit_(void)
{
    stop_run("XPLB_EXIT");
}
RS_ABQ_EXPORT void XPLB_EXIT(void) RS_ABQ_ALIAS("xplb_exit_");

RS_ABQ_EXPORT void xit_(void)
{
    stop_run("XIT");
}
RS_ABQ_EXPORT void XIT(void) RS_ABQ_ALIAS("xit_");

/* ------------------------------------------------------------ job facts */

RS_ABQ_EXPORT void getjobname_(char *jobname, int *lenjobname, size_t ljobname)
{
    *lenjobname = to_fortran(jobname, ljobname, host.jobname);
}
RS_ABQ_EXPORT void GETJOBNAME(char *jobname, int *lenjobname, size_t ljobname)
    RS_ABQ_ALIAS("getjobname_");
RS_ABQ_EXPORT void vgetjobname_(char *jobname, int *lenjobname, size_t ljobname)
    RS_ABQ_ALIAS("getjobname_");
RS_ABQ_EXPORT void VGETJOBNAME(char *jobname, int *lenjobname, size_t ljobname)
    RS_ABQ_ALIAS("getjobname_");

RS_ABQ_EXPORT void getoutdir_(char *outdir, int *lenoutdir, size_t loutdir)
{
    char cwd[1024];
    const char *dir = host.outdir;
    if (!dir[0])
        dir = getcwd(cwd, sizeof cwd) ? cwd : ".";
    *lenoutdir = to_fortran(outdir, loutdir, dir);
}
RS_ABQ_EXPORT void GETOUTDIR(char *outdir, int *lenoutdir, size_t loutdir)
    RS_ABQ_ALIAS("getoutdir_");
RS_ABQ_EXPORT void vgetoutdir_(char *outdir, int *lenoutdir, size_t loutdir)
    RS_ABQ_ALIAS("getoutdir_");
RS_ABQ_EXPORT void VGETOUTDIR(char *outdir, int *lenoutdir, size_t loutdir)
    RS_ABQ_ALIAS("getoutdir_");

RS_ABQ_EXPORT void getnumcpus_(int *numprocesses)
{
    *numprocesses = host.ncpus;
}
RS_ABQ_EXPORT void GETNUMCPUS(int *numprocesses) RS_ABQ_ALIAS("getnumcpus_");
RS_ABQ_EXPORT void vgetnumcpus_(int *numprocesses) RS_ABQ_ALIAS("getnumcpus_");
RS_ABQ_EXPORT void VGETNUMCPUS(int *numprocesses) RS_ABQ_ALIAS("getnumcpus_");

RS_ABQ_EXPORT void getrank_(int *kprocessnum)
{
    *kprocessnum = host.rank;
}
RS_ABQ_EXPORT void GETRANK(int *kprocessnum) RS_ABQ_ALIAS("getrank_");
RS_ABQ_EXPORT void vgetrank_(int *kprocessnum) RS_ABQ_ALIAS("getrank_");
RS_ABQ_EXPORT void VGETRANK(int *kprocessnum) RS_ABQ_ALIAS("getrank_");

/* ------------------------------------------------------------ particles */

/* Node number (particle tag) -> (slave surface name, tag); jrcd 1 when the tag is not a
 * contact of the current call or an element is asked for. */
static void partinfo(int num, int jtyp, char *partname, int *locnum, int *jrcd,
                     size_t lpart)
{
    *locnum = 0;
    *jrcd = 1;
    to_fortran(partname, lpart, "");
    const rs_law_block *b = cur.b;
    if (!b || jtyp != 0 || !b->jSlvUid)
        return;
    for (int k = 0; k < b->nSlvNod; ++k)
        if (b->jSlvUid[k] == num) {
            char name[RS_LAW_NAMELEN + 1];
            size_t n = trimmed(b->surfSlv, RS_LAW_NAMELEN);
            memcpy(name, b->surfSlv, n);
            name[n] = '\0';
            to_fortran(partname, lpart, name);
            *locnum = num;
            *jrcd = 0;
            return;
        }
}

/* GETPARTINFO(INTNUM, JTYP, PARTNAME, LOCNUM, JRCD): JTYP 0 a node, 1 an element. */
RS_ABQ_EXPORT void getpartinfo_(const int *intnum, const int *jtyp, char *partname,
                                int *locnum, int *jrcd, size_t lpart)
{
    partinfo(*intnum, *jtyp, partname, locnum, jrcd, lpart);
}
RS_ABQ_EXPORT void GETPARTINFO(const int *intnum, const int *jtyp, char *partname,
                               int *locnum, int *jrcd, size_t lpart)
    RS_ABQ_ALIAS("getpartinfo_");

/* VGETPARTINFO(userNodeNum, jInternalExternal, partName, locNum, jrcd): node numbers
 * only; internal and user numbers are both the particle tag. */
RS_ABQ_EXPORT void vgetpartinfo_(const int *nodenum, const int *jinternal, char *partname,
                                 int *locnum, int *jrcd, size_t lpart)
{
    (void)jinternal;
    partinfo(*nodenum, 0, partname, locnum, jrcd, lpart);
}
RS_ABQ_EXPORT void VGETPARTINFO(const int *nodenum, const int *jinternal, char *partname,
                                int *locnum, int *jrcd, size_t lpart)
    RS_ABQ_ALIAS("vgetpartinfo_");

/* VGETVRM('VAR', rData, jData, cData, jStatus): no material points here. */
RS_ABQ_EXPORT void vgetvrm_(const char *var, double *rdata, int *jdata, char *cdata,
                            int *jstatus, size_t lvar, size_t lcdata)
{
    (void)rdata;
    (void)jdata;
    (void)cdata;
    (void)lcdata;
    *jstatus = 1;
    char line[300];
    snprintf(
        line, sizeof line,
        "[rank %d] %s called VGETVRM('%.*s'): VGETVRM reads material point results, "
        "and a rigidsurf contact has none (the slave is a DEM particle); use RS_GETDEM "
        "for the particle's data",
        host.rank, cur.routine ? cur.routine : "a user routine", (int)trimmed(var, lvar),
        var);
    host_fatal(line);
}
RS_ABQ_EXPORT void VGETVRM(const char *var, double *rdata, int *jdata, char *cdata,
                           int *jstatus, size_t lvar, size_t lcdata)
    RS_ABQ_ALIAS("vgetvrm_");

/* RS_GETDEM(KNODE, DEMV, JRCD): DEMV(1:8) of contact KNODE of the current call (1 for
 * UINTER and FRIC); see rs_abq_dem_fields. */
RS_ABQ_EXPORT void rs_getdem_(const int *knode, double *demv, int *jrcd)
{
    *jrcd = rs_abq_dem_fields(*knode, demv);
}
RS_ABQ_EXPORT void RS_GETDEM(const int *knode, double *demv, int *jrcd)
    RS_ABQ_ALIAS("rs_getdem_");
