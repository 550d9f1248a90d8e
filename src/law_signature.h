/* rigidsurf (private): the SUBROUTINE statement of a user routine, read from its Fortran
 * source, and its argument count checked against the lists the loaders call.
 *
 * A routine's dummy arguments are passed by position, so a list that differs from the
 * one the adapter calls shifts every argument after the difference. The names are the
 * author's (AMKI for DVISCOUS, lower case, ...); only their count is checked. */
#ifndef RIGIDSURF_LAW_SIGNATURE_H
#define RIGIDSURF_LAW_SIGNATURE_H

#include "rigidsurf/types.h"

#include <stddef.h>

/// Where a SUBROUTINE statement is and how many dummy arguments it lists.
typedef struct rs_fsub {
    char file[4096]; ///< the file that holds it (the source or a file it INCLUDEs)
    int line;        ///< the line the statement starts on, from 1
    int nargs;       ///< its dummy arguments (0 for SUBROUTINE NAME or NAME())
} rs_fsub;

/// Scans Fortran text (fixed form when free_form is 0: label in columns 1-5,
/// continuation in column 6, text to column 132, 'C', 'c', '*' or '!' comment lines,
/// tabs; free form: '&' continuation, '!' comments) for the SUBROUTINE statement of
/// name (any case). file names the text in messages and in sub->file; the files the
/// text INCLUDEs are read from file's folder. RS_OK with *sub filled; RS_ERR_NOTFOUND
/// when there is none; RS_ERR_PARSE, naming file and line, when its argument list is
/// not closed or holds an entry that is not a name.
int rs_fsub_scan(const char *text, size_t n, int free_form, const char *file,
                 const char *name, rs_fsub *sub, rs_error *err);

/// rs_fsub_scan on the file path, in the form its extension names
/// (rs_law_source_form); RS_ERR_IO when it cannot be read.
int rs_fsub_read(const char *path, const char *name, rs_fsub *sub, rs_error *err);

/// The argument lists the loaders call a routine with.
typedef enum rs_arglist {
    RS_ARGS_VUINTER = 1,      ///< Abaqus/Explicit VUINTER, 49 arguments
    RS_ARGS_UINTER = 2,       ///< UINTER with DVISCOUS, DSTRUCTURAL and FREQR, 47
    RS_ARGS_UINTER_OLDER = 3, ///< the older UINTER, without those three, 44
    RS_ARGS_FRIC = 4          ///< FRIC, 39
} rs_arglist;

/// Reads the SUBROUTINE statement of routine ("vuinter", "uinter" or "fric") in the
/// source src and finds the list its argument count matches (*list). A count that
/// matches none is RS_ERR_ARG, naming the file, the line, the count found and the
/// counts of the lists expected; a missing statement is RS_ERR_NOTFOUND.
int rs_law_source_list(const char *src, const char *routine, rs_arglist *list,
                       rs_error *err);

#endif
