/* Building Fortran user routines into shared libraries (include/rigidsurf/law_build.h).
 *
 * Where the pieces are: the utility library is the librigidsurf_abaqus that this
 * process has loaded (found with dladdr), and the Fortran includes sit beside it: in an
 * installed tree at <prefix>/RS_REL_INCDIR for a library in <prefix>/RS_REL_LIBDIR, in
 * the build tree at RS_BUILD_INCDIR. */
#define _GNU_SOURCE

#include "rigidsurf/law_build.h"
#include "rigidsurf/abaqus_util.h"

#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <spawn.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

#ifndef RS_BUILD_INCDIR
#define RS_BUILD_INCDIR ""
#endif
#ifndef RS_REL_INCDIR
#define RS_REL_INCDIR "include/rigidsurf"
#endif
#ifndef RS_REL_LIBDIR
#define RS_REL_LIBDIR "lib"
#endif

#define RS_PATH 4096

enum { FORM_NONE = 0, FORM_FIXED = RS_FORM_FIXED, FORM_FREE = RS_FORM_FREE };

int rs_law_source_form(const char *path)
{
    if (!path)
        return FORM_NONE;
    const char *base = strrchr(path, '/');
    const char *dot = strrchr(base ? base : path, '.');
    if (!dot)
        return FORM_NONE;
    static const char *const fixed[] = {".f", ".for", ".ftn", ".f77", ".F", ".FOR", ".fpp"};
    static const char *const free_[] = {".f90", ".f95", ".f03", ".f08", ".F90"};
    for (size_t i = 0; i < sizeof fixed / sizeof *fixed; ++i)
        if (strcmp(dot, fixed[i]) == 0)
            return FORM_FIXED;
    for (size_t i = 0; i < sizeof free_ / sizeof *free_; ++i)
        if (strcmp(dot, free_[i]) == 0)
            return FORM_FREE;
    return FORM_NONE;
}

int rs_law_is_source(const char *path)
{
    return rs_law_source_form(path) != FORM_NONE;
}

