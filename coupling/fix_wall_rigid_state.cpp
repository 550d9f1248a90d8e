/* fix wall/rigid: per-atom contact history (rows and slot-major slots) with its MPI
 * exchange, and the restart file (global record and per-atom records). */
#include "fix_wall_rigid.h"
#include "rigidsurf/vec.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "memory.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <sys/mman.h>
#include <vector>

using namespace LAMMPS_NS;

namespace
{

/* Restart layout version (global record). */
/* 7: the global record ends with the spin's angle, its remainder, rate and orientation
 * S (12 doubles; absent in 6, read as no spin so far);
 * 6: directory entries are RS_DIR_LIVE(f) = f + 1, empty 0, leaving -(f + 1) (5: f, -1
 * and -2 - f, so an entry of 5 is one less: read and converted), and the global record
 * ends with the servo's controller state (integral of the error, last process value;
 * absent in 5); 4: a slot ends with the contact's sed, fluxSlv and fluxMst; 3: each
 * atom's record starts with the capacity it was written with (the capacity grows during
 * a run); 2: directory in the row, slots after it */
const double kRestartVersion = 7.0;
/* The oldest version read: 5, its directories converted (unpack_restart). */
const double kRestartOldest = 5.0;

} // namespace

void FixWallRigid::clear_row(int i)
{
    double *r = row_[i];
    double *h = slot0(i);
    const ptrdiff_t stride = slot_stride();
    rs_track_clear(&tracker_, r, h, stride); /* the whole slot, its energies included */
    r[tprev_offset()] = NAN;
    for (size_t p = 0; p < predef_names_.size(); p++)
        r[pred_offset() + (int)p] = NAN;
}

/* The wall may have moved since the candidates were chosen: every point of the box moved
 * by at most |dD| + |dphi| * (largest distance of a box corner from the rotation centre).
 * Beyond half the skin the list is refreshed, as LIGGGHTS reneighbours when a particle
 * moved half the skin. */
/* ---------------------------------------------------------------------------------- */
/* Restart: global state (motion, wall heat, energy totals) and per-atom history.     */

enum {
    RST_VERSION,
    RST_CAPACITY,
    RST_NSTATEV,
    RST_NPRED,
    RST_T,
    RST_T_ERR,
    RST_DISP,
    RST_DISP_ERR = RST_DISP + 3,
    RST_PHI = RST_DISP_ERR + 3,
    RST_PHI_ERR,
    RST_VEL,
    RST_OMEGA = RST_VEL + 3,
    RST_TEMP,
    RST_DTEMP,
    RST_HEAT,
    RST_DISS,
    RST_COUNT = RST_DISS + 4
};

void FixWallRigid::write_restart(FILE *fp)
{
    double loc[5] = {heat_wall_, diss_[0], diss_[1], diss_[2], diss_[3]}, all[5];
    MPI_Allreduce(loc, all, 5, MPI_DOUBLE, MPI_SUM, world);
    double list[RST_COUNT];
    list[RST_VERSION] = kRestartVersion;
    int cap = capacity_; /* ranks may have grown apart: the largest */
    MPI_Allreduce(&capacity_, &cap, 1, MPI_INT, MPI_MAX, world);
    list[RST_CAPACITY] = cap;
    list[RST_NSTATEV] = nstatev_;
    list[RST_NPRED] = (double)predef_names_.size();
    list[RST_T] = motion_.t;
    list[RST_T_ERR] = motion_.t_err;
    for (int d = 0; d < 3; d++) {
        list[RST_DISP + d] = motion_.disp[d];
        list[RST_DISP_ERR + d] = motion_.disp_err[d];
        list[RST_VEL + d] = motion_.vel[d];
    }
    list[RST_PHI] = motion_.phi;
    list[RST_PHI_ERR] = motion_.phi_err;
    list[RST_OMEGA] = motion_.omega;
    list[RST_TEMP] = temp_wall_;
    list[RST_DTEMP] = dtemp_wall_;
    list[RST_HEAT] = all[0];
    for (int d = 0; d < 4; d++)
        list[RST_DISS + d] = all[1 + d];
    /* then the facets' wear (`wear finnie`): its count and the totals */
    const int nwear = wear_ ? (int)wear_el_.size() : 0;
    std::vector<double> wear((size_t)nwear + 1, 0.0);
    wear[0] = nwear;
    if (nwear)
        MPI_Allreduce(wear_el_.data(), wear.data() + 1, nwear, MPI_DOUBLE, MPI_SUM, world);
    const double servo[2] = {servo_.sum_err, servo_.old_pv};
    /* then the spin (from version 7): its angle, remainder, rate and the orientation S */
    double spin[12] = {motion_.spin_phi, motion_.spin_phi_err, motion_.spin_omega};
    std::memcpy(spin + 3, motion_.S, sizeof motion_.S);
    if (comm->me == 0) {
        int size = (RST_COUNT + 1 + nwear + 2 + 12) * sizeof(double);
        std::fwrite(&size, sizeof(int), 1, fp);
        std::fwrite(list, sizeof(double), RST_COUNT, fp);
        std::fwrite(wear.data(), sizeof(double), (size_t)nwear + 1, fp);
        std::fwrite(servo, sizeof(double), 2, fp);
        std::fwrite(spin, sizeof(double), 12, fp);
    }
}

