/* fix wall/rigid: a rigidsurf master surface as a LIGGGHTS wall.
 * Syntax, keywords and output: docs/fix_wall_rigid.md. Conventions: docs/conventions.md. */
#include "fix_wall_rigid.h"
#include "rigidsurf/vec.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_property_atom.h"
#include "fix_property_global.h"
#include "force.h"
#include "group.h"
#include "input.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"
#include "variable.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <unistd.h>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace
{

/* Global vector: 1-3 force on the wall, 4-6 moment on the wall about the surface
 * origin, 7 touching contacts, 8 ALLSE, 9 ALLFD, 10 ALLPD, 11 ALLVD, 12 ALLCD, 13 wall
 * temperature, 14 heat into the wall. */
const int kNout = 14;

/* Restart layout version (global record). */
const double kRestartVersion = 2.0; // 2: directory in the row, slots after it

int rates_callback(double t, double vel[3], double *omega, void *ctx)
{
    (void)t;
    static_cast<FixWallRigid *>(ctx)->motion_rates(vel, omega);
    return 0;
}

bool is_number(const char *s)
{
    if (!s || !*s)
        return false;
    char *end = NULL;
    errno = 0;
    std::strtod(s, &end);
    return end && *end == '\0' && errno == 0;
}

} // namespace

/* ---------------------------------------------------------------------------------- */

FixWallRigid::FixWallRigid(LAMMPS *lmp, int narg, char **arg)
    : Fix(lmp, narg, arg), surf_ok_(false), ndir_(3), moving_(false), ivar_omega_(-1),
      rot_by_period_(false), period_(0.0), phi_at_build_(0.0), spin_invariant_(false),
      law_kind_(LAW_BUILTIN), law_(NULL), loaded_ok_(false), props_given_(false),
      hertz_(false), nstatev_(0), statev_given_(false), wall_type_(1), capacity_(4),
      tracking_(0.0), tracking_given_(false), area_mode_(AREA_NODE), area_const_(1.0),
      temp_given_(false), temp_wall_(0.0), dtemp_wall_(0.0), capacity_wall_(0.0),
      heat_wall_(0.0), heat_step_(0.0), fix_temp_(NULL), fix_heatflux_(NULL),
      fix_heatcap_(NULL), vtk_every_(0), vtk_mesh_ok_(false), row_(NULL), hist_(NULL),
      nmax_(0), rebuild_(true), se_now_(0.0), ncontact_(0), out_step_(-1), out_valid_(false)
{
    std::memset(&surf_, 0, sizeof surf_);
    std::memset(&loaded_, 0, sizeof loaded_);
    std::memset(&contacts_, 0, sizeof contacts_);
    std::memset(&tout_, 0, sizeof tout_);
    std::memset(&cb_, 0, sizeof cb_);
    std::memset(&vtk_mesh_, 0, sizeof vtk_mesh_);
    std::memset(&tracker_, 0, sizeof tracker_);
    rs_law_block_init(&blk_);
    rs_motion_init(&motion_);
    for (int d = 0; d < 3; d++) {
        ivar_vel_[d] = -1;
        disp_at_build_[d] = 0.0;
        f_wall_[d] = m_wall_[d] = 0.0;
    }
    for (int d = 0; d < 4; d++)
        diss_[d] = 0.0;
    for (int d = 0; d < kNout; d++)
        out_[d] = 0.0;

    parse(narg, arg);

    ndir_ = rs_surface_ndir(&surf_);
    tracker_.capacity = capacity_;
    tracker_.nstatev = nstatev_;
    tracker_.ndir = ndir_;
    tracker_.tracking = tracking_;
    temp_mst_[0] = temp_wall_;
    dtemp_mst_[0] = 0.0;

    restart_global = 1;
    restart_peratom = 1;
    create_attribute = 1;
    time_depend = moving_ ? 1 : 0;

    vector_flag = 1;
    size_vector = kNout;
    global_freq = 1;
    extvector = -1;
    extlist = new int[kNout];
    for (int d = 0; d < kNout; d++)
        extlist[d] = 1;
    extlist[12] = 0; // wall temperature is intensive

    peratom_flag = 1;
    size_peratom_cols = 6;
    peratom_freq = 1;
    array_atom = NULL;

    if (vtk_every_ > 0)
        nevery = vtk_every_;

    grow_arrays(atom->nmax);
    atom->add_callback(0);
    atom->add_callback(1);
    for (int i = 0; i < atom->nlocal; i++)
        clear_row(i);
}

FixWallRigid::~FixWallRigid()
{
    atom->delete_callback(id, 0);
    atom->delete_callback(id, 1);
    memory->destroy(row_);
    memory->sfree(hist_);
    memory->destroy(array_atom);
    delete[] extlist;
    extlist = NULL;
    rs_contacts_free(&contacts_);
    rs_track_out_free(&tout_);
    rs_cblock_free(&cb_);
    rs_trimesh_free(&vtk_mesh_);
    if (loaded_ok_)
        rs_law_unload(&loaded_);
    if (surf_ok_)
        rs_surface_free(&surf_);
}

/* ---------------------------------------------------------------------------------- */
/* Input                                                                              */

void FixWallRigid::fail(const std::string &msg)
{
    std::string m = std::string("Fix wall/rigid ") + id + ": " + msg;
    error->all(FLERR, m.c_str());
    std::abort(); // not reached: error->all ends the run
}

/* Error::one ends with MPI_Abort, which drops whatever stdio still buffers: on a pipe or
 * a file the message and the last thermo lines would be lost. They are flushed here, and
 * the message written to the log, before Error::one runs. */
void FixWallRigid::fail_one(const std::string &msg)
{
    std::string m = std::string("Fix wall/rigid ") + id + ": " + msg;
    if (screen) {
        std::fflush(screen);
        if (!isatty(fileno(screen))) {
            std::fprintf(screen, "ERROR on proc %d: %s (%s:%d)\n", comm->me, m.c_str(),
                         __FILE__, __LINE__);
            std::fflush(screen);
        }
    }
    if (logfile) {
        std::fprintf(logfile, "ERROR on proc %d: %s (%s:%d)\n", comm->me, m.c_str(),
                     __FILE__, __LINE__);
        std::fflush(logfile);
    }
    error->one(FLERR, m.c_str());
    std::abort();
}

double FixWallRigid::number(const char *keyword, const char *what, const char *s)
{
    if (!is_number(s))
        fail(std::string("keyword '") + keyword + "' expects " + what + ", got '" +
             (s ? s : "(end of line)") + "'");
    double v = std::strtod(s, NULL);
    if (!std::isfinite(v))
        fail(std::string("keyword '") + keyword + "' expects a finite " + what);
    return v;
}

int FixWallRigid::integer(const char *keyword, const char *what, const char *s)
{
    char *end = NULL;
    long v = s ? std::strtol(s, &end, 10) : 0;
    if (!s || !*s || *end != '\0' || v < -2147483647L || v > 2147483647L)
        fail(std::string("keyword '") + keyword + "' expects " + what + ", got '" +
             (s ? s : "(end of line)") + "'");
    return (int)v;
}

bool FixWallRigid::is_keyword(const char *s) const
{
    static const char *const kw[] = {
        "surface",  "name", "law",    "props",       "type",   "statev", "tracking", "area",
        "contacts", "move", "rotate", "temperature", "predef", "vtk",    "curvature"};
    for (const char *k : kw)
        if (std::strcmp(s, k) == 0)
            return true;
    return false;
}

