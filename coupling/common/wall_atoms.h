/* The per-atom half of fix wall/rigid, alike in both engines (coupling/liggghts/,
 * coupling/lammps/): the wall's per-atom history (rs_wall_grow, _copy, _clear, _pack,
 * _unpack) and the fix's 6-column per-atom output through the engine's atom callbacks,
 * its restart records (per atom and global), the global vector summed once a step, and
 * the memory it holds. LIGGGHTS forked its Fix from LAMMPS's, so both have these callbacks
 * by the same names: RsWallAtoms<Fix> is the engine's Fix with them, and each adapter's
 * FixWallRigid derives from it, instantiating it where the engine's headers are. The fix
 * gives fail and fail_one (its errors, as the engine ends a run) and, where the engine
 * sizes its exchange buffer from the fix, exchanged. */
#ifndef RIGIDSURF_COUPLING_WALL_ATOMS_H
#define RIGIDSURF_COUPLING_WALL_ATOMS_H

#include "adapter.h"

#include <climits>
#include <string>

template <class Fix> class RsWallAtoms : public Fix
{
  public:
    using Fix::Fix;

    double compute_vector(int n) override
    {
        if (!out_valid_ || out_step_ != this->update->ntimestep) {
            rs_wall_vector(wall_, out_);
            out_valid_ = true;
            out_step_ = this->update->ntimestep;
        }
        return (n >= 0 && n < RS_WALL_NVEC) ? out_[n] : 0.0;
    }

    void write_restart(FILE *fp) override
    {
        rs_adapter_write_restart(wall_, fp, this->comm->me);
    }

    void restart(char *buf) override
    {
        rs_error err;
        rs_error_clear(&err);
        if (rs_wall_read_restart(wall_, reinterpret_cast<const double *>(buf), INT_MAX,
                                 &err) != RS_OK)
            fail(err.msg);
    }

    void grow_arrays(int nmax) override
    {
        rs_error err;
        rs_error_clear(&err);
        if (rs_wall_grow(wall_, nmax, &err) != RS_OK)
            fail_one(err.msg);
        if (!info_->peratom || nmax <= nmax_)
            return;
        this->memory->grow(this->array_atom, nmax, 6, "wall/rigid:array_atom");
        for (int i = nmax_; i < nmax; i++)
            for (int c = 0; c < 6; c++)
                this->array_atom[i][c] = 0.0;
        nmax_ = nmax;
    }

    void copy_arrays(int i, int j, int) override
    {
        rs_wall_copy(wall_, i, j);
        for (int c = 0; this->array_atom && c < 6; c++)
            this->array_atom[j][c] = this->array_atom[i][c];
    }

    void set_arrays(int i) override
    {
        rs_wall_clear(wall_, i);
        for (int c = 0; this->array_atom && c < 6; c++)
            this->array_atom[i][c] = 0.0;
    }

    int pack_exchange(int i, double *buf) override
    {
        return rs_wall_pack(wall_, i, buf);
    }

    int unpack_exchange(int nlocal, double *buf) override
    {
        rs_error err;
        rs_error_clear(&err);
        const int n = rs_wall_unpack(wall_, nlocal, buf, &err);
        if (n < 0)
            fail_one(err.msg);
        for (int c = 0; this->array_atom && c < 6; c++)
            this->array_atom[nlocal][c] = 0.0;
        exchanged();
        return n;
    }

    int pack_restart(int i, double *buf) override
    {
        return rs_adapter_pack_restart(wall_, i, buf);
    }

    void unpack_restart(int nlocal, int nth) override
    {
        rs_error err;
        rs_error_clear(&err);
        if (rs_adapter_unpack_restart(wall_, nlocal, this->atom->extra[nlocal], nth,
                                      &err) != RS_OK)
            fail_one(err.msg);
    }

    int size_restart(int) override
    {
        return rs_wall_pack_size(wall_) + 1;
    }

    int maxsize_restart() override
    {
        return rs_wall_pack_size(wall_) + 1;
    }

    double memory_usage() override
    {
        return rs_wall_memory(wall_) +
               (info_->peratom ? 6.0 * nmax_ * sizeof(double) : 0.0);
    }

  protected:
    /// An error of all ranks, and one of this rank alone, each ending the run.
    [[noreturn]] virtual void fail(const std::string &msg) = 0;
    [[noreturn]] virtual void fail_one(const std::string &msg) = 0;
    /// After an atom came in through the exchange (its slots may have grown).
    virtual void exchanged() {}

    rs_wall *wall_ = nullptr;
    const rs_wall_info *info_ = nullptr;
    int nmax_ = 0; ///< rows of the per-atom output (peratom yes)
    /* the global vector, summed over the ranks once a step */
    double out_[RS_WALL_NVEC] = {};
    long long out_step_ = -1;
    bool out_valid_ = false;
};

#endif