void FixWallRigid::restart(char *buf)
{
    const double *list = reinterpret_cast<const double *>(buf);
    const double version = list[RST_VERSION];
    if (!(version >= kRestartOldest && version <= kRestartVersion) ||
        version != (double)(int)version) {
        std::ostringstream o;
        o << "the restart file holds wall/rigid data of layout version " << version
          << "; this build reads versions " << kRestartOldest << " to " << kRestartVersion
          << " (write the restart file again with a matching build)";
        fail(o.str());
    }
    restart_version_ = version;
    if ((int)list[RST_NSTATEV] != nstatev_ ||
        (int)list[RST_NPRED] != (int)predef_names_.size()) {
        std::ostringstream o;
        o << "restart file has " << (int)list[RST_NSTATEV] << " state variables and "
          << (int)list[RST_NPRED] << " predef fields; this fix has " << nstatev_ << " and "
          << predef_names_.size() << " (keep the law, statev and predef unchanged)";
        fail(o.str());
    }
    /* the contact capacity the run had grown to */
    const int cap = (int)list[RST_CAPACITY];
    if (cap > capacity_ && !grow_capacity(cap)) {
        std::ostringstream o;
        o << "restart file has " << cap << " contact slots per atom; this fix can hold at "
          << "most " << max_capacity();
        fail(o.str());
    }
    motion_.t = list[RST_T];
    motion_.t_err = list[RST_T_ERR];
    for (int d = 0; d < 3; d++) {
        motion_.disp[d] = list[RST_DISP + d];
        motion_.disp_err[d] = list[RST_DISP_ERR + d];
        if (!var_vel_[d].empty())
            motion_.vel[d] = list[RST_VEL + d];
    }
    motion_.phi = list[RST_PHI];
    motion_.phi_err = list[RST_PHI_ERR];
    if (!var_omega_.empty())
        motion_.omega = list[RST_OMEGA];
    /* the spin, when both the file (version 7 on) and this fix have one */
    const int nw = std::max((int)list[RST_COUNT], 0);
    const double *spin = list + RST_COUNT + 1 + nw + 2;
    if (version >= 7.0 && motion_.spin_on) {
        motion_.spin_phi = spin[0];
        motion_.spin_phi_err = spin[1];
        if (!var_spin_.empty())
            motion_.spin_omega = spin[2];
        std::memcpy(motion_.S, spin + 3, sizeof motion_.S);
    }
    /* The pose from the restored phi and D: a zero step with the rates switched off. */
    rs_motion_rates_fn rates = motion_.rates;
    motion_.rates = NULL;
    rs_error err;
    rs_error_clear(&err);
    rs_motion_advance(&motion_, 0.0, &err);
    motion_.rates = rates;
    temp_wall_ = list[RST_TEMP];
    dtemp_wall_ = list[RST_DTEMP];
    temp_mst_[0] = temp_wall_;
    dtemp_mst_[0] = dtemp_wall_;
    /* Totals live on rank 0; the others add their shares from here on. */
    const bool root = comm->me == 0;
    heat_wall_ = root ? list[RST_HEAT] : 0.0;
    for (int d = 0; d < 4; d++)
        diss_[d] = root ? list[RST_DISS + d] : 0.0;
    /* the facets' wear, when both the file and this fix keep it */
    const int nwear = (int)list[RST_COUNT];
    if (wear_ && nwear > 0) {
        const int nf = rs_surface_facet_count(&surf_);
        if (nwear != nf) {
            std::ostringstream o;
            o << "restart file has the wear of " << nwear << " facets; this fix's mesh has "
              << nf << " (keep the surface unchanged)";
            fail(o.str());
        }
        wear_el_.assign((size_t)nf, 0.0);
        if (root)
            for (int k = 0; k < nf; k++)
                wear_el_[k] = list[RST_COUNT + 1 + k];
    }
    /* the servo's controller (from version 6) and the rate it set, the same on every
     * rank */
    const double *servo = list + RST_COUNT + 1 + std::max(nwear, 0);
    if (servo_.on) {
        servo_.sum_err = version >= 6.0 ? servo[0] : 0.0;
        servo_.old_pv = version >= 6.0 ? servo[1] : 0.0;
        for (int d = 0; d < 3; d++)
            motion_.vel[d] = list[RST_VEL + d];
        motion_.omega = list[RST_OMEGA];
    }
}

