/* rigidsurf-build-law: compiles a Fortran user routine (VUINTER, UINTER, FRIC) into a
 * shared library that `law vuinter|uinter|fric LIB.so` loads, with the flags and include
 * files of include/rigidsurf/law_build.h.
 *
 *   rigidsurf-build-law FILE.f [-o LIB.so] [-v]
 *
 * Without -o the library is lib<stem>.so in the working directory. -v prints the
 * compiler command. The compiler's whole output goes to LIB.so.log; a failed build
 * prints its first error and exits with status 1. A build the compiler warned about
 * prints the compiler's output on stderr, as `abaqus make` shows it, and a line with
 * the count of warnings. */
#include "rigidsurf/law_build.h"

#include <stdio.h>
#include <string.h>

/* The compiler's output, as it printed it, and the count of its warnings. */
static void print_warnings(const char *src, const char *out)
{
    char log[1100];
    snprintf(log, sizeof log, "%s.log", out);
    rs_build_warnings w;
    rs_law_build_read_warnings(log, &w);
    if (w.count == 0)
        return;
    FILE *f = fopen(log, "r");
    if (f) {
        char buf[4096];
        size_t n;
        while ((n = fread(buf, 1, sizeof buf, f)) > 0)
            fwrite(buf, 1, n, stderr);
        fclose(f);
    }
    fprintf(stderr, "rigidsurf-build-law: %s: %d %s from the compiler (whole output: %s)\n",
            src, w.count, w.count == 1 ? "warning" : "warnings", log);
}

static void usage(FILE *f)
{
    fprintf(f, "usage: rigidsurf-build-law FILE.f [-o LIB.so] [-v]\n"
               "  compiles a Fortran VUINTER, UINTER or FRIC (fixed form: .f .for .ftn "
               ".f77 .F .FOR .fpp;\n"
               "  free form: .f90 .f95 .f03 .f08 .F90) into a shared library for "
               "law vuinter|uinter|fric\n");
}

int main(int argc, char **argv)
{
    const char *src = NULL, *out = NULL;
    int verbose = 0;
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "-o") == 0) {
            if (i + 1 >= argc) {
                fprintf(stderr, "rigidsurf-build-law: -o needs a file name\n");
                usage(stderr);
                return 2;
            }
            out = argv[++i];
        } else if (strcmp(argv[i], "-v") == 0) {
            verbose = 1;
        } else if (strcmp(argv[i], "-h") == 0 || strcmp(argv[i], "--help") == 0) {
            usage(stdout);
            return 0;
        } else if (argv[i][0] == '-') {
            fprintf(stderr, "rigidsurf-build-law: unknown option '%s'\n", argv[i]);
            usage(stderr);
            return 2;
        } else if (src) {
            fprintf(stderr, "rigidsurf-build-law: one source file only ('%s' and '%s')\n",
                    src, argv[i]);
            return 2;
        } else {
            src = argv[i];
        }
    }
    if (!src) {
        usage(stderr);
        return 2;
    }
    char def[1024];
    if (!out) {
        const char *base = strrchr(src, '/');
        base = base ? base + 1 : src;
        const char *dot = strrchr(base, '.');
        int stem = (int)(dot ? (size_t)(dot - base) : strlen(base));
        snprintf(def, sizeof def, "lib%.*s.so", stem, base);
        out = def;
    }
    rs_error err;
    if (rs_law_build(src, out, verbose, &err) != RS_OK) {
        fprintf(stderr, "rigidsurf-build-law: %s\n", err.msg);
        return 1;
    }
    print_warnings(src, out);
    printf("%s\n", out);
    return 0;
}