void FixWallRigid::parse(int narg, char **arg)
{
    if (narg < 4)
        fail("expected 'fix ID group wall/rigid surface FILE law LAW [keyword value ...]'");

    std::string surf_file, surf_name, surf_text;
    bool have_surface = false, have_law = false;
    bool curvature = false, curvature_given = false;
    int user_statev = 0;

    int iarg = 3;
    while (iarg < narg) {
        const char *kw = arg[iarg];
        auto need = [&](int n, const char *what) {
            if (iarg + n >= narg)
                fail(std::string("keyword '") + kw + "' expects " + what);
        };
        if (std::strcmp(kw, "surface") == 0) {
            need(1, "a surface file name or 'inline'");
            if (have_surface)
                fail("keyword 'surface' given twice");
            have_surface = true;
            if (std::strcmp(arg[iarg + 1], "inline") == 0) {
                iarg = parse_surface(narg, arg, iarg + 2);
                surf_text = "inline";
            } else {
                surf_file = arg[iarg + 1];
                iarg += 2;
            }
        } else if (std::strcmp(kw, "name") == 0) {
            need(1, "the name of a surface in the surface file");
            surf_name = arg[iarg + 1];
            iarg += 2;
        } else if (std::strcmp(kw, "law") == 0) {
            need(1, "a law name (hertz, hooke, bonded_interface, linear_softening, "
                    "coulomb, user, vuinter, uinter, fric)");
            if (have_law)
                fail("keyword 'law' given twice");
            have_law = true;
            iarg = parse_law(narg, arg, iarg + 1);
        } else if (std::strcmp(kw, "props") == 0) {
            iarg++;
            props_.clear();
            while (iarg < narg && !is_keyword(arg[iarg])) {
                props_.push_back(number("props", "numbers", arg[iarg]));
                iarg++;
            }
            if (props_.empty())
                fail("keyword 'props' expects at least one number");
            props_given_ = true;
        } else if (std::strcmp(kw, "type") == 0) {
            need(1, "a wall material type (integer >= 1)");
            wall_type_ =
                integer("type", "a wall material type (integer >= 1)", arg[iarg + 1]);
            if (wall_type_ < 1 || wall_type_ > atom->ntypes) {
                std::ostringstream o;
                o << "keyword 'type' expects a material type in 1.." << atom->ntypes
                  << " (create_box), got " << wall_type_;
                fail(o.str());
            }
            iarg += 2;
        } else if (std::strcmp(kw, "statev") == 0) {
            need(1, "a number of state variables (integer >= 0)");
            user_statev = integer("statev", "a number of state variables (integer >= 0)",
                                  arg[iarg + 1]);
            if (user_statev < 0)
                fail("keyword 'statev' expects an integer >= 0");
            statev_given_ = true;
            iarg += 2;
        } else if (std::strcmp(kw, "tracking") == 0) {
            need(1, "a tracking thickness (length >= 0)");
            tracking_ =
                number("tracking", "a tracking thickness (length >= 0)", arg[iarg + 1]);
            if (tracking_ < 0.0)
                fail("keyword 'tracking' expects a length >= 0");
            tracking_given_ = true;
            iarg += 2;
        } else if (std::strcmp(kw, "area") == 0) {
            need(1, "'node', 'projected' or a constant area > 0");
            if (std::strcmp(arg[iarg + 1], "node") == 0) {
                area_mode_ = AREA_NODE;
            } else if (std::strcmp(arg[iarg + 1], "projected") == 0) {
                area_mode_ = AREA_PROJECTED;
            } else {
                area_mode_ = AREA_CONSTANT;
                area_const_ = number("area", "'node', 'projected' or a constant area > 0",
                                     arg[iarg + 1]);
                if (!(area_const_ > 0.0))
                    fail("keyword 'area' expects a constant area > 0");
            }
            iarg += 2;
        } else if (std::strcmp(kw, "contacts") == 0) {
            need(1, "a per-particle contact capacity");
            capacity_ =
                integer("contacts", "a per-particle contact capacity", arg[iarg + 1]);
            if (capacity_ < 1 || capacity_ > RS_TRACK_MAX_CAPACITY) {
                std::ostringstream o;
                o << "keyword 'contacts' expects a capacity in 1.." << RS_TRACK_MAX_CAPACITY
                  << ", got " << capacity_;
                fail(o.str());
            }
            iarg += 2;
        } else if (std::strcmp(kw, "move") == 0 || std::strcmp(kw, "rotate") == 0) {
            iarg = parse_motion(narg, arg, iarg);
        } else if (std::strcmp(kw, "temperature") == 0) {
            need(1, "a wall temperature");
            temp_wall_ = number("temperature", "a wall temperature", arg[iarg + 1]);
            temp_given_ = true;
            iarg += 2;
            if (iarg < narg && std::strcmp(arg[iarg], "capacity") == 0) {
                if (iarg + 1 >= narg)
                    fail("keyword 'capacity' expects a wall heat capacity > 0 (energy per "
                         "kelvin)");
                capacity_wall_ =
                    number("capacity", "a wall heat capacity > 0", arg[iarg + 1]);
                if (!(capacity_wall_ > 0.0))
                    fail("keyword 'capacity' expects a wall heat capacity > 0");
                iarg += 2;
            }
        } else if (std::strcmp(kw, "predef") == 0) {
            iarg++;
            while (iarg < narg && !is_keyword(arg[iarg])) {
                predef_names_.push_back(arg[iarg]);
                iarg++;
            }
            if (predef_names_.empty())
                fail("keyword 'predef' expects the names of fix property/atom scalars");
        } else if (std::strcmp(kw, "vtk") == 0) {
            need(2, "a file name and an output interval N > 0");
            vtk_file_ = arg[iarg + 1];
            vtk_every_ = integer("vtk", "an output interval N > 0", arg[iarg + 2]);
            if (vtk_every_ < 1)
                fail("keyword 'vtk' expects an output interval N > 0");
            iarg += 3;
        } else if (std::strcmp(kw, "curvature") == 0) {
            need(1, "'yes' or 'no'");
            if (std::strcmp(arg[iarg + 1], "yes") == 0)
                curvature = true;
            else if (std::strcmp(arg[iarg + 1], "no") == 0)
                curvature = false;
            else
                fail(std::string("keyword 'curvature' expects 'yes' or 'no', got '") +
                     arg[iarg + 1] + "'");
            curvature_given = true;
            iarg += 2;
        } else {
            fail(std::string("unknown keyword '") + kw +
                 "'; expected surface, name, law, props, type, statev, tracking, area, "
                 "contacts, move, rotate, temperature, predef, vtk or curvature");
        }
    }

    if (!have_surface)
        fail("missing 'surface FILE' (or 'surface inline ...')");
    if (!have_law)
        fail("missing 'law LAW'");

    /* The surface: one parser for files and inline definitions. */
    rs_error err;
    rs_error_clear(&err);
    int rc;
    if (surf_text == "inline") {
        if (!surf_name.empty())
            fail("keyword 'name' selects a surface in a file; an inline surface has none");
        rc = rs_surface_parse(inline_text_.c_str(), "inline surface", NULL, &surf_, &err);
    } else {
        rc = rs_surface_read(surf_file.c_str(),
                             surf_name.empty() ? NULL : surf_name.c_str(), &surf_, &err);
    }
    if (rc != RS_OK)
        fail(err.msg);
    surf_ok_ = true;

    /* State variables. */
    const int law_nsv = law_->nstatev;
    if (law_kind_ == LAW_BUILTIN) {
        if (statev_given_ && user_statev != law_nsv) {
            std::ostringstream o;
            o << "law '" << law_->name << "' has " << law_nsv
              << " state variables; 'statev " << user_statev << "' does not match";
            fail(o.str());
        }
        nstatev_ = law_nsv;
    } else if (law_name_ == "uinter" || law_name_ == "fric") {
        nstatev_ = law_nsv + user_statev; // the adapter's own first, then the routine's
    } else {
        if (law_nsv > 0 && statev_given_ && user_statev != law_nsv) {
            std::ostringstream o;
            o << "law '" << law_->name << "' declares " << law_nsv
              << " state variables; 'statev " << user_statev << "' does not match";
            fail(o.str());
        }
        nstatev_ = law_nsv > 0 ? law_nsv : user_statev;
    }

    /* Properties. */
    if (curvature_given && !hertz_)
        fail("keyword 'curvature' applies to law hertz only");
    if (hertz_) {
        if (props_given_) {
            /* Explicit Hertz properties override the LIGGGHTS material properties. */
            rc = rs_law_check_props(law_, props_.data(), (int)props_.size(), &err);
            if (rc != RS_OK)
                fail(err.msg);
            if (curvature_given)
                fail("law hertz with 'props': give the curvature flag as the 7th property");
        } else {
            props_.assign(1, curvature ? 1.0 : 0.0); // remembered until init()
        }
    } else {
        rc = rs_law_check_props(law_, props_.data(), (int)props_.size(), &err);
        if (rc != RS_OK)
            fail(err.msg);
    }
}

/* surface inline KIND ... profile ITEMS end: the same keyword text a surface file holds,
 * built here and handed to rs_surface_parse. */