/* The per-atom history of a large run walks through megabytes each step: its blocks are
 * offered to the kernel as huge pages (one TLB entry for 32768 hertz slots instead of one
 * per 64), where the kernel gives them on request (transparent_hugepage madvise). */
static const size_t kHugePage = (size_t)2 << 20;

static void advise_huge(void *p, size_t bytes)
{
#ifdef MADV_HUGEPAGE
    const uintptr_t page = 4096, a = ((uintptr_t)p + page - 1) & ~(page - 1),
                    b = ((uintptr_t)p + bytes) & ~(page - 1);
    if (bytes >= kHugePage && b > a)
        madvise((void *)a, b - a, MADV_HUGEPAGE); /* a hint: its failure changes nothing */
#else
    (void)p, (void)bytes;
#endif
}

/* Slot memory, on 2 MB boundaries when it is that large; freed with free(). */
double *FixWallRigid::alloc_slots(size_t n)
{
    const size_t bytes = std::max(n, (size_t)1) * sizeof(double);
    void *p = NULL;
    if (posix_memalign(&p, bytes >= kHugePage ? kHugePage : 64, bytes) != 0)
        fail_one("out of memory for the contact history slots");
    advise_huge(p, bytes);
    return static_cast<double *>(p);
}

void FixWallRigid::grow_arrays(int nmax)
{
    if (nmax <= nmax_)
        return;
    memory->grow(row_, nmax, row_size(), "wall/rigid:history");
    advise_huge(row_[0], (size_t)nmax * row_size() * sizeof(double));
    if (peratom_)
        memory->grow(array_atom, nmax, 6, "wall/rigid:array_atom");
    /* The slots move: slot j of the old nmax_ atoms to the start of block j. */
    const size_t hs = slot_size(), oldblk = (size_t)nmax_ * hs, blk = (size_t)nmax * hs;
    double *h = alloc_slots(capacity_ * blk);
    for (int j = 0; j < capacity_; j++)
        if (oldblk)
            std::memcpy(h + j * blk, hist_ + j * oldblk, sizeof(double) * oldblk);
    std::free(hist_);
    hist_ = h;
    const int old = nmax_;
    nmax_ = nmax;
    for (int i = old; i < nmax; i++) {
        clear_row(i);
        for (int c = 0; array_atom && c < 6; c++)
            array_atom[i][c] = 0.0;
    }
}

