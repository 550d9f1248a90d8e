/* What the engines' adapters of fix wall/rigid do alike (coupling/liggghts/,
 * coupling/lammps/), written once and free of any engine's header: the host table's
 * callbacks onto the fix, sums over the ranks, the time of a call, the run's settings, the
 * per-atom restart records in LAMMPS's layout (which LIGGGHTS keeps), the wall's global
 * restart record, and the engine as the host of the Abaqus utility routines. The templates
 * take the engine's own classes (its fix, its LAMMPS instance) and are instantiated in each
 * adapter, where the engine's headers are. */
#ifndef RIGIDSURF_COUPLING_ADAPTER_H
#define RIGIDSURF_COUPLING_ADAPTER_H

#include "rigidsurf/abaqus_util.h"
#include "rigidsurf/wall.h"

#include <cstdio>
#include <cstring>
#include <mpi.h>
#include <string>

/// v[0 .. n) replaced by its sum, smallest or largest value over comm (RS_REDUCE_*).
void rs_adapter_reduce(MPI_Comm comm, double *v, int n, int op);

/// The time at the start of the increment a call handles, from the engine's last time
/// atime at step atimestep: the end of step ntimestep less dt, or now at a setup call.
double rs_adapter_time(double atime, long long atimestep, long long ntimestep, double dt,
                       bool setup);

/// A run's settings from the engine's: its time step, neighbour skin and rebuild rule
/// (delay, every, check, once), box and exchange limit (0: none).
rs_wall_run rs_adapter_run(double dt, double skin, int delay, int every, int dist_check,
                           int build_once, const double *boxlo, const double *boxhi,
                           int exchange_max);

/// Atom i's restart record in buf: its length (LAMMPS's first value, which the engine
/// reads to skip it), then the wall's record. Returns the doubles written.
int rs_adapter_pack_restart(const rs_wall *w, int i, double *buf);

/// Atom i's history from its restart values extra (the engine's atom->extra[i]), where
/// this fix's record is the nth.
int rs_adapter_unpack_restart(rs_wall *w, int i, const double *extra, int nth,
                              rs_error *err);

/// The wall's global restart record (collective); rank me 0 writes its size in bytes and
/// the record to fp.
void rs_adapter_write_restart(rs_wall *w, FILE *fp, int me);

/// The job name GETJOBNAME gives: the log file's name (-log, -l) without its folder and
/// suffix; with -log none the input script's (-in, -i); the engine's default_log
/// (log.NAME) without -log; NAME when there is neither a log nor an input file.
std::string rs_adapter_job_name(const char *default_log);

/// A user routine's information line or warning: the screen and the log of rank 0; a rank
/// without either prints on its standard output.
void rs_adapter_print(FILE *screen, FILE *logfile, const char *text);

/// The wall's line of information (rs_wall_host.info) as `INFO: msg` on the screen and in
/// the log, each where the engine has one.
void rs_adapter_info(FILE *screen, FILE *logfile, const char *msg);

/// The host table of fix F (its members reduce, variable_find, variable_eval, material,
/// warning, info, engine_law) on rank me of ntypes material types; engine_law_name names the
/// engine's own law.
template <class F>
rs_wall_host rs_adapter_host(F *fix, int me, int ntypes, const char *engine_law_name)
{
    struct cb {
        static F *self(void *ctx)
        {
            return static_cast<F *>(ctx);
        }
        static void reduce(void *ctx, double *v, int n, int op)
        {
            self(ctx)->reduce(v, n, op);
        }
        static int variable_find(void *ctx, const char *name)
        {
            return self(ctx)->variable_find(name);
        }
        static double variable_eval(void *ctx, int index, int why)
        {
            return self(ctx)->variable_eval(index, why);
        }
        static int material(void *ctx, const char *name, int i, int j, int required,
                            const char *who, double *value, rs_error *err)
        {
            return self(ctx)->material(name, i, j, required, who, value, err);
        }
        static void warning(void *ctx, const char *msg)
        {
            self(ctx)->warning(msg);
        }
        static void info(void *ctx, const char *msg)
        {
            self(ctx)->info(msg);
        }
        static int engine_law(void *ctx, const char *const *words, int nwords,
                              const rs_law **law, rs_error *err)
        {
            return self(ctx)->engine_law(words, nwords, law, err);
        }
    };
    rs_wall_host h;
    std::memset(&h, 0, sizeof h);
    h.ctx = fix;
    h.rank = me;
    h.ntypes = ntypes;
    h.reduce = cb::reduce;
    h.variable_find = cb::variable_find;
    h.variable_eval = cb::variable_eval;
    h.material = cb::material;
    h.warning = cb::warning;
    h.info = cb::info;
    h.engine_law = cb::engine_law;
    h.engine_law_name = engine_law_name;
    return h;
}

/// The index of the equal-style variable name of the engine instance lmp, RS_VAR_MISSING
/// or RS_VAR_NOT_EQUAL.
template <class L> int rs_adapter_variable_find(L *lmp, const char *name)
{
    const int iv = lmp->input->variable->find(const_cast<char *>(name));
    if (iv < 0)
        return RS_VAR_MISSING;
    return lmp->input->variable->equalstyle(iv) ? iv : RS_VAR_NOT_EQUAL;
}

/// The value of variable index. A servo's target is read after the step's forces, as
/// LIGGGHTS's servo reads it: the computes it uses are then current, and asked for again
/// at the next step.
template <class L> double rs_adapter_variable_eval(L *lmp, int index, int why)
{
    if (why != RS_VAR_SERVO)
        return lmp->input->variable->compute_equal(index);
    lmp->modify->clearstep_compute();
    const double v = lmp->input->variable->compute_equal(index);
    lmp->modify->addstep_compute(lmp->update->ntimestep + 1);
    return v;
}

/// The engine instance lmp as the host of the Abaqus utility routines that user routines
/// call (include/rigidsurf/abaqus_util.h): their lines to its screen and log, their errors
/// through its error->one, its rank and rank count, the job name (default_log: the
/// engine's own log file name).
template <class L> void rs_adapter_abaqus_host(L *lmp, const char *default_log)
{
    struct cb {
        static void message(void *ctx, int, const char *text)
        {
            L *l = static_cast<L *>(ctx);
            rs_adapter_print(l->screen, l->logfile, text);
        }
        static void fatal(void *ctx, const char *text)
        {
            static_cast<L *>(ctx)->error->one(__FILE__, __LINE__, text);
        }
    };
    const std::string job = rs_adapter_job_name(default_log);
    rs_abq_host host;
    std::memset(&host, 0, sizeof host);
    host.message = cb::message;
    host.fatal = cb::fatal;
    host.ctx = lmp;
    host.jobname = job.c_str();
    host.outdir = NULL;
    host.rank = lmp->comm->me;
    host.ncpus = lmp->comm->nprocs;
    rs_abq_set_host(&host);
}

#endif