int FixWallRigid::parse_surface(int narg, char **arg, int iarg)
{
    if (iarg >= narg)
        fail("'surface inline' expects 'revolution', 'cylinder' or 'segments'");
    std::string kind = arg[iarg++];
    std::ostringstream head, data;
    std::string sides, fillet, extent;
    auto num = [&](const char *what) -> std::string {
        if (iarg >= narg)
            fail(std::string("'surface inline ") + kind + "' expects " + what);
        number("surface inline", what, arg[iarg]);
        return arg[iarg++];
    };
    auto fmt = [](double v) {
        char buf[40];
        std::snprintf(buf, sizeof buf, "%.17g", v);
        return std::string(buf);
    };
    auto point = [&](const char *what, double p[3]) {
        for (int d = 0; d < 3; d++)
            p[d] = std::strtod(num(what).c_str(), NULL);
        return fmt(p[0]) + ", " + fmt(p[1]) + ", " + fmt(p[2]);
    };
    std::string a, b, c;
    double pa[3], pb[3], pc[3];
    if (kind == "revolution") {
        while (iarg < narg && std::strcmp(arg[iarg], "profile") != 0) {
            std::string k = arg[iarg++];
            if (k == "origin")
                a = point("origin x y z", pa);
            else if (k == "axis")
                b = point("axis ax ay az", pb);
            else if (k == "fillet")
                fillet = num("a fillet radius");
            else if (k == "sides")
                sides = num("sides 1 or 2");
            else
                fail("'surface inline revolution' expects origin, axis, fillet, sides or "
                     "profile, got '" +
                     k + "'");
        }
        if (a.empty() || b.empty())
            fail("'surface inline revolution' needs 'origin x y z' and 'axis ax ay az'");
        /* The file gives a second point on the axis: origin + axis. */
        b = fmt(pa[0] + pb[0]) + ", " + fmt(pa[1] + pb[1]) + ", " + fmt(pa[2] + pb[2]);
    } else if (kind == "cylinder") {
        while (iarg < narg && std::strcmp(arg[iarg], "profile") != 0) {
            std::string k = arg[iarg++];
            if (k == "a")
                a = point("a x y z (origin)", pa);
            else if (k == "b")
                b = point("b x y z (on the local x axis)", pb);
            else if (k == "c")
                c = point("c x y z (on the generator)", pc);
            else if (k == "extent")
                extent = num("extent zmin zmax"), extent += ", " + num("extent zmin zmax");
            else if (k == "fillet")
                fillet = num("a fillet radius");
            else if (k == "sides")
                sides = num("sides 1 or 2");
            else
                fail("'surface inline cylinder' expects a, b, c, extent, fillet, sides or "
                     "profile, got '" +
                     k + "'");
        }
        if (a.empty() || b.empty() || c.empty())
            fail("'surface inline cylinder' needs points 'a x y z', 'b x y z', 'c x y z'");
    } else if (kind == "segments") {
        while (iarg < narg && std::strcmp(arg[iarg], "profile") != 0) {
            std::string k = arg[iarg++];
            if (k == "fillet")
                fillet = num("a fillet radius");
            else if (k == "sides")
                sides = num("sides 1 or 2");
            else
                fail("'surface inline segments' expects fillet, sides or profile, got '" +
                     k + "'");
        }
    } else {
        fail("'surface inline' expects 'revolution', 'cylinder' or 'segments', got '" +
             kind + "'");
    }
    if (iarg >= narg)
        fail("'surface inline " + kind + "' expects 'profile START x y ... end'");
    iarg++; // profile

    std::ostringstream prof;
    bool ended = false;
    while (iarg < narg) {
        std::string k = arg[iarg++];
        std::string K = k;
        for (char &ch : K)
            ch = (char)std::toupper((unsigned char)ch);
        if (K == "END") {
            ended = true;
            break;
        }
        int nv;
        if (K == "START" || K == "LINE")
            nv = 2;
        else if (K == "CIRCL" || K == "PARAB")
            nv = 4;
        else
            fail(
                "'surface inline' profile expects START, LINE, CIRCL, PARAB or end, got '" +
                k + "'");
        prof << K;
        for (int v = 0; v < nv; v++)
            prof << ", " << num("profile coordinates");
        prof << "\n";
    }
    if (!ended)
        fail("'surface inline' profile is not closed by 'end'");

    std::string KIND = kind;
    for (char &ch : KIND)
        ch = (char)std::toupper((unsigned char)ch);
    head << "*SURFACE, TYPE=" << KIND << ", NAME=" << id;
    if (!fillet.empty())
        head << ", FILLET RADIUS=" << fillet;
    if (!sides.empty())
        head << ", SIDES=" << sides;
    if (!extent.empty())
        head << ", EXTENT=" << extent;
    head << "\n";
    if (kind == "revolution")
        data << a << ", " << b << "\n";
    else if (kind == "cylinder")
        data << a << ", " << b << "\n" << c << "\n";
    std::string text = head.str() + data.str();
    inline_text_ = text + prof.str();
    return iarg;
}

/* law NAME | user LIB SYMBOL | vuinter LIB | uinter LIB [normal LAW] | fric LIB normal LAW
 */
int FixWallRigid::parse_law(int narg, char **arg, int iarg)
{
    law_name_ = arg[iarg++];
    rs_error err;
    rs_error_clear(&err);
    auto lib_arg = [&](const char *what) -> const char * {
        if (iarg >= narg || is_keyword(arg[iarg]))
            fail("law " + law_name_ + " expects " + what);
        return arg[iarg++];
    };
    auto normal_arg = [&](bool required) -> const rs_law * {
        if (iarg + 1 < narg && std::strcmp(arg[iarg], "normal") == 0) {
            const rs_law *n = rs_law_find(arg[iarg + 1]);
            if (!n)
                fail(std::string("law ") + law_name_ + ": 'normal " + arg[iarg + 1] +
                     "' is not a built-in law (hertz, hooke, bonded_interface, "
                     "linear_softening, coulomb)");
            iarg += 2;
            return n;
        }
        if (required)
            fail("law " + law_name_ +
                 " expects 'normal LAW' (a built-in law giving the "
                 "contact pressure)");
        return NULL;
    };
    int rc = RS_OK;
    if (law_name_ == "user") {
        const char *lib = lib_arg("a shared library and a symbol: user LIB.so SYMBOL");
        const char *sym = lib_arg("a symbol after the library: user LIB.so SYMBOL");
        rc = rs_law_load_c(lib, sym, &loaded_, &err);
        law_kind_ = LAW_LOADED;
    } else if (law_name_ == "vuinter") {
        const char *lib = lib_arg("a shared library holding vuinter: vuinter LIB.so");
        rc = rs_law_load_vuinter(lib, &loaded_, &err);
        law_kind_ = LAW_LOADED;
    } else if (law_name_ == "uinter") {
        const char *lib = lib_arg("a shared library holding uinter: uinter LIB.so");
        const rs_law *normal = normal_arg(false);
        rc = rs_law_load_uinter(lib, normal, &loaded_, &err);
        law_kind_ = LAW_LOADED;
    } else if (law_name_ == "fric") {
        const char *lib = lib_arg("a shared library holding fric: fric LIB.so normal LAW");
        const rs_law *normal = normal_arg(true);
        rc = rs_law_load_fric(lib, normal, &loaded_, &err);
        law_kind_ = LAW_LOADED;
    } else {
        law_ = rs_law_find(law_name_.c_str());
        if (!law_) {
            std::string known;
            for (int i = 0; i < rs_law_count(); i++)
                known += std::string(i ? ", " : "") + rs_law_at(i)->name;
            fail("unknown law '" + law_name_ + "'; expected one of " + known +
                 ", user, vuinter, uinter or fric");
        }
        law_kind_ = LAW_BUILTIN;
        hertz_ = std::strcmp(law_->name, "hertz") == 0;
        return iarg;
    }
    if (rc != RS_OK)
        fail(err.msg);
    loaded_ok_ = true;
    law_ = &loaded_;
    return iarg;
}

/* move linear VX VY VZ | rotate origin X Y Z axis AX AY AZ (omega W | period P).
 * A value may be v_NAME, an equal-style variable evaluated every step. */