int FixWallRigid::max_capacity() const
{
    /* 1 (capacity) + capacity (directory) + the rest of the row + capacity slots */
    const int fixed = 1 + row_size() - capacity_;
    const int cap = (kExchangeMax - fixed) / (slot_size() + 1);
    return std::min(cap, (int)RS_TRACK_MAX_CAPACITY);
}

bool FixWallRigid::grow_capacity(int need)
{
    if (need <= capacity_)
        return true;
    const int maxcap = max_capacity();
    if (need > maxcap)
        return false;
    int cap = capacity_;
    while (cap < need)
        cap *= 2;
    cap = std::min(cap, maxcap);
    /* every atom's history through the new layout: packed at the old capacity, then
     * unpacked into rows and slots made for the new one */
    const int old_as = 1 + atom_size();
    std::vector<double> keep((size_t)nmax_ * old_as);
    for (int i = 0; i < nmax_; i++) {
        keep[(size_t)i * old_as] = capacity_;
        pack_atom(i, &keep[(size_t)i * old_as + 1]);
    }
    capacity_ = cap;
    tracker_.capacity = cap;
    memory->destroy(row_);
    std::free(hist_);
    row_ = NULL;
    hist_ = NULL;
    memory->create(row_, std::max(nmax_, 1), row_size(), "wall/rigid:history");
    advise_huge(row_[0], (size_t)std::max(nmax_, 1) * row_size() * sizeof(double));
    hist_ = alloc_slots((size_t)capacity_ * std::max(nmax_, 1) * slot_size());
    for (int i = 0; i < nmax_; i++)
        unpack_sized(i, &keep[(size_t)i * old_as]);
    init_scratch();
    return true;
}

/* One atom's history as plain doubles: its row, then its slots in slot order. */
void FixWallRigid::pack_atom(int i, double *buf) const
{
    const int rs = row_size(), hs = slot_size();
    const ptrdiff_t stride = slot_stride();
    std::memcpy(buf, row_[i], sizeof(double) * rs);
    const double *h = slot0(i);
    for (int j = 0; j < capacity_; j++)
        std::memcpy(buf + rs + j * hs, h + j * stride, sizeof(double) * hs);
}

void FixWallRigid::unpack_atom(int i, const double *buf)
{
    const int rs = row_size(), hs = slot_size();
    const ptrdiff_t stride = slot_stride();
    std::memcpy(row_[i], buf, sizeof(double) * rs);
    double *h = slot0(i);
    for (int j = 0; j < capacity_; j++)
        std::memcpy(h + j * stride, buf + rs + j * hs, sizeof(double) * hs);
}

/* An atom's history packed with capacity buf[0] (at most capacity_) into atom i: the
 * directory and slots it has, the rest free. */
int FixWallRigid::unpack_sized(int i, const double *buf)
{
    const int cin = (int)buf[0];
    const int hs = slot_size(), rest = row_size() - capacity_;
    const ptrdiff_t stride = slot_stride();
    const double *row = buf + 1, *slots = row + cin + rest;
    clear_row(i);
    std::memcpy(row_[i], row, sizeof(double) * cin);                    /* directory */
    std::memcpy(row_[i] + capacity_, row + cin, sizeof(double) * rest); /* T, fields */
    double *h = slot0(i);
    for (int j = 0; j < cin; j++)
        std::memcpy(h + j * stride, slots + j * hs, sizeof(double) * hs);
    return 1 + cin + rest + cin * hs;
}

void FixWallRigid::copy_arrays(int i, int j, int delflag)
{
    (void)delflag;
    const int hs = slot_size();
    const ptrdiff_t stride = slot_stride();
    std::memcpy(row_[j], row_[i], sizeof(double) * row_size());
    for (int s = 0; s < capacity_; s++)
        std::memcpy(slot0(j) + s * stride, slot0(i) + s * stride, sizeof(double) * hs);
    for (int c = 0; array_atom && c < 6; c++)
        array_atom[j][c] = array_atom[i][c];
}