static int is_file(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

static void dirname_of(const char *path, char *dir, size_t size)
{
    const char *slash = strrchr(path, '/');
    if (!slash)
        snprintf(dir, size, ".");
    else if (slash == path)
        snprintf(dir, size, "/");
    else
        snprintf(dir, size, "%.*s", (int)(slash - path), path);
}

/* The utility library loaded in this process and the Fortran includes that go with it. */
static int find_resources(const char *what, char *libdir, char *incdir, rs_error *err)
{
    Dl_info info;
    if (!dladdr((void *)rs_abq_set_host, &info) || !info.dli_fname || !info.dli_fname[0])
        return rs_error_set(err, RS_ERR_NOTFOUND,
                            "%s: cannot locate librigidsurf_abaqus (the utility routines "
                            "user routines link against)",
                            what);
    char real[RS_PATH];
    if (!realpath(info.dli_fname, real))
        snprintf(real, sizeof real, "%s", info.dli_fname);
    dirname_of(real, libdir, RS_PATH);

    /* installed: <prefix>/<libdir> -> <prefix>/<incdir> */
    const size_t nl = strlen(libdir), nr = strlen(RS_REL_LIBDIR);
    if (nl > nr && strcmp(libdir + nl - nr, RS_REL_LIBDIR) == 0 &&
        libdir[nl - nr - 1] == '/') {
        snprintf(incdir, RS_PATH, "%.*s%s", (int)(nl - nr), libdir, RS_REL_INCDIR);
        char probe[RS_PATH + 32];
        snprintf(probe, sizeof probe, "%s/VABA_PARAM.INC", incdir);
        if (is_file(probe))
            return RS_OK;
    }
    snprintf(incdir, RS_PATH, "%s", RS_BUILD_INCDIR);
    char probe[RS_PATH + 32];
    snprintf(probe, sizeof probe, "%s/VABA_PARAM.INC", incdir);
    if (incdir[0] && is_file(probe))
        return RS_OK;
    return rs_error_set(err, RS_ERR_NOTFOUND,
                        "%s: the Fortran includes (VABA_PARAM.INC, ABA_PARAM.INC) are "
                        "not beside %s (expected in %.*s%s or %s)",
                        what, real, (int)(nl > nr ? nl - nr : 0), libdir, RS_REL_INCDIR,
                        RS_BUILD_INCDIR);
}

/* ------------------------------------------------------------ hashing */

static uint64_t fnv(uint64_t h, const void *data, size_t n)
{
    const unsigned char *p = (const unsigned char *)data;
    for (size_t i = 0; i < n; ++i) {
        h ^= p[i];
        h *= 1099511628211ull;
    }
    return h;
}

static char *read_all(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    size_t cap = 1 << 14, len = 0;
    char *buf = (char *)malloc(cap + 1);
    while (buf) {
        size_t got = fread(buf + len, 1, cap - len, f);
        len += got;
        if (len < cap)
            break;
        char *grown = (char *)realloc(buf, 2 * cap + 1);
        if (!grown) {
            free(buf);
            buf = NULL;
            break;
        }
        buf = grown;
        cap *= 2;
    }
    fclose(f);
    if (buf) {
        buf[len] = '\0';
        *n = len;
    }
    return buf;
}

/* Hashes the file and, up to depth 8, the files its INCLUDE lines name in dir. */
static uint64_t hash_file(uint64_t h, const char *path, const char *dir, int depth)
{
    size_t n = 0;
    char *text = read_all(path, &n);
    if (!text)
        return fnv(h, path, strlen(path));
    h = fnv(h, text, n);
    for (char *line = text; depth < 8 && line && *line;) {
        char *next = strchr(line, '\n');
        if (next)
            *next++ = '\0';
        char *p = line;
        while (*p == ' ' || *p == '\t')
            ++p;
        if (strncasecmp(p, "include", 7) == 0) {
            p += 7;
            while (*p == ' ' || *p == '\t')
                ++p;
            char q = *p;
            char *end = (q == '\'' || q == '"') ? strchr(p + 1, q) : NULL;
            if (end) {
                char inc[RS_PATH];
                snprintf(inc, sizeof inc, "%s/%.*s", dir, (int)(end - p - 1), p + 1);
                if (is_file(inc))
                    h = hash_file(h, inc, dir, depth + 1);
            }
        }
        line = next;
    }
    free(text);
    return h;
}

/* ------------------------------------------------------------ compiling */

typedef struct build_cmd {
    const char *argv[32];
    int argc;
    char rpath[RS_PATH + 16];
} build_cmd;

static void make_cmd(build_cmd *c, const char *fc, int form, const char *incdir,
                     const char *srcdir, const char *libdir, const char *src,
                     const char *out)
{
    int a = 0;
    c->argv[a++] = fc;
    if (form == FORM_FIXED) {
        c->argv[a++] = "-ffixed-form";
        c->argv[a++] = "-ffixed-line-length-132";
    } else {
        c->argv[a++] = "-ffree-form";
        c->argv[a++] = "-ffree-line-length-none";
    }
    c->argv[a++] = "-fallow-argument-mismatch";
    c->argv[a++] = "-Wno-tabs";
    c->argv[a++] = "-O2";
    c->argv[a++] = "-fPIC";
    c->argv[a++] = "-shared";
    c->argv[a++] = "-I";
    c->argv[a++] = incdir;
    c->argv[a++] = "-I";
    c->argv[a++] = srcdir;
    c->argv[a++] = src;
    c->argv[a++] = "-o";
    c->argv[a++] = out;
    c->argv[a++] = "-L";
    c->argv[a++] = libdir;
    c->argv[a++] = "-lrigidsurf_abaqus";
    snprintf(c->rpath, sizeof c->rpath, "-Wl,-rpath,%s", libdir);
    c->argv[a++] = c->rpath;
    c->argv[a] = NULL;
    c->argc = a;
}

static uint64_t hash_cmd(uint64_t h, const build_cmd *c)
{
    for (int i = 0; i < c->argc; ++i)
        h = fnv(h, c->argv[i], strlen(c->argv[i]) + 1);
    return h;
}

/* The compiler's first error: the "file:line:col:" line before the first "Error" line,
 * and that line. */
static void first_error(const char *log, char *out, size_t size)
{
    size_t n = 0;
    char *text = read_all(log, &n);
    out[0] = '\0';
    if (!text)
        return;
    const char *prev = NULL, *last = NULL;
    for (char *line = text; line && *line;) {
        char *next = strchr(line, '\n');
        if (next)
            *next++ = '\0';
        if (strstr(line, "Error") || strstr(line, "error:")) {
            snprintf(out, size, "%s%s%s", prev ? prev : "", prev ? " " : "", line);
            break;
        }
        if (line[0] && line[0] != ' ' && strchr(line, ':'))
            prev = line;
        if (line[0])
            last = line;
        line = next;
    }
    if (!out[0]) /* no error line: the output's last line */
        snprintf(out, size, "%s", last ? last : "(no output)");
    free(text);
}

/* A warning: gfortran's "Warning: text" line (its location on a line before), or a
 * "...: Warning: text" or "...: warning: text" line (f951's, gcc's, the linker's). */
static int is_warning(const char *line)
{
    return strncmp(line, "Warning:", 8) == 0 || strstr(line, ": Warning:") ||
           strstr(line, ": warning:");
}

void rs_law_build_read_warnings(const char *log, rs_build_warnings *w)
{
    if (!w)
        return;
    memset(w, 0, sizeof *w);
    if (!log)
        return;
    snprintf(w->log, sizeof w->log, "%s", log);
    size_t n = 0;
    char *text = read_all(log, &n);
    if (!text)
        return;
    const char *where = NULL; /* the last "FILE:LINE:COL:" line */
    for (char *line = text; line && *line;) {
        char *next = strchr(line, '\n');
        if (next)
            *next++ = '\0';
        const size_t len = strlen(line);
        if (is_warning(line)) {
            if (++w->count == 1) {
                const int located = strncmp(line, "Warning:", 8) == 0 && where;
                snprintf(w->first, sizeof w->first, "%s%s%s", located ? where : "",
                         located ? " " : "", line);
            }
        } else if (len > 1 && line[0] != ' ' && line[len - 1] == ':' &&
                   strchr(line, ':') < line + len - 1) {
            where = line;
        }
        line = next;
    }
    free(text);
}

/* Runs the command with stdout and stderr into the open file logfd; the exit status, or
 * -1 with errno. */
static int run_logged(const build_cmd *c, int logfd)
{
    posix_spawn_file_actions_t fa;
    if (posix_spawn_file_actions_init(&fa) != 0)
        return -1;
    posix_spawn_file_actions_adddup2(&fa, logfd, 1);
    posix_spawn_file_actions_adddup2(&fa, logfd, 2);
    posix_spawn_file_actions_addclose(&fa, 0);
    pid_t pid;
    int rc = posix_spawnp(&pid, c->argv[0], &fa, NULL, (char *const *)c->argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    if (rc != 0) {
        errno = rc;
        return -1;
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            return -1;
    if (WIFEXITED(status))
        return WEXITSTATUS(status);
    return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

static const char *compiler(void)
{
    const char *fc = getenv("RIGIDSURF_FC");
    return fc && fc[0] ? fc : "gfortran";
}

/* Compiles src to out through a temporary file beside it (so a reader never sees half a
 * library); the compiler's output goes to log. */
static int compile(const build_cmd *proto, const char *src, const char *out,
                   const char *log, int verbose, rs_error *err)
{
    char tmp[RS_PATH + 32];
    snprintf(tmp, sizeof tmp, "%s.tmp%ld", out, (long)getpid());
    build_cmd c = *proto;
    for (int i = 0; i < c.argc; ++i)
        if (c.argv[i] == out)
            c.argv[i] = tmp;
    /* the copy's rpath argument points into the copy */
    c.argv[c.argc - 1] = c.rpath;
    if (verbose) {
        for (int i = 0; i < c.argc; ++i)
            printf("%s%s", i ? " " : "", c.argv[i]);
        printf("\n");
        fflush(stdout);
    }
    int logfd = open(log, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (logfd < 0) {
        int e = errno;
        return rs_error_set(err, RS_ERR_IO, "%s: cannot write %s: %s", src, log,
                            strerror(e));
    }
    int rc = run_logged(&c, logfd);
    close(logfd);
    if (rc < 0) {
        int e = errno;
        return rs_error_set(
            err, RS_ERR_IO,
            "%s: cannot run the Fortran compiler '%s': %s (install gfortran, "
            "or set RIGIDSURF_FC)",
            src, c.argv[0], strerror(e));
    }
    if (rc == 127)
        return rs_error_set(
            err, RS_ERR_IO,
            "%s: the Fortran compiler '%s' was not found (install gfortran, "
            "or set RIGIDSURF_FC)",
            src, c.argv[0]);
    if (rc != 0) {
        unlink(tmp);
        char first[300];
        first_error(log, first, sizeof first);
        return rs_error_set(
            err, RS_ERR_PARSE,
            "%s: the Fortran compiler failed (exit %d): %s (whole output: %s)", src, rc,
            first, log);
    }
    if (rename(tmp, out) != 0) {
        int e = errno;
        unlink(tmp);
        return rs_error_set(err, RS_ERR_IO, "%s: cannot write %s: %s", src, out,
                            strerror(e));
    }
    return RS_OK;
}

static int prepare(const char *src, int *form, char *libdir, char *incdir, char *srcdir,
                   rs_error *err)
{
    if (!src || !src[0])
        return rs_error_set(err, RS_ERR_ARG, "user routine: no source file given");
    *form = rs_law_source_form(src);
    if (*form == FORM_NONE)
        return rs_error_set(err, RS_ERR_ARG,
                            "%s: not a Fortran source (expected .f, .for, .ftn, .f77, .F, "
                            ".FOR, .fpp, .f90, .f95, .f03, .f08 or .F90)",
                            src);
    if (access(src, R_OK) != 0) {
        int e = errno;
        return rs_error_set(err, RS_ERR_IO, "%s: cannot read: %s", src, strerror(e));
    }
    dirname_of(src, srcdir, RS_PATH);
    return find_resources(src, libdir, incdir, err);
}

int rs_law_build(const char *src, const char *out, int verbose, rs_error *err)
{
    if (!out || !out[0])
        return rs_error_set(err, RS_ERR_ARG, "%s: no output library given",
                            src ? src : "user routine");
    char libdir[RS_PATH], incdir[RS_PATH], srcdir[RS_PATH];
    int form;
    int rc = prepare(src, &form, libdir, incdir, srcdir, err);
    if (rc)
        return rc;
    build_cmd c;
    make_cmd(&c, compiler(), form, incdir, srcdir, libdir, src, out);
    char log[RS_PATH + 8];
    snprintf(log, sizeof log, "%s.log", out);
    return compile(&c, src, out, log, verbose, err);
}

static int mkdirs(const char *path)
{
    char buf[RS_PATH];
    snprintf(buf, sizeof buf, "%s", path);
    for (char *p = buf + 1; *p; ++p)
        if (*p == '/') {
            *p = '\0';
            if (mkdir(buf, 0755) != 0 && errno != EEXIST)
                return -1;
            *p = '/';
        }
    return mkdir(buf, 0755) != 0 && errno != EEXIST ? -1 : 0;
}

static void cache_dir(char *dir, size_t size)
{
    const char *e = getenv("RIGIDSURF_CACHE");
    if (e && e[0]) {
        snprintf(dir, size, "%s", e);
        return;
    }
    e = getenv("XDG_CACHE_HOME");
    if (e && e[0]) {
        snprintf(dir, size, "%s/rigidsurf", e);
        return;
    }
    e = getenv("HOME");
    if (e && e[0]) {
        snprintf(dir, size, "%s/.cache/rigidsurf", e);
        return;
    }
    snprintf(dir, size, "/tmp/rigidsurf-cache-%ld", (long)getuid());
}

int rs_law_build_cached(const char *src, char *so_path, size_t size, rs_error *err)
{
    char libdir[RS_PATH], incdir[RS_PATH], srcdir[RS_PATH];
    int form;
    int rc = prepare(src, &form, libdir, incdir, srcdir, err);
    if (rc)
        return rc;
    char dir[RS_PATH];
    cache_dir(dir, sizeof dir);
    if (mkdirs(dir) != 0) {
        int e = errno;
        return rs_error_set(
            err, RS_ERR_IO,
            "%s: cannot create the build cache %s: %s (set RIGIDSURF_CACHE)", src, dir,
            strerror(e));
    }
    /* the name: the file's stem and the hash of everything the build reads */
    const char *base = strrchr(src, '/');
    base = base ? base + 1 : src;
    const char *dot = strrchr(base, '.');
    int stem = (int)(dot ? (size_t)(dot - base) : strlen(base));
    char out[RS_PATH + 64];
    build_cmd c;
    make_cmd(&c, compiler(), form, incdir, srcdir, libdir, src, "-");
    uint64_t h = hash_cmd(1469598103934665603ull, &c);
    h = hash_file(h, src, srcdir, 0);
    char inc[RS_PATH + 32];
    snprintf(inc, sizeof inc, "%s/VABA_PARAM.INC", incdir);
    h = hash_file(h, inc, incdir, 8);
    snprintf(inc, sizeof inc, "%s/ABA_PARAM.INC", incdir);
    h = hash_file(h, inc, incdir, 8);
    snprintf(out, sizeof out, "%s/%.*s-%016llx.so", dir, stem, base, (unsigned long long)h);
    if ((size_t)snprintf(so_path, size, "%s", out) >= size)
        return rs_error_set(err, RS_ERR_ARG, "%s: the cache path %s is too long", src, out);
    if (is_file(out))
        return RS_OK;

    /* One process compiles; the others wait on the lock, then find the library. */
    char lock[RS_PATH + 80];
    snprintf(lock, sizeof lock, "%s.lock", out);
    int fd = open(lock, O_RDWR | O_CREAT, 0644);
    if (fd < 0) {
        int e = errno;
        return rs_error_set(err, RS_ERR_IO, "%s: cannot open the lock %s: %s", src, lock,
                            strerror(e));
    }
    struct flock fl;
    memset(&fl, 0, sizeof fl);
    fl.l_type = F_WRLCK;
    fl.l_whence = SEEK_SET;
    while (fcntl(fd, F_SETLKW, &fl) != 0)
        if (errno != EINTR) {
            int e = errno;
            close(fd);
            return rs_error_set(err, RS_ERR_IO, "%s: cannot lock %s: %s", src, lock,
                                strerror(e));
        }
    rc = RS_OK;
    if (!is_file(out)) {
        make_cmd(&c, compiler(), form, incdir, srcdir, libdir, src, out);
        char log[RS_PATH + 80];
        snprintf(log, sizeof log, "%s.log", out);
        rc = compile(&c, src, out, log, 0, err);
    }
    close(fd); /* releases the lock */
    return rc;
}