int FixWallRigid::parse_motion(int narg, char **arg, int iarg)
{
    auto value = [&](const char *kw, const char *what, std::string &var) -> double {
        if (iarg >= narg)
            fail(std::string("keyword '") + kw + "' expects " + what);
        const char *s = arg[iarg++];
        if (std::strncmp(s, "v_", 2) == 0 && s[2]) {
            var = s + 2;
            return 0.0;
        }
        var.clear();
        return number(kw, what, s);
    };
    auto constant = [&](const char *kw, const char *what) -> double {
        if (iarg >= narg)
            fail(std::string("keyword '") + kw + "' expects " + what);
        return number(kw, what, arg[iarg++]);
    };
    if (std::strcmp(arg[iarg], "move") == 0) {
        iarg++;
        if (iarg >= narg || std::strcmp(arg[iarg], "linear") != 0)
            fail("keyword 'move' expects 'linear VX VY VZ'");
        iarg++;
        double vel[3];
        for (int d = 0; d < 3; d++)
            vel[d] = value("move linear", "a velocity component (number or v_name)",
                           var_vel_[d]);
        rs_motion_set_translation(&motion_, vel);
    } else {
        iarg++;
        double origin[3], axis[3], omega = 0.0;
        if (iarg >= narg || std::strcmp(arg[iarg], "origin") != 0)
            fail("keyword 'rotate' expects 'origin X Y Z axis AX AY AZ omega W' (or period "
                 "P)");
        iarg++;
        for (int d = 0; d < 3; d++)
            origin[d] = constant("rotate origin", "a coordinate");
        if (iarg >= narg || std::strcmp(arg[iarg], "axis") != 0)
            fail("keyword 'rotate' expects 'axis AX AY AZ' after the origin");
        iarg++;
        for (int d = 0; d < 3; d++)
            axis[d] = constant("rotate axis", "an axis component");
        if (iarg + 1 >= narg)
            fail("keyword 'rotate' expects 'omega W' or 'period P' after the axis");
        if (std::strcmp(arg[iarg], "omega") == 0) {
            iarg++;
            omega = value("rotate omega", "an angular speed in rad/time (number or v_name)",
                          var_omega_);
            rot_by_period_ = false;
        } else if (std::strcmp(arg[iarg], "period") == 0) {
            iarg++;
            period_ = value("rotate period", "a period (number or v_name)", var_omega_);
            if (var_omega_.empty()) {
                if (period_ == 0.0)
                    fail("keyword 'rotate period' expects a non-zero period");
                omega = 2.0 * RS_PI / period_;
            }
            rot_by_period_ = true;
        } else {
            fail(std::string("keyword 'rotate' expects 'omega W' or 'period P', got '") +
                 arg[iarg] + "'");
        }
        rs_error err;
        rs_error_clear(&err);
        if (rs_motion_set_rotation(&motion_, origin, axis, omega, &err) != RS_OK)
            fail(err.msg);
    }
    moving_ = true;
    bool vars = !var_omega_.empty();
    for (int d = 0; d < 3; d++)
        vars = vars || !var_vel_[d].empty();
    if (vars) {
        motion_.rates = rates_callback;
        motion_.ctx = this;
    }
    return iarg;
}

void FixWallRigid::motion_rates(double vel[3], double *omega)
{
    for (int d = 0; d < 3; d++)
        if (ivar_vel_[d] >= 0)
            vel[d] = input->variable->compute_equal(ivar_vel_[d]);
    if (ivar_omega_ >= 0) {
        double v = input->variable->compute_equal(ivar_omega_);
        if (rot_by_period_) {
            if (v == 0.0)
                fail("variable v_" + var_omega_ + " (rotate period) is zero");
            v = 2.0 * RS_PI / v;
        }
        *omega = v;
    }
}

/* ---------------------------------------------------------------------------------- */
/* Run setup                                                                          */

int FixWallRigid::setmask()
{
    int mask = 0;
    mask |= PRE_NEIGHBOR;
    mask |= POST_FORCE;
    if (moving_)
        mask |= INITIAL_INTEGRATE;
    if (vtk_every_ > 0)
        mask |= END_OF_STEP;
    return mask;
}

int FixWallRigid::min_type()
{
    return wall_type_;
}

int FixWallRigid::max_type()
{
    return wall_type_;
}

void FixWallRigid::init()
{
    if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
        fail("needs per-atom radius, mass, omega and torque (atom_style granular or "
             "sphere)");
    if (std::strstr(update->integrate_style, "respa"))
        fail("run_style respa is not supported; use verlet");
    if (!tracking_given_)
        tracking_ = neighbor->skin;
    tracker_.tracking = tracking_;

    /* A surface of revolution spun about its own axis keeps its shape in space: the
     * rotation then never moves it toward a particle. */
    spin_invariant_ = false;
    if (moving_ && surf_.kind == RS_SURF_REVOLUTION) {
        double ax[3], r[3], rx[3];
        rs_cross3(motion_.axis, surf_.ez, ax);
        for (int d = 0; d < 3; d++)
            r[d] = motion_.center0[d] - surf_.a[d];
        rs_cross3(r, surf_.ez, rx);
        const double scale = std::max(1.0, std::sqrt(domain->xprd * domain->xprd +
                                                     domain->yprd * domain->yprd +
                                                     domain->zprd * domain->zprd));
        spin_invariant_ =
            std::sqrt(ax[0] * ax[0] + ax[1] * ax[1] + ax[2] * ax[2]) < 1e-12 &&
            std::sqrt(rx[0] * rx[0] + rx[1] * rx[1] + rx[2] * rx[2]) < 1e-12 * scale;
    }
    if (hertz_ && !props_given_)
        init_hertz_props();
    init_variables();
    init_heat();
    init_predef();
    if (vtk_every_ > 0 && !vtk_mesh_ok_)
        init_vtk_mesh();
    init_scratch();
    rebuild_ = true;
}

/* law hertz without props: the LIGGGHTS material properties of the particle type and
 * the wall type, looked up as fix wall/gran looks them up (global_properties.cpp). */
void FixWallRigid::init_hertz_props()
{
    const double curv = props_.empty() ? 0.0 : props_[0];
    const int max_type = force->registry.max_type();
    const char *cs = "fix wall/rigid (law hertz)";
    FixPropertyGlobal *Y = static_cast<FixPropertyGlobal *>(modify->find_fix_property(
        "youngsModulus", "property/global", "peratomtype", max_type, 0, cs));
    FixPropertyGlobal *nu = static_cast<FixPropertyGlobal *>(modify->find_fix_property(
        "poissonsRatio", "property/global", "peratomtype", max_type, 0, cs));
    FixPropertyGlobal *e = static_cast<FixPropertyGlobal *>(
        modify->find_fix_property("coefficientRestitution", "property/global",
                                  "peratomtypepair", max_type, max_type, cs));
    FixPropertyGlobal *mu = static_cast<FixPropertyGlobal *>(
        modify->find_fix_property("coefficientFriction", "property/global",
                                  "peratomtypepair", max_type, max_type, cs));
    const int w = wall_type_ - 1;
    type_props_.assign(atom->ntypes + 1, std::vector<double>());
    for (int t = 1; t <= max_type && t <= atom->ntypes; t++) {
        const int p = t - 1;
        std::vector<double> v = {Y->compute_vector(p),
                                 nu->compute_vector(p),
                                 Y->compute_vector(w),
                                 nu->compute_vector(w),
                                 e->compute_array(p, w),
                                 mu->compute_array(p, w),
                                 curv};
        rs_error err;
        rs_error_clear(&err);
        if (rs_law_check_props(law_, v.data(), (int)v.size(), &err) != RS_OK) {
            std::ostringstream o;
            o << "material properties of particle type " << t << " against wall type "
              << wall_type_ << ": " << err.msg;
            fail(o.str());
        }
        type_props_[t] = v;
    }
    props_.assign(1, curv);
}

void FixWallRigid::init_variables()
{
    auto find = [&](const std::string &name) {
        int iv = input->variable->find(const_cast<char *>(name.c_str()));
        if (iv < 0)
            fail("variable v_" + name + " (motion) does not exist");
        if (!input->variable->equalstyle(iv))
            fail("variable v_" + name + " (motion) must be equal-style");
        return iv;
    };
    for (int d = 0; d < 3; d++)
        ivar_vel_[d] = var_vel_[d].empty() ? -1 : find(var_vel_[d]);
    ivar_omega_ = var_omega_.empty() ? -1 : find(var_omega_);
}

void FixWallRigid::init_heat()
{
    fix_temp_ = static_cast<FixPropertyAtom *>(
        modify->find_fix_property("Temp", "property/atom", "scalar", 0, 0, style, false));
    fix_heatflux_ = static_cast<FixPropertyAtom *>(modify->find_fix_property(
        "heatFlux", "property/atom", "scalar", 0, 0, style, false));
    fix_heatcap_ = NULL;
    if (fix_temp_) {
        const int max_type = force->registry.max_type();
        fix_heatcap_ = static_cast<FixPropertyGlobal *>(
            modify->find_fix_property("thermalCapacity", "property/global", "peratomtype",
                                      max_type, 0, style, false));
    }
}

void FixWallRigid::init_predef()
{
    predef_fix_.clear();
    for (const std::string &name : predef_names_) {
        FixPropertyAtom *f = static_cast<FixPropertyAtom *>(modify->find_fix_property(
            name.c_str(), "property/atom", "scalar", 0, 0, style, false));
        if (!f)
            fail("predef " + name +
                 ": no fix property/atom holding a per-atom scalar named '" + name + "'");
        predef_fix_.push_back(f);
    }
}

