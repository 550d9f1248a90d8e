/* rigidsurf: building a Fortran user routine (VUINTER, UINTER, FRIC) from its source,
 * as `abaqus make` does.
 *
 * The compiler is gfortran (or $RIGIDSURF_FC), found on PATH when a routine is built.
 * The flags follow Abaqus's own fixed-form build: 132 columns, tabs accepted, argument
 * mismatches allowed; a free-form file (.f90, .f95, .f03, .f08, .F90) has unlimited
 * lines. The include path holds VABA_PARAM.INC, ABA_PARAM.INC (and their lower-case
 * names) and the routine's own folder; the library links librigidsurf_abaqus (the
 * utility routines: include/rigidsurf/abaqus_util.h).
 *
 * rs_law_build_cached keeps each result under a name made of the routine's file name
 * and a hash of its text, of the files it INCLUDEs from its folder, of the Fortran
 * includes and of the compiler command. The cache folder is $RIGIDSURF_CACHE, else
 * $XDG_CACHE_HOME/rigidsurf, else $HOME/.cache/rigidsurf, else /tmp/rigidsurf-cache-UID.
 * Processes building the same routine at once (MPI ranks) wait on a lock: one compiles,
 * the others load its result. */
#ifndef RIGIDSURF_LAW_BUILD_H
#define RIGIDSURF_LAW_BUILD_H

#include "rigidsurf/law.h"
#include "rigidsurf/types.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/// 1 if path names a Fortran source by its extension (.f .for .ftn .f77 .F .FOR .fpp
/// fixed form; .f90 .f95 .f03 .f08 .F90 free form), else 0.
int rs_law_is_source(const char *path);

/// Source forms (rs_law_source_form).
enum { RS_FORM_FIXED = 1, RS_FORM_FREE = 2 };

/// The source form path's extension names: RS_FORM_FIXED, RS_FORM_FREE, or 0 when it
/// is not a Fortran source.
int rs_law_source_form(const char *path);

/// What the compiler said about a routine it built: its warnings, read from its whole
/// output (the log kept beside the library).
typedef struct rs_build_warnings {
    int count;       ///< warnings in the output (gfortran's "Warning:" lines and others')
    char first[400]; ///< the first on one line, "FILE:LINE:COL: Warning: text"; "" if none
    char log[4096];  ///< the log's path
} rs_build_warnings;

/// Counts the warnings in the compiler output log and keeps the first. A log that
/// cannot be read has none.
void rs_law_build_read_warnings(const char *log, rs_build_warnings *w);

/// The compiler's warnings for a law that rs_law_load_vuinter, rs_law_load_uinter or
/// rs_law_load_fric built from a Fortran source (also when the build was found in the
/// cache); NULL for any other law.
const rs_build_warnings *rs_law_warnings(const rs_law *law);

/// Compiles src into the shared library out. On a compile error, err names the file
/// and holds the compiler's first error; the whole compiler output is in out.log.
/// verbose != 0 prints the compiler command on stdout.
int rs_law_build(const char *src, const char *out, int verbose, rs_error *err);

/// Builds src into the cache, or finds it there; the library's path goes to so_path.
int rs_law_build_cached(const char *src, char *so_path, size_t size, rs_error *err);

#ifdef __cplusplus
}
#endif

#endif
