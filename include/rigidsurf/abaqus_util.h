/* rigidsurf: the Abaqus utility routines that user subroutines call (XPLB_ABQERR,
 * STDB_ABQERR, XIT, XPLB_EXIT, GETJOBNAME, GETOUTDIR, GETNUMCPUS, GETRANK,
 * GETPARTINFO and their V-forms, VGETVRM) and rigidsurf's RS_GETDEM.
 *
 * They live in the shared library librigidsurf_abaqus, which user routines link against
 * (rigidsurf-build-law does) and which every rigidsurf host loads, so a routine's calls
 * reach the host that called it. A host describes itself once (rs_abq_set_host); the law
 * adapters bracket every call of a user routine with rs_abq_call_begin/rs_abq_call_end,
 * which tells the utilities which contacts they are asked about and collects the errors
 * a routine raised.
 *
 * Severities of XPLB_ABQERR / STDB_ABQERR (LOP): 1 an information line, -1 a warning,
 * -2 an error that ends the run once the routine returns (rs_abq_call_end reports it),
 * -3 an error that ends the run at once (the host's fatal hook).
 *
 * A setup call (rs_law_block.setup: the forces before a run's first increment, history
 * restored afterwards) repeats the first increment's call; its information and warning
 * lines are not printed, so a routine's messages appear once per increment. */
#ifndef RIGIDSURF_ABAQUS_UTIL_H
#define RIGIDSURF_ABAQUS_UTIL_H

#include "rigidsurf/law.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Severity of a message from a user routine.
enum {
    RS_ABQ_INFO = 1,     ///< LOP = 1
    RS_ABQ_WARNING = -1, ///< LOP = -1
    RS_ABQ_ERROR = -2,   ///< LOP = -2: the run ends after the routine returns
    RS_ABQ_FATAL = -3    ///< LOP = -3, XIT, XPLB_EXIT: the run ends now
};

/// What a host tells the utilities about itself. Strings are copied.
typedef struct rs_abq_host {
    /// Prints one message of a user routine (severity RS_ABQ_INFO or RS_ABQ_WARNING;
    /// errors reach the host through rs_abq_call_end or fatal). NULL: stderr.
    void (*message)(void *ctx, int severity, const char *text);
    /// Ends the run with text (an error of severity -3, XIT, XPLB_EXIT). It must not
    /// return; if it does, the process exits with status 1. NULL: stderr, exit(1).
    void (*fatal)(void *ctx, const char *text);
    void *ctx;           ///< passed to message and fatal
    const char *jobname; ///< GETJOBNAME (NULL: "rigidsurf")
    const char *outdir;  ///< GETOUTDIR (NULL: the working directory)
    int rank;            ///< GETRANK: this process's rank, from 0
    int ncpus;           ///< GETNUMCPUS: the number of ranks (< 1: 1)
} rs_abq_host;

/// Installs the host (NULL: the defaults above). Not thread-safe; call before any law.
void rs_abq_set_host(const rs_abq_host *host);

/// The host's rank and rank count as the utilities see them.
int rs_abq_rank(void);
int rs_abq_ncpus(void);

/// Brackets one call of a user routine on block b: k is the contact of a point-wise
/// routine (UINTER, FRIC), -1 for a block routine (VUINTER). routine names it in
/// messages ("VUINTER", "UINTER", "FRIC"). b must stay valid until rs_abq_call_end.
void rs_abq_call_begin(const rs_law_block *b, int k, const char *routine);
/// Ends the bracket. RS_OK, or RS_ERR_ARG with err holding the first error (severity
/// -2) the routine raised, named by its routine and the law.
int rs_abq_call_end(rs_error *err);

/// The DEM data of one contact of the current call (the RS_GETDEM routine):
/// out[0..7] = radius, mass, effective radius, relative velocity of the contact point
/// in (n, t1, t2), wall curvatures along t1 and t2 (0 where the engine has none).
/// knode is 1-based within a VUINTER block; a point-wise routine passes 1. Returns 0,
/// or 1 when there is no current call or knode is out of range (out is zeroed).
int rs_abq_dem_fields(int knode, double out[8]);

/// The message text of XPLB_ABQERR: string (length len, blank-padded) with %I, %R, %D
/// and %S replaced in order by intv, realv and charv (CHARACTER*8 entries). Written to
/// out (NUL-terminated, truncated to size).
void rs_abq_format(char *out, size_t size, const char *string, size_t len, const int *intv,
                   const double *realv, const char *charv);

#ifdef __cplusplus
}
#endif

#endif