void FixWallRigid::init_vtk_mesh()
{
    const double span =
        std::sqrt(domain->xprd * domain->xprd + domain->yprd * domain->yprd +
                  domain->zprd * domain->zprd);
    rs_error err;
    rs_error_clear(&err);
    if (rs_surface_triangulate(&surf_, span, 72, &vtk_mesh_, &err) != RS_OK)
        fail(std::string("vtk: ") + err.msg);
    vtk_mesh_ok_ = true;
}

/* ---------------------------------------------------------------------------------- */
/* The step                                                                           */

/* Forces without history: LIGGGHTS walls compute setup forces with the shear history
 * frozen. Here the history rows of each block are saved, the tracker is run with a zero
 * increment and no master rotation, the law with b->setup = 1, and the rows restored. */
void FixWallRigid::setup(int vflag)
{
    (void)vflag;
    compute(true);
    if (vtk_every_ > 0 && update->ntimestep % vtk_every_ == 0)
        write_vtk();
}

void FixWallRigid::initial_integrate(int vflag)
{
    (void)vflag;
    rs_error err;
    rs_error_clear(&err);
    if (rs_motion_advance(&motion_, update->dt, &err) != RS_OK)
        fail(std::string("motion: ") + err.msg);
}

void FixWallRigid::pre_neighbor()
{
    rebuild_ = true;
}

void FixWallRigid::post_force(int vflag)
{
    (void)vflag;
    compute(false);
}

void FixWallRigid::end_of_step()
{
    write_vtk();
}

void FixWallRigid::clear_row(int i)
{
    double *r = row_[i];
    double *h = slot0(i);
    const ptrdiff_t stride = slot_stride();
    rs_track_clear(&tracker_, r, h, stride);
    for (int j = 0; j < capacity_; j++)
        h[j * stride + hist_size()] = 0.0; /* sed */
    r[tprev_offset()] = NAN;
    for (size_t p = 0; p < predef_names_.size(); p++)
        r[pred_offset() + (int)p] = NAN;
}

/* The wall may have moved since the candidates were chosen: every point of the box moved
 * by at most |dD| + |dphi| * (largest distance of a box corner from the rotation centre).
 * Beyond half the skin the list is refreshed, as LIGGGHTS reneighbours when a particle
 * moved half the skin. */
bool FixWallRigid::wall_moved_beyond_skin() const
{
    if (!moving_)
        return false;
    double dd = 0.0;
    for (int d = 0; d < 3; d++)
        dd += (motion_.disp[d] - disp_at_build_[d]) * (motion_.disp[d] - disp_at_build_[d]);
    double bound = std::sqrt(dd);
    const double dphi = std::fabs(motion_.phi - phi_at_build_);
    if (dphi > 0.0 && !spin_invariant_) {
        double c[3], rmax2 = 0.0;
        rs_motion_center(&motion_, c);
        for (int k = 0; k < 8; k++) {
            const double p[3] = {(k & 1) ? domain->boxhi[0] : domain->boxlo[0],
                                 (k & 2) ? domain->boxhi[1] : domain->boxlo[1],
                                 (k & 4) ? domain->boxhi[2] : domain->boxlo[2]};
            double r2 = 0.0;
            for (int d = 0; d < 3; d++)
                r2 += (p[d] - c[d]) * (p[d] - c[d]);
            rmax2 = std::max(rmax2, r2);
        }
        bound += dphi * std::sqrt(rmax2);
    }
    return bound > 0.5 * neighbor->skin;
}

/* Scratch of one block, sized once for RS_BLOCK particles and RS_BLOCK * capacity
 * contacts (the tracker never emits more: a particle with more contacts than slots is an
 * error), so the step itself allocates and fills nothing it does not need. */
void FixWallRigid::init_scratch()
{
    const size_t np = RS_BLOCK, nc = (size_t)RS_BLOCK * capacity_, nd = ndir_;
    const size_t npred = std::max((int)predef_names_.size(), 1);
    for (std::vector<double> *a :
         {&bx_, &by_, &bz_, &bvx_, &bvy_, &bvz_, &bwx_, &bwy_, &bwz_, &brad_})
        a->resize(np);
    bid_.resize(np), bdir_.resize(np), bhist_.resize(np), bidx_.resize(np);
    take_.resize(np);
    deepest_.resize(np);
    for (std::vector<double> *a : {&bmass_, &bheat_, &btemp_, &bdtemp_})
        a->resize(np);
    btype_.resize(np);
    bpred_.resize(np * npred), bdpred_.resize(np * npred);
    leaving_.resize(nc), c_sedp_.resize(nc);
    nleave_ = 0;
    ident_ = false;
    cb_.area_mode = area_mode_ == AREA_CONSTANT    ? RS_AREA_CONSTANT
                    : area_mode_ == AREA_PROJECTED ? RS_AREA_PROJECTED
                                                   : RS_AREA_NODE;
    cb_.area_const = area_const_;
    cb_.ndir = (int)nd;
    cb_.nstatev = nstatev_;
    cb_.npred = (int)predef_names_.size();
    rs_error err;
    if (rs_cblock_reserve(&cb_, (int)nc, &err) != RS_OK)
        fail(err.msg);

    /* The law block's fields that stay for the run. */
    rs_law_block_init(&blk_);
    blk_.kStep = 1;
    blk_.nSurfDir = ndir_ - 1;
    blk_.nDir = ndir_;
    blk_.nStateVar = nstatev_;
    blk_.nPred = (int)predef_names_.size();
    rs_law_block_set_name(blk_.surfInt, id);
    rs_law_block_set_name(blk_.surfSlv, group->names[igroup]);
    rs_law_block_set_name(blk_.surfMst, surf_.name[0] ? surf_.name : id);
    blk_.tempMst = temp_mst_;
    blk_.dtempMst = dtemp_mst_;
    blk_.wall_type = wall_type_;
}

/* Candidates: group atoms whose gap to the surface is within tracking + skin, and every
 * atom that still holds a contact (it must see its contact leave). */
void FixWallRigid::build_candidates()
{
    cand_.clear();
    const int nlocal = atom->nlocal;
    const int *mask = atom->mask;
    double **x = atom->x;
    const double *radius = atom->radius;
    rs_error err;
    rs_error_clear(&err);

    int n = 0;
    auto flush = [&]() {
        if (n == 0)
            return;
        double rmax = 0.0;
        for (int k = 0; k < n; k++) {
            const int i = bidx_[k];
            bx_[k] = x[i][0];
            by_[k] = x[i][1];
            bz_[k] = x[i][2];
            brad_[k] = radius[i];
            rmax = std::max(rmax, radius[i]);
            char held = 0;
            for (int j = 0; j < capacity_; j++)
                held |= row_[i][j] != RS_DIR_EMPTY;
            take_[k] = held;
        }
        rs_query q;
        q.n = n;
        q.slave.x = bx_.data();
        q.slave.y = by_.data();
        q.slave.z = bz_.data();
        q.slave.radius = brad_.data();
        q.pose = &motion_.pose;
        q.gap_max = tracking_ + neighbor->skin;
        q.dist_min = -rmax;
        contacts_.n = 0;
        if (rs_surface_query(&surf_, &q, &contacts_, &err) != RS_OK)
            fail_one(std::string("surface query: ") + err.msg);
        for (int c = 0; c < contacts_.n; c++)
            take_[contacts_.point[c]] = 1;
        for (int k = 0; k < n; k++)
            if (take_[k])
                cand_.push_back(bidx_[k]);
        n = 0;
    };
    for (int i = 0; i < nlocal; i++) {
        if (!(mask[i] & groupbit))
            continue;
        bidx_[n++] = i;
        if (n == RS_BLOCK)
            flush();
    }
    flush();

    if (hertz_ && !props_given_) {
        const int *type = atom->type;
        std::stable_sort(cand_.begin(), cand_.end(),
                         [type](int a, int b) { return type[a] < type[b]; });
    }
    for (int d = 0; d < 3; d++)
        disp_at_build_[d] = motion_.disp[d];
    phi_at_build_ = motion_.phi;
    rebuild_ = false;
}

