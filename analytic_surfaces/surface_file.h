/* Surface files (reader.c): what the reader shares with the kinds' syntax, each kind's
 * data lines and the making of its surface (rs_surface_syntax, reached through the kind's
 * table, rs_surface_ops.syntax), and the keyword text's values and messages
 * (keyword_text.c). Private to the geometry layer. */
#ifndef RS_SURFACE_FILE_H
#define RS_SURFACE_FILE_H

#include "rigidsurf/surface.h"

#include <stddef.h>

/// Most values on one line.
#define RS_SF_MAXTOK 16

/// A value of a line (not NUL-terminated).
typedef struct tok {
    const char *p;
    int len;
} tok;

/// Where the reader is: messages read "ORIGIN:LINE: what was expected".
typedef struct parser {
    const char *origin;
    int line;
    rs_error *err;
    int from_file; /* origin is the path of the file being read */
} parser;

/* A surface being read: its *SURFACE line's parameters, then what its kind's data lines
 * give (rs_surface_syntax.line). */
typedef struct draft {
    int active;
    int kline; /* line of its *SURFACE */
    rs_surface_kind kind;
    const struct rs_surface_syntax *syntax; /* its kind's (TYPE=) */
    char name[80];
    int sides;
    double fillet;
    int bounded;
    double zmin, zmax;
    int ncoord; /* coordinate lines read */
    double ab[6], c[3];
    int started;
    double cur[2];
    int start_line;
    char file[4096]; /* MESH: FILE= as written */
    double scale;    /* MESH: SCALE= */
    int placed;      /* MESH: the placement line was read */
    int self;        /* MESH: its elements are in this file (no FILE=) */
    double abc[9];
    rs_segment *seg;
    int *segline;
    int nseg, cap;
} draft;

/// Parameters of *SURFACE that a kind takes besides TYPE=, NAME= and SIDES=.
enum { RS_SF_FILLET = 1, RS_SF_EXTENT = 2, RS_SF_FILE = 4 };

/// How a surface file describes a kind: its parameters, its data lines and the making of
/// its surface. Messages read "ORIGIN:LINE: what was expected" (rs_sf_error).
typedef struct rs_surface_syntax {
    rs_surface_kind kind;
    unsigned params; ///< RS_SF_FILLET, RS_SF_EXTENT, RS_SF_FILE (with SCALE=)
    /// Optional: checks the *SURFACE line's parameters (have_file: FILE= was given).
    int (*head)(const parser *ps, draft *d, int have_file);
    /// One data line of the surface, t[0 .. nt).
    int (*line)(const parser *ps, tok *t, int nt, draft *d);
    /// The surface of a complete draft, into s (zeroed); on error s is left zeroed.
    int (*build)(parser *ps, draft *d, rs_surface *s);
} rs_surface_syntax;

/// The kinds that surface files name, in the order messages list them (surface_kinds.c):
/// kind i's table, NULL past the last.
const rs_surface_ops *rs_surface_kind_at(int i);

/// The syntax of the analytic kinds (profile_file.c).
extern const rs_surface_syntax rs_segments_syntax, rs_cylinder_syntax, rs_revolution_syntax;

/// An error at the parser's line: fmt takes the strings a and b (NULL: empty).
int rs_sf_error(const parser *ps, int code, const char *fmt, const char *a, const char *b);
/// Upper-cased token without blanks, truncated to cap - 1 characters.
void rs_sf_normkey(const tok *t, char *out, size_t cap);
/// Printable copy of a token for messages.
void rs_sf_showtok(const tok *t, char *out, size_t cap);
/// A finite number of magnitude at most RS_COORD_MAX (a Fortran D exponent allowed).
int rs_sf_number(const parser *ps, const tok *t, double *v);
/// n numbers.
int rs_sf_numbers(const parser *ps, const tok *t, int n, double *v);
/// The range of a number: finite and of magnitude at most RS_COORD_MAX, else an error of
/// the given code that shows it as show (NULL: the value itself).
int rs_sf_value(const parser *ps, int code, double x, const char *show);
/// One profile line of draft d at the parser's line: word RS_WORD_START (v: x, y) or a
/// segment, RS_WORD_LINE (x1, y1), RS_WORD_CIRCL (x1, y1, xc, yc), RS_WORD_PARAB (xm, ym,
/// x1, y1), from the current point (profile_file.c).
int rs_sf_profile_item(const parser *ps, draft *d, rs_profile_word word, const double v[4]);
/// A line whose first value holds blanks, its values written without commas: an error
/// that shows the line's form. A profile word shows its own form; a line that starts
/// with a number shows points (its form; NULL where no point line is expected: no
/// error). RS_OK for any other line.
int rs_sf_commas(const parser *ps, const tok *t, const char *points);
/// Splits a line at commas; tokens are trimmed. Returns the count or -1 beyond
/// RS_SF_MAXTOK.
int rs_sf_split(const char *s, int len, tok *t);

#endif
