/* What the engines' adapters of fix wall/rigid do alike, without an engine's header
 * (adapter.h). */
#include "adapter.h"

#include <fstream>
#include <iterator>
#include <vector>

void rs_adapter_reduce(MPI_Comm comm, double *v, int n, int op)
{
    const MPI_Op mop = op == RS_REDUCE_MIN   ? MPI_MIN
                       : op == RS_REDUCE_MAX ? MPI_MAX
                                             : MPI_SUM;
    std::vector<double> in(v, v + n);
    MPI_Allreduce(in.data(), v, n, MPI_DOUBLE, mop, comm);
}

double rs_adapter_time(double atime, long long atimestep, long long ntimestep, double dt,
                       bool setup)
{
    const double end = atime + (ntimestep - atimestep) * dt;
    return setup ? end : end - dt;
}

rs_wall_run rs_adapter_run(double dt, double skin, int delay, int every, int dist_check,
                           int build_once, const double *boxlo, const double *boxhi,
                           int exchange_max)
{
    rs_wall_run run;
    std::memset(&run, 0, sizeof run);
    run.dt = dt;
    run.skin = skin;
    run.half_skin = delay == 0 && every == 1 && dist_check && !build_once;
    for (int d = 0; d < 3; d++) {
        run.box_lo[d] = boxlo[d];
        run.box_hi[d] = boxhi[d];
    }
    run.exchange_max = exchange_max;
    return run;
}

int rs_adapter_pack_restart(const rs_wall *w, int i, double *buf)
{
    const int n = rs_wall_pack(w, i, buf + 1);
    buf[0] = n + 1;
    return n + 1;
}

int rs_adapter_unpack_restart(rs_wall *w, int i, const double *extra, int nth,
                              rs_error *err)
{
    int m = 0;
    for (int k = 0; k < nth; k++)
        m += static_cast<int>(extra[m]);
    const int n = static_cast<int>(extra[m]) - 1;
    return rs_wall_unpack_restart(w, i, &extra[m + 1], n, err);
}

void rs_adapter_write_restart(rs_wall *w, FILE *fp, int me)
{
    std::vector<double> list((size_t)rs_wall_restart_size(w));
    rs_wall_write_restart(w, list.data());
    if (me != 0)
        return;
    const int size = (int)(list.size() * sizeof(double));
    std::fwrite(&size, sizeof(int), 1, fp);
    std::fwrite(list.data(), sizeof(double), list.size(), fp);
}

std::string rs_adapter_job_name(const char *default_log)
{
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<std::string> args;
    for (size_t i = 0; i < all.size();) {
        size_t j = all.find('\0', i);
        if (j == std::string::npos)
            j = all.size();
        args.push_back(all.substr(i, j - i));
        i = j + 1;
    }
    std::string log = default_log, input;
    for (size_t i = 0; i + 1 < args.size(); i++) {
        if (args[i] == "-log" || args[i] == "-l")
            log = args[i + 1];
        else if (args[i] == "-in" || args[i] == "-i")
            input = args[i + 1];
    }
    std::string name = log == "none" ? input : log;
    const size_t slash = name.rfind('/');
    if (slash != std::string::npos)
        name = name.substr(slash + 1);
    const size_t dot = name.rfind('.');
    if (dot != std::string::npos && dot > 0)
        name = name.substr(0, dot);
    if (name.empty()) { /* input from stdin, no log: the engine's name (log.NAME) */
        const char *suffix = std::strrchr(default_log, '.');
        name = suffix ? suffix + 1 : default_log;
    }
    return name;
}

void rs_adapter_info(FILE *screen, FILE *logfile, const char *msg)
{
    for (FILE *fp : {screen, logfile})
        if (fp)
            std::fprintf(fp, "INFO: %s\n", msg);
}

void rs_adapter_print(FILE *screen, FILE *logfile, const char *text)
{
    if (screen)
        std::fprintf(screen, "%s\n", text);
    if (logfile)
        std::fprintf(logfile, "%s\n", text);
    if (!screen && !logfile) {
        std::fprintf(stdout, "%s\n", text);
        std::fflush(stdout);
    }
}