void FixWallRigid::compute(bool setup_call)
{
    for (int d = 0; d < 3; d++)
        f_wall_[d] = m_wall_[d] = 0.0;
    se_now_ = 0.0;
    ncontact_ = 0;
    out_valid_ = false;
    heat_step_ = 0.0;

    /* Per-atom output: every candidate's row is written by its block each step, so only
     * the rows that may stop being candidates are zeroed here: all of them after a
     * reneighbouring (local indices change), the old candidates' before a refresh the
     * wall's motion asks for. Between the two, indices and candidates are fixed. */
    bool refresh = rebuild_ || setup_call;
    if (refresh) {
        const int nlocal = atom->nlocal;
        for (int i = 0; i < nlocal; i++)
            for (int c = 0; c < 6; c++)
                array_atom[i][c] = 0.0;
    } else if (wall_moved_beyond_skin()) {
        for (int i : cand_)
            for (int c = 0; c < 6; c++)
                array_atom[i][c] = 0.0;
        refresh = true;
    }
    if (refresh)
        build_candidates();

    /* Blocks of at most RS_BLOCK particles; with per-type properties a block holds one
     * particle type (the candidates are sorted by type). */
    const bool per_type = hertz_ && !props_given_;
    const int *type = atom->type;
    const int nc = (int)cand_.size();
    for (int b0 = 0; b0 < nc;) {
        int b1 = std::min(nc, b0 + RS_BLOCK);
        if (per_type)
            for (int k = b0 + 1; k < b1; k++)
                if (type[cand_[k]] != type[cand_[b0]]) {
                    b1 = k;
                    break;
                }
        process_block(&cand_[b0], b1 - b0, setup_call);
        b0 = b1;
    }

    if (!setup_call) {
        /* Wall heat: a lumped capacity integrates the total flux into it. */
        double q = heat_step_;
        if (capacity_wall_ > 0.0) {
            double qall = 0.0;
            MPI_Allreduce(&q, &qall, 1, MPI_DOUBLE, MPI_SUM, world);
            dtemp_wall_ = qall * update->dt / capacity_wall_;
            temp_wall_ += dtemp_wall_;
        }
        heat_wall_ += q * update->dt;
        temp_mst_[0] = temp_wall_;
        dtemp_mst_[0] = dtemp_wall_;
        update_previous_fields();
    }
}

void FixWallRigid::process_block(const int *idx, int n, bool setup_call)
{
    double **x = atom->x, **v = atom->v, **omega = atom->omega;
    const double *radius = atom->radius, *rmass = atom->rmass;
    const int *tag = atom->tag, *type = atom->type;
    const int nd = ndir_, ns = nstatev_, as = atom_size();
    const double dt = update->dt;
    rs_error err;
    rs_error_clear(&err);

    /* Gather; the extremes of R and m tell whether the block is monodisperse. */
    double *__restrict qx = bx_.data(), *__restrict qy = by_.data(),
                       *__restrict qz = bz_.data();
    double *__restrict qvx = bvx_.data(), *__restrict qvy = bvy_.data(),
                       *__restrict qvz = bvz_.data();
    double *__restrict qwx = bwx_.data(), *__restrict qwy = bwy_.data(),
                       *__restrict qwz = bwz_.data();
    double *__restrict qr = brad_.data();
    int *__restrict qid = bid_.data();
    double **__restrict qd = bdir_.data();
    double **__restrict qh = bhist_.data();
    double *__restrict qm = bmass_.data();
    int *__restrict qt = btype_.data();
    double rmax = radius[idx[0]];
    for (int k = 0; k < n; k++) {
        const int i = idx[k];
        const double *xi = x[i], *vi = v[i], *wi = omega[i];
        const double R = radius[i], m = rmass[i];
        qx[k] = xi[0], qy[k] = xi[1], qz[k] = xi[2];
        qvx[k] = vi[0], qvy[k] = vi[1], qvz[k] = vi[2];
        qwx[k] = wi[0], qwy[k] = wi[1], qwz[k] = wi[2];
        qr[k] = R;
        qm[k] = m;
        qt[k] = type[i];
        qid[k] = tag[i];
        qd[k] = row_[i];
        qh[k] = slot0(i);
        rmax = std::max(rmax, R);
    }
    if (setup_call) {
        saved_rows_.resize((size_t)n * as);
        for (int k = 0; k < n; k++)
            pack_atom(idx[k], &saved_rows_[(size_t)k * as]);
    }

    rs_query q;
    q.n = n;
    q.slave.x = bx_.data(), q.slave.y = by_.data(), q.slave.z = bz_.data();
    q.slave.radius = brad_.data();
    q.pose = &motion_.pose;
    q.gap_max = tracking_;
    q.dist_min = -rmax;
    contacts_.n = 0;
    if (rs_surface_query(&surf_, &q, &contacts_, &err) != RS_OK)
        fail_one(std::string("surface query: ") + err.msg);

    rs_particles p;
    p.n = n;
    p.x = bx_.data(), p.y = by_.data(), p.z = bz_.data();
    p.vx = bvx_.data(), p.vy = bvy_.data(), p.vz = bvz_.data();
    p.wx = bwx_.data(), p.wy = bwy_.data(), p.wz = bwz_.data();
    p.radius = brad_.data();
    p.id = bid_.data();
    p.dir = bdir_.data();
    p.hist = bhist_.data();
    p.slot_stride = slot_stride();

    /* A setup call has no increment: no slip, no master rotation. */
    rs_motion still;
    const rs_motion *mp = moving_ ? &motion_ : NULL;
    if (setup_call && moving_) {
        still = motion_;
        for (int a = 0; a < 9; a++)
            still.dQ[a] = (a % 4 == 0) ? 1.0 : 0.0;
        mp = &still;
    }
    if (rs_track_update(&tracker_, &surf_, mp, setup_call ? 0.0 : dt, &p, &contacts_,
                        &tout_, &err) != RS_OK)
        fail_one(err.msg);

    const int ne = tout_.n;
    if (ne > cb_.cap) // not reached: at most capacity contacts per particle
        fail_one("internal: block has more contacts than its scratch");
    if (ne == 0) {
        for (int k = 0; k < n; k++)
            for (int c = 0; c < 6; c++)
                array_atom[idx[k]][c] = 0.0;
        if (setup_call)
            for (int k = 0; k < n; k++)
                unpack_atom(idx[k], &saved_rows_[(size_t)k * as]);
        return;
    }
    /* Stress of the previous increment in this increment's basis, and the law state. */
    rs_track_load(&tracker_, &tout_, cb_.stress, ns ? cb_.statev : NULL);
    law_inputs(idx, n, ne, setup_call);

    /* The law, in slices of at most RS_BLOCK contacts. */
    const double *Temp = fix_temp_ ? fix_temp_->vector_atom : NULL;
    const double *props = props_.data();
    int nprops = (int)props_.size();
    if (hertz_ && !props_given_) {
        const int t = type[idx[0]];
        if (t >= (int)type_props_.size() || type_props_[t].empty()) {
            std::ostringstream o;
            o << "law hertz: no material properties for particle type " << t
              << " (youngsModulus, poissonsRatio, coefficientRestitution, "
                 "coefficientFriction must cover it)";
            fail_one(o.str());
        }
        props = type_props_[t].data();
        nprops = (int)type_props_[t].size();
    }
    const double time_end = update->atime + (update->ntimestep - update->atimestep) * dt;
    rs_law_block b = blk_;
    b.kInc = (int)update->ntimestep;
    b.nProps = nprops;
    b.nTemp = (Temp || temp_given_) ? 1 : 0;
    b.timStep = b.timGlb = setup_call ? time_end : time_end - dt;
    b.dTimCur = dt;
    b.props = nprops ? props : NULL;
    b.setup = setup_call ? 1 : 0;
    if (rs_cblock_call(&cb_, law_, &b, &tout_, &err) != RS_OK)
        fail_one(err.msg);

    /* The scatter also stores each live contact's sed in its slot (leaving: 0). A unit
     * area (the default) drops the products with A, which are exact. */
    const bool unit =
        area_mode_ == AREA_NODE || (area_mode_ == AREA_CONSTANT && area_const_ == 1.0);
    if (nd == 3) {
        if (unit)
            nleave_ ? scatter<3, true, true>(idx, n, ne, setup_call)
                    : scatter<3, false, true>(idx, n, ne, setup_call);
        else
            nleave_ ? scatter<3, true, false>(idx, n, ne, setup_call)
                    : scatter<3, false, false>(idx, n, ne, setup_call);
    } else {
        if (unit)
            nleave_ ? scatter<2, true, true>(idx, n, ne, setup_call)
                    : scatter<2, false, true>(idx, n, ne, setup_call);
        else
            nleave_ ? scatter<2, true, false>(idx, n, ne, setup_call)
                    : scatter<2, false, false>(idx, n, ne, setup_call);
    }

    if (setup_call) {
        for (int k = 0; k < n; k++)
            unpack_atom(idx[k], &saved_rows_[(size_t)k * as]);
        return;
    }
    rs_track_commit(&tracker_, &tout_, cb_.stress, ns ? cb_.statev : NULL);
}