void FixWallRigid::set_arrays(int i)
{
    clear_row(i);
    for (int c = 0; array_atom && c < 6; c++)
        array_atom[i][c] = 0.0;
}

/* Exchange and restart records: the capacity, then the atom's history. An atom from a
 * rank whose capacity grew further grows this rank's first. */
int FixWallRigid::pack_exchange(int i, double *buf)
{
    buf[0] = capacity_;
    pack_atom(i, buf + 1);
    return 1 + atom_size();
}

int FixWallRigid::unpack_exchange(int nlocal, double *buf)
{
    const int cin = (int)buf[0];
    if (cin > capacity_ && !grow_capacity(cin))
        fail_one("an atom arrived with more contact slots than this rank can hold");
    const int n = unpack_sized(nlocal, buf);
    for (int c = 0; array_atom && c < 6; c++)
        array_atom[nlocal][c] = 0.0;
    return n;
}

int FixWallRigid::pack_restart(int i, double *buf)
{
    const int n = 1 + atom_size();
    buf[0] = n + 1;
    buf[1] = capacity_;
    pack_atom(i, buf + 2);
    return n + 1;
}

void FixWallRigid::unpack_restart(int nlocal, int nth)
{
    double **extra = atom->extra;
    int m = 0;
    for (int k = 0; k < nth; k++)
        m += static_cast<int>(extra[nlocal][m]);
    const int n = static_cast<int>(extra[nlocal][m]) - 1;
    const double *rec = &extra[nlocal][m + 1];
    const int cin = (int)rec[0];
    const int rest = row_size() - capacity_;
    const int want = 1 + rest + cin * (1 + slot_size());
    /* A record written under another slot layout of this law: with every field of the
     * contact's last call kept (files before the slots followed the law, or a law that
     * reads them all), or with the slip and rdisp1 that this law does not read (files
     * before RS_DROP_SLIP). The fields this law does not read are left out. */
    const unsigned layouts[2] = {0u, tracker_.drop & ~(unsigned)RS_DROP_SLIP};
    std::vector<double> compact;
    for (int v = 0; v < 2 && cin >= 1 && n != want && compact.empty(); v++) {
        rs_tracker from = tracker_;
        from.drop = layouts[v];
        const int fs = rs_track_slot_size(&from), hs = slot_size();
        if (fs == hs || n != 1 + rest + cin * (1 + fs))
            continue;
        compact.assign(rec, rec + 1 + cin + rest);
        std::vector<double> slot((size_t)hs);
        for (int j = 0; j < cin; j++) {
            rs_track_slot_convert(&tracker_, from.drop,
                                  rec + 1 + cin + rest + (size_t)j * fs, slot.data());
            compact.insert(compact.end(), slot.begin(), slot.end());
        }
    }
    if (!compact.empty()) {
        rec = compact.data();
    } else if (cin < 1 || n != want) {
        std::ostringstream o;
        o << "restart file has " << n << " history values per atom for " << cin
          << " contact slots; this fix needs " << want
          << " (keep the law, statev and predef unchanged)";
        fail_one(o.str());
    }
    if (cin > capacity_ && !grow_capacity(cin))
        fail_one("the restart file has more contact slots per atom than this fix can hold");
    if (restart_version_ == 0.0)
        fail_one("the restart file holds wall/rigid history per atom but no global record "
                 "with its layout version");
    unpack_sized(nlocal, rec);
    /* version 5: a directory entry was the feature f (empty -1, leaving -2 - f), one less
     * than RS_DIR_LIVE(f) (RS_DIR_EMPTY, RS_DIR_LEAVING(f)) */
    if (restart_version_ < 6.0)
        for (int j = 0; j < cin; j++)
            row_[nlocal][j] += 1.0;
}

int FixWallRigid::size_restart(int nlocal)
{
    (void)nlocal;
    return atom_size() + 2;
}

int FixWallRigid::maxsize_restart()
{
    return atom_size() + 2;
}

double FixWallRigid::memory_usage()
{
    return (double)nmax_ * (atom_size() + (peratom_ ? 6 : 0)) * sizeof(double);
}