/* The law's per-contact inputs (rs_cblock_inputs) from the block's particles, with their
 * heat capacities, temperatures and predefined fields; then each contact's sed from its
 * slot, and the leaving flags. */
void FixWallRigid::law_inputs(const int *idx, int n, int ne, bool setup_call)
{
    const double *cp = fix_heatcap_ ? fix_heatcap_->get_values() : NULL;
    double *const *__restrict bd = bdir_.data();
    rs_block_particles p;
    std::memset(&p, 0, sizeof p);
    p.n = n;
    p.radius = brad_.data();
    p.mass = bmass_.data();
    p.id = bid_.data();
    p.type = btype_.data();
    if (cp) {
        for (int k = 0; k < n; k++)
            bheat_[k] = bmass_[k] * cp[btype_[k] - 1];
        p.heatcap = bheat_.data();
    }
    const double *Temp = fix_temp_ ? fix_temp_->vector_atom : NULL;
    if (Temp) {
        const int tp0 = tprev_offset();
        for (int k = 0; k < n; k++) {
            const int i = idx[k];
            const double Tp = bd[k][tp0];
            btemp_[k] = Temp[i];
            bdtemp_[k] = (setup_call || std::isnan(Tp)) ? 0.0 : Temp[i] - Tp;
        }
        p.temp = btemp_.data();
        p.dtemp = bdtemp_.data();
    }
    const int npred = (int)predef_names_.size();
    if (npred) {
        const int pd0 = pred_offset();
        for (int k = 0; k < n; k++) {
            const int i = idx[k];
            for (int a = 0; a < npred; a++) {
                const double val = predef_fix_[a]->vector_atom[i];
                const double prev = bd[k][pd0 + a];
                bpred_[(size_t)k * npred + a] = val;
                bdpred_[(size_t)k * npred + a] =
                    (setup_call || std::isnan(prev)) ? 0.0 : val - prev;
            }
        }
        p.pred = bpred_.data();
        p.dpred = bdpred_.data();
    }
    rs_cblock_inputs(&cb_, &tout_, &p, update->dt);

    const int sed0 = hist_size(); /* the sed follows the tracker's slot */
    const int *__restrict pt = tout_.point;
    double *const *__restrict dir = tout_.dir;
    double *const *__restrict slot = tout_.slot;
    double **__restrict sedp = c_sedp_.data();
    double *__restrict sed = cb_.sed;
    char *__restrict leaving = leaving_.data();
    int nleave = 0;
    bool ident = true;
    for (int e = 0; e < ne; e++) {
        double *sp = slot[e] + sed0;
        sedp[e] = sp;
        sed[e] = *sp;
        const char lv = RS_DIR_IS_LEAVING(*dir[e]);
        leaving[e] = lv;
        nleave += lv;
        ident &= pt[e] == e;
    }
    nleave_ = nleave;
    ident_ = ident && ne == n;
}

/* Scatter: F = A (s1 n - s2 t1 - s3 t2) on the particle at x_cp, -F on the wall; the
 * wall's sums, energies, each contact's sed into its slot and the per-atom output of the
 * block's particles. ND = 2: the plane is z = const, t2 = -ez and the contact point keeps
 * the particle's z. LEAVE: some contacts are leaving (they apply nothing). UNITA: every
 * area is 1. */
template <int ND, bool LEAVE, bool UNITA>
void FixWallRigid::scatter(const int *idx, int n, int ne, bool setup_call)
{
    double **f = atom->f, **torque = atom->torque;
    double origin[3];
    rs_pose_to_global(&motion_.pose, surf_.a, origin);
    const double o0 = origin[0], o1 = origin[1], o2 = origin[2];
    const int *__restrict pt = tout_.point;
    const char *__restrict leaving = leaving_.data();
    const double *__restrict px = bx_.data(), *__restrict py = by_.data(),
                             *__restrict pz = bz_.data();
    const double *__restrict alocal = tout_.alocaldir, *__restrict coord = tout_.coordslv,
                             *__restrict rdisp = tout_.rdisp;
    const double *__restrict stress = cb_.stress, *__restrict area = cb_.area;
    const bool track_deepest = !ident_;
    int *__restrict deepest = deepest_.data();
    if (track_deepest)
        for (int k = 0; k < n; k++)
            deepest[k] = -1;

    double fw0 = f_wall_[0], fw1 = f_wall_[1], fw2 = f_wall_[2];
    double mw0 = m_wall_[0], mw1 = m_wall_[1], mw2 = m_wall_[2];
    int ncontact = ncontact_;
    for (int e = 0; e < ne; e++) {
        if (LEAVE && leaving[e])
            continue;
        const int k = pt[e];
        const double A = UNITA ? 1.0 : area[e];
        const double *s = stress + (size_t)e * ND;
        const double *L = alocal + (size_t)e * ND * ND; // columns n, t1[, t2]
        const double *xc = coord + (size_t)e * ND;
        double F0, F1, F2, xc0, xc1, xc2;
        if (ND == 3) {
            F0 = A * (s[0] * L[0] - s[1] * L[3] - s[2] * L[6]);
            F1 = A * (s[0] * L[1] - s[1] * L[4] - s[2] * L[7]);
            F2 = A * (s[0] * L[2] - s[1] * L[5] - s[2] * L[8]);
            xc0 = xc[0], xc1 = xc[1], xc2 = xc[2];
        } else {
            /* n = (L0, L1, 0), t1 = (L2, L3, 0), t2 = (0, 0, -1) */
            F0 = A * (s[0] * L[0] - s[1] * L[2] - 0.0 * 0.0);
            F1 = A * (s[0] * L[1] - s[1] * L[3] - 0.0 * 0.0);
            F2 = A * (s[0] * 0.0 - s[1] * 0.0 - 0.0 * -1.0);
            xc0 = xc[0], xc1 = xc[1], xc2 = pz[k];
        }
        const double r0 = xc0 - px[k], r1 = xc1 - py[k], r2 = xc2 - pz[k];
        const double rw0 = xc0 - o0, rw1 = xc1 - o1, rw2 = xc2 - o2;
        const double Fw0 = -F0, Fw1 = -F1, Fw2 = -F2;
        double *fi = f[idx[k]], *ti = torque[idx[k]];
        fi[0] += F0, fi[1] += F1, fi[2] += F2;
        ti[0] += r1 * F2 - r2 * F1;
        ti[1] += r2 * F0 - r0 * F2;
        ti[2] += r0 * F1 - r1 * F0;
        fw0 += Fw0, fw1 += Fw1, fw2 += Fw2;
        mw0 += rw1 * Fw2 - rw2 * Fw1;
        mw1 += rw2 * Fw0 - rw0 * Fw2;
        mw2 += rw0 * Fw1 - rw1 * Fw0;
        const double rd1 = rdisp[(size_t)e * ND];
        ncontact += rd1 > 0.0;
        if (track_deepest) {
            const int d = deepest[k];
            if (d < 0 || rd1 > rdisp[(size_t)d * ND])
                deepest[k] = e;
        }
    }
    f_wall_[0] = fw0, f_wall_[1] = fw1, f_wall_[2] = fw2;
    m_wall_[0] = mw0, m_wall_[1] = mw1, m_wall_[2] = mw2;
    ncontact_ = ncontact;

    /* Energies, heat, and sed into the slots (not in a setup call: its history is
     * restored). */
    const double *__restrict sed = cb_.sed;
    double se = se_now_;
    if (setup_call) {
        for (int e = 0; e < ne; e++)
            if (!(LEAVE && leaving[e]))
                se += sed[e] * area[e];
    } else {
        const double *__restrict sfd = cb_.sfd, *__restrict spd = cb_.spd,
                                 *__restrict svd = cb_.svd, *__restrict scd = cb_.scd,
                                 *__restrict fmst = cb_.flux_mst;
        double *const *__restrict sedp = c_sedp_.data();
        double d0 = diss_[0], d1 = diss_[1], d2 = diss_[2], d3 = diss_[3];
        double heat = heat_step_;
        for (int e = 0; e < ne; e++) {
            if (LEAVE && leaving[e]) {
                *sedp[e] = 0.0;
                continue;
            }
            const double A = UNITA ? 1.0 : area[e];
            se += sed[e] * A;
            d0 += sfd[e] * A;
            d1 += spd[e] * A;
            d2 += svd[e] * A;
            d3 += scd[e] * A;
            heat += fmst[e] * A;
            *sedp[e] = sed[e];
        }
        diss_[0] = d0, diss_[1] = d1, diss_[2] = d2, diss_[3] = d3;
        heat_step_ = heat;
        if (fix_heatflux_) {
            double *heatflux = fix_heatflux_->vector_atom;
            const double *fslv = cb_.flux_slv;
            for (int e = 0; e < ne; e++)
                if (!(LEAVE && leaving[e]))
                    heatflux[idx[pt[e]]] += fslv[e] * area[e];
        }
    }
    se_now_ = se;

    /* Per-atom output: the deepest live contact of each particle with this wall, zeros
     * for a particle without one. */
    for (int k = 0; k < n; k++) {
        const int e = track_deepest ? deepest[k] : (LEAVE && leaving[k]) ? -1 : k;
        double *o = array_atom[idx[k]];
        if (e < 0) {
            o[0] = o[1] = o[2] = o[3] = o[4] = o[5] = 0.0;
            continue;
        }
        const double *s = stress + (size_t)e * ND;
        const double *rd = rdisp + (size_t)e * ND;
        o[0] = rd[0];
        o[1] = rd[1];
        o[2] = ND == 3 ? rd[2] : 0.0;
        o[3] = s[0];
        o[4] = s[1];
        o[5] = ND == 3 ? s[2] : 0.0;
    }
}

void FixWallRigid::update_previous_fields()
{
    const int nlocal = atom->nlocal;
    const int *mask = atom->mask;
    const double *Temp = fix_temp_ ? fix_temp_->vector_atom : NULL;
    const int npred = (int)predef_fix_.size();
    if (!Temp && npred == 0)
        return;
    for (int i = 0; i < nlocal; i++) {
        if (!(mask[i] & groupbit))
            continue;
        if (Temp)
            row_[i][tprev_offset()] = Temp[i];
        for (int a = 0; a < npred; a++)
            row_[i][pred_offset() + a] = predef_fix_[a]->vector_atom[i];
    }
}

/* Legacy VTK polydata of the surface in its current pose; '*' in the name becomes the
 * step. Written by rank 0 (every rank holds the same surface and pose). */
void FixWallRigid::write_vtk()
{
    if (comm->me != 0 || !vtk_mesh_ok_)
        return;
    std::string name = vtk_file_;
    const size_t star = name.find('*');
    if (star != std::string::npos) {
        std::ostringstream o;
        o << update->ntimestep;
        name.replace(star, 1, o.str());
    }
    FILE *fp = std::fopen(name.c_str(), "w");
    if (!fp)
        fail_one("vtk: cannot open '" + name + "' for writing");
    std::fprintf(fp,
                 "# vtk DataFile Version 2.0\nfix wall/rigid %s step " BIGINT_FORMAT
                 "\nASCII\nDATASET POLYDATA\nPOINTS %d double\n",
                 id, update->ntimestep, vtk_mesh_.nvert);
    for (int v = 0; v < vtk_mesh_.nvert; v++) {
        double X[3];
        rs_pose_to_global(&motion_.pose, &vtk_mesh_.xyz[3 * v], X);
        std::fprintf(fp, "%.10g %.10g %.10g\n", X[0], X[1], X[2]);
    }
    std::fprintf(fp, "POLYGONS %d %d\n", vtk_mesh_.ntri, 4 * vtk_mesh_.ntri);
    for (int t = 0; t < vtk_mesh_.ntri; t++)
        std::fprintf(fp, "3 %d %d %d\n", vtk_mesh_.tri[3 * t], vtk_mesh_.tri[3 * t + 1],
                     vtk_mesh_.tri[3 * t + 2]);
    std::fclose(fp);
}

/* ---------------------------------------------------------------------------------- */
/* Output                                                                             */

double FixWallRigid::compute_vector(int n)
{
    if (!out_valid_ || out_step_ != update->ntimestep) {
        double loc[13], all[13];
        for (int d = 0; d < 3; d++) {
            loc[d] = f_wall_[d];
            loc[3 + d] = m_wall_[d];
        }
        loc[6] = ncontact_;
        loc[7] = se_now_;
        for (int d = 0; d < 4; d++)
            loc[8 + d] = diss_[d];
        loc[12] = heat_wall_;
        MPI_Allreduce(loc, all, 13, MPI_DOUBLE, MPI_SUM, world);
        for (int d = 0; d < 12; d++)
            out_[d] = all[d];
        out_[12] = temp_wall_;
        out_[13] = all[12];
        out_valid_ = true;
        out_step_ = update->ntimestep;
    }
    return (n >= 0 && n < kNout) ? out_[n] : 0.0;
}

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
    list[RST_CAPACITY] = capacity_;
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
    if (comm->me == 0) {
        int size = RST_COUNT * sizeof(double);
        std::fwrite(&size, sizeof(int), 1, fp);
        std::fwrite(list, sizeof(double), RST_COUNT, fp);
    }
}

void FixWallRigid::restart(char *buf)
{
    const double *list = reinterpret_cast<const double *>(buf);
    if (list[RST_VERSION] != kRestartVersion)
        fail("the restart file holds wall/rigid data of another layout version");
    if ((int)list[RST_CAPACITY] != capacity_ || (int)list[RST_NSTATEV] != nstatev_ ||
        (int)list[RST_NPRED] != (int)predef_names_.size()) {
        std::ostringstream o;
        o << "restart file has contacts " << (int)list[RST_CAPACITY] << ", "
          << (int)list[RST_NSTATEV] << " state variables and " << (int)list[RST_NPRED]
          << " predef fields; this fix has " << capacity_ << ", " << nstatev_ << " and "
          << predef_names_.size() << " (keep contacts, law, statev and predef unchanged)";
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
}

void FixWallRigid::grow_arrays(int nmax)
{
    if (nmax <= nmax_)
        return;
    memory->grow(row_, nmax, row_size(), "wall/rigid:history");
    memory->grow(array_atom, nmax, 6, "wall/rigid:array_atom");
    /* The slots move: slot j of the old nmax_ atoms to the start of block j. */
    const size_t hs = slot_size(), oldblk = (size_t)nmax_ * hs, blk = (size_t)nmax * hs;
    double *h = (double *)memory->smalloc((bigint)(capacity_ * blk * sizeof(double)),
                                          "wall/rigid:slots");
    for (int j = 0; j < capacity_; j++)
        if (oldblk)
            std::memcpy(h + j * blk, hist_ + j * oldblk, sizeof(double) * oldblk);
    memory->sfree(hist_);
    hist_ = h;
    const int old = nmax_;
    nmax_ = nmax;
    for (int i = old; i < nmax; i++) {
        clear_row(i);
        for (int c = 0; c < 6; c++)
            array_atom[i][c] = 0.0;
    }
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

void FixWallRigid::copy_arrays(int i, int j, int delflag)
{
    (void)delflag;
    const int hs = slot_size();
    const ptrdiff_t stride = slot_stride();
    std::memcpy(row_[j], row_[i], sizeof(double) * row_size());
    for (int s = 0; s < capacity_; s++)
        std::memcpy(slot0(j) + s * stride, slot0(i) + s * stride, sizeof(double) * hs);
    for (int c = 0; c < 6; c++)
        array_atom[j][c] = array_atom[i][c];
}

void FixWallRigid::set_arrays(int i)
{
    clear_row(i);
    for (int c = 0; c < 6; c++)
        array_atom[i][c] = 0.0;
}

int FixWallRigid::pack_exchange(int i, double *buf)
{
    pack_atom(i, buf);
    return atom_size();
}

int FixWallRigid::unpack_exchange(int nlocal, double *buf)
{
    unpack_atom(nlocal, buf);
    for (int c = 0; c < 6; c++)
        array_atom[nlocal][c] = 0.0;
    return atom_size();
}

int FixWallRigid::pack_restart(int i, double *buf)
{
    const int n = atom_size();
    buf[0] = n + 1;
    pack_atom(i, buf + 1);
    return n + 1;
}

void FixWallRigid::unpack_restart(int nlocal, int nth)
{
    double **extra = atom->extra;
    int m = 0;
    for (int k = 0; k < nth; k++)
        m += static_cast<int>(extra[nlocal][m]);
    const int n = static_cast<int>(extra[nlocal][m]) - 1;
    if (n != atom_size()) {
        std::ostringstream o;
        o << "restart file has " << n << " history values per atom, this fix needs "
          << atom_size() << " (keep contacts, law, statev and predef unchanged)";
        fail_one(o.str());
    }
    unpack_atom(nlocal, &extra[nlocal][m + 1]);
}

int FixWallRigid::size_restart(int nlocal)
{
    (void)nlocal;
    return atom_size() + 1;
}

int FixWallRigid::maxsize_restart()
{
    return atom_size() + 1;
}

double FixWallRigid::memory_usage()
{
    return (double)nmax_ * (atom_size() + 6) * sizeof(double);
}
