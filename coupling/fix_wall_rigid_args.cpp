/* fix wall/rigid: its arguments (docs/fix_wall_rigid.md, "Syntax") and the error
 * messages that name them. */
#include "fix_wall_rigid.h"
#include "liggghts_law.h"
#include "rigidsurf/law_build.h"
#include "rigidsurf/vec.h"

#include "domain.h"
#include "error.h"
#include "force.h"
#include "input.h"
#include "modify.h"
#include "update.h"
#include "variable.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <unistd.h>

using namespace LAMMPS_NS;

namespace
{

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
        fail(std::string("keyword '") + keyword + "' expects " + what + ", got '" + s +
             "' (not a finite number)");
    if (std::fabs(v) > RS_COORD_MAX)
        fail(std::string("keyword '") + keyword + "' expects " + what + ", got '" + s +
             "' (magnitude above 1e100)");
    return v;
}

/* A number > 0 (what says so): number's errors, or "expects WHAT, got S" for one <= 0. */
double FixWallRigid::positive(const char *keyword, const char *what, const char *s)
{
    const double v = number(keyword, what, s);
    if (!(v > 0.0))
        fail(std::string("keyword '") + keyword + "' expects " + what + ", got " + s);
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
        "surface",     "name",         "law",    "props",    "type",
        "statev",      "tracking",     "area",   "contacts", "move",
        "rotate",      "temperature",  "predef", "vtk",      "curvature",
        "pnewdt",      "surface_vel",  "wear",   "servo",    "conduction",
        "store_force", "contact_area", "spin",   "peratom"};
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
        /* a keyword of two values: true for `on`, false for `off`, else an error */
        auto either = [&](const char *on, const char *off) {
            const std::string want = std::string("'") + on + "' or '" + off + "'";
            need(1, want.c_str());
            const char *val = arg[iarg + 1];
            if (std::strcmp(val, on) != 0 && std::strcmp(val, off) != 0)
                fail(std::string("keyword '") + kw + "' expects " + want + ", got '" + val +
                     "'");
            iarg += 2;
            return std::strcmp(val, on) == 0;
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
            if (user_statev < 0 || user_statev > RS_MAX_STATEV) {
                std::ostringstream o;
                o << "keyword 'statev' expects a number of state variables in 0.."
                  << RS_MAX_STATEV << ", got " << user_statev;
                fail(o.str());
            }
            statev_given_ = true;
            iarg += 2;
        } else if (std::strcmp(kw, "tracking") == 0) {
            need(1, "a tracking thickness (length >= 0)");
            tracking_ =
                number("tracking", "a tracking thickness (length >= 0)", arg[iarg + 1]);
            if (tracking_ < 0.0)
                fail(std::string("keyword 'tracking' expects a length >= 0, got ") +
                     arg[iarg + 1]);
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
                    fail(std::string("keyword 'area' expects a constant area > 0, got ") +
                         arg[iarg + 1]);
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
        } else if (std::strcmp(kw, "servo") == 0) {
            if (moving_ || servo_.on)
                fail("keyword 'servo' moves the wall itself; it takes no 'move', 'rotate' "
                     "or 'spin' and is given once");
            iarg = parse_servo(narg, arg, iarg + 1);
        } else if (std::strcmp(kw, "move") == 0 || std::strcmp(kw, "rotate") == 0 ||
                   std::strcmp(kw, "spin") == 0) {
            if (servo_.on)
                fail("keyword 'servo' moves the wall itself; it takes no 'move', 'rotate' "
                     "or 'spin'");
            iarg = parse_motion(narg, arg, iarg);
        } else if (std::strcmp(kw, "wear") == 0) {
            wear_ = either("finnie", "off");
        } else if (std::strcmp(kw, "surface_vel") == 0) {
            need(3, "a surface velocity VX VY VZ");
            double u[3];
            for (int d = 0; d < 3; d++)
                u[d] = number("surface_vel", "a surface velocity component VX VY VZ",
                              arg[iarg + 1 + d]);
            rs_motion_set_surface_velocity(&motion_, u);
            belt_ = u[0] != 0.0 || u[1] != 0.0 || u[2] != 0.0;
            iarg += 4;
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
                    positive("capacity", "a wall heat capacity > 0", arg[iarg + 1]);
                iarg += 2;
            }
        } else if (std::strcmp(kw, "conduction") == 0) {
            need(1, "'liggghts' or 'off'");
            if (std::strcmp(arg[iarg + 1], "liggghts") == 0)
                conduction_ = true;
            else if (std::strcmp(arg[iarg + 1], "off") == 0)
                conduction_ = false;
            else
                fail(
                    std::string("keyword 'conduction' expects 'liggghts' or 'off', got '") +
                    arg[iarg + 1] + "'");
            iarg += 2;
        } else if (std::strcmp(kw, "contact_area") == 0) {
            need(1, "'overlap', 'projection' or 'constant A'");
            const char *m = arg[iarg + 1];
            if (std::strcmp(m, "overlap") == 0) {
                carea_mode_ = CAREA_OVERLAP;
            } else if (std::strcmp(m, "projection") == 0) {
                carea_mode_ = CAREA_PROJECTION;
            } else if (std::strcmp(m, "constant") == 0) {
                need(2, "'constant A' with an area A > 0");
                carea_const_ =
                    positive("contact_area constant", "an area > 0", arg[iarg + 2]);
                carea_mode_ = CAREA_CONSTANT;
                iarg++;
            } else {
                fail(
                    std::string("keyword 'contact_area' expects 'overlap', 'projection' or "
                                "'constant A', got '") +
                    m + "'");
            }
            carea_given_ = true;
            iarg += 2;
        } else if (std::strcmp(kw, "store_force") == 0) {
            need(1, "'yes', 'no' or 'into ID'");
            wallforce_id_.clear();
            if (std::strcmp(arg[iarg + 1], "yes") == 0) {
                store_force_ = true;
            } else if (std::strcmp(arg[iarg + 1], "no") == 0) {
                store_force_ = false;
            } else if (std::strcmp(arg[iarg + 1], "into") == 0) {
                need(2, "'into ID': the ID W of the per-atom vector force_W");
                store_force_ = true;
                wallforce_id_ = std::string("force_") + arg[iarg + 2];
                iarg++;
            } else {
                fail(std::string("keyword 'store_force' expects 'yes', 'no' or 'into ID', "
                                 "got '") +
                     arg[iarg + 1] + "'");
            }
            iarg += 2;
        } else if (std::strcmp(kw, "peratom") == 0) {
            peratom_ = either("yes", "no");
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
                fail(std::string("keyword 'vtk' expects an output interval N > 0, got ") +
                     arg[iarg + 2]);
            iarg += 3;
        } else if (std::strcmp(kw, "curvature") == 0) {
            curvature = either("yes", "no");
            curvature_given = true;
        } else if (std::strcmp(kw, "pnewdt") == 0) {
            pnewdt_stop_ = !either("warn", "stop");
        } else {
            fail(std::string("unknown keyword '") + kw +
                 "'; expected surface, name, law, props, type, statev, tracking, area, "
                 "contacts, move, rotate, spin, servo, surface_vel, temperature, "
                 "conduction, "
                 "contact_area, predef, vtk, curvature, wear, store_force, peratom or "
                 "pnewdt");
        }
    }

    if (!have_surface)
        fail("missing 'surface FILE' (or 'surface inline ...')");
    if (conduction_ && !temp_given_)
        fail("keyword 'conduction liggghts' needs the wall's 'temperature T'");
    if (carea_given_ && !conduction_)
        fail("keyword 'contact_area' sets the area of 'conduction liggghts', which is not "
             "given");
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
        fail(std::string("keyword 'surface': ") + err.msg);
    surf_ok_ = true;
    if (wear_ && !rs_surface_has_facets(&surf_))
        fail("keyword 'wear' needs a mesh surface (TYPE=MESH or 'surface inline mesh'): "
             "the wear is kept per facet");
    if (surf_.warning[0] && comm->me == 0)
        error->warning(FLERR,
                       (std::string("fix wall/rigid: surface: ") + surf_.warning).c_str());
    /* What asks nothing of the user (a plate's or a belt's open rim): one INFO line. */
    if (surf_.info[0] && comm->me == 0)
        for (FILE *fp : {screen, logfile})
            if (fp)
                std::fprintf(fp, "INFO: fix wall/rigid %s: surface: %s\n", id, surf_.info);

    /* State variables. */
    const int law_nsv = law_->nstatev;
    if (law_kind_ == LAW_LIGGGHTS) {
        /* LIGGGHTS's model: its history, material properties and force; the interface
         * keywords of stress laws do not apply. */
        if (statev_given_ && user_statev != law_nsv) {
            std::ostringstream o;
            o << "law liggghts " << lig_->description() << " keeps " << law_nsv
              << " history values per contact; 'statev " << user_statev
              << "' does not match";
            fail(o.str());
        }
        if (props_given_)
            fail("law liggghts reads its material properties from fix property/global "
                 "(youngsModulus, poissonsRatio, ...), as fix wall/gran does; 'props' "
                 "does not apply");
        if (area_mode_ != AREA_NODE)
            fail("law liggghts gives a force, not a stress; 'area' does not apply");
        if ((temp_given_ && !conduction_) || !predef_names_.empty())
            fail("law liggghts conducts no heat and reads no predefined fields; "
                 "'temperature' applies to the interface laws and to 'conduction "
                 "liggghts', 'predef' to the interface laws");
        if (curvature_given)
            fail("keyword 'curvature' applies to law hertz only");
        nstatev_ = law_nsv;
    } else if (law_kind_ == LAW_BUILTIN) {
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
    if (nstatev_ > RS_MAX_STATEV) {
        std::ostringstream o;
        o << "law '" << law_->name << "' with 'statev " << user_statev << "' needs "
          << nstatev_ << " state variables per contact, more than " << RS_MAX_STATEV;
        fail(o.str());
    }

    /* Properties. */
    if (law_kind_ == LAW_LIGGGHTS)
        return;
    if (curvature_given && !hertz_)
        fail("keyword 'curvature' applies to law hertz only");
    if (hertz_) {
        if (props_given_) {
            /* Explicit Hertz properties override the LIGGGHTS material properties. */
            rc = rs_law_check_props(law_, props_.data(), (int)props_.size(), &err);
            if (rc != RS_OK)
                fail(std::string("keyword 'props': ") + err.msg);
            if (curvature_given)
                fail("law hertz with 'props': give the curvature flag as the 7th property");
        } else {
            props_.assign(1, curvature ? 1.0 : 0.0); // remembered until init()
        }
    } else if (hooke_ && !props_given_) {
        props_.clear(); // the LIGGGHTS material properties, looked up in init()
    } else {
        rc = rs_law_check_props(law_, props_.data(), (int)props_.size(), &err);
        if (rc != RS_OK)
            fail(std::string("keyword 'props': ") + err.msg);
    }
}

/* surface inline KIND ... profile ITEMS end: the same keyword text a surface file holds,
 * built here and handed to rs_surface_parse. */
int FixWallRigid::parse_surface(int narg, char **arg, int iarg)
{
    if (iarg >= narg)
        fail("'surface inline' expects 'revolution', 'cylinder', 'segments' or 'mesh'");
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
    if (kind == "mesh") {
        /* surface inline mesh FILE [scale s] [place ax ay az bx by bz cx cy cz] [sides n]
         */
        if (iarg >= narg || is_keyword(arg[iarg]))
            fail("'surface inline mesh' expects a mesh FILE (.stl, .obj, .off or .ply)");
        std::string file = arg[iarg++];
        if (file.find_first_of(",\n") != std::string::npos)
            fail("'surface inline mesh': the file name '" + file +
                 "' holds a comma or a line break (expected a plain path)");
        std::string scale, place, msides;
        while (iarg < narg) {
            std::string k = arg[iarg];
            if (k == "scale") {
                iarg++;
                scale = num("scale s");
            } else if (k == "sides") {
                iarg++;
                msides = num("sides 1 or 2");
            } else if (k == "place") {
                iarg++;
                double p[3];
                place = point("place ax ay az bx by bz cx cy cz", p);
                place += ", " + point("place ax ay az bx by bz cx cy cz", p);
                place += ", " + point("place ax ay az bx by bz cx cy cz", p);
            } else {
                break;
            }
        }
        head << "*SURFACE, TYPE=MESH, NAME=" << id << ", FILE=" << file;
        if (!scale.empty())
            head << ", SCALE=" << scale;
        if (!msides.empty())
            head << ", SIDES=" << msides;
        head << "\n";
        if (!place.empty())
            head << place << "\n";
        inline_text_ = head.str();
        return iarg;
    }
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
                c = point("c x y z (off the local x axis, on the generator's side)", pc);
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
        fail("'surface inline' expects 'revolution', 'cylinder', 'segments' or 'mesh', got "
             "'" +
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
 * A Fortran LIB (FILE.f, .f90, ...) is built first (rs_law_build_cached). */
int FixWallRigid::parse_law(int narg, char **arg, int iarg)
{
    law_name_ = arg[iarg++];
    rs_error err;
    rs_error_clear(&err);
    auto lib_arg = [&](const char *what) -> const char * {
        if (iarg >= narg || is_keyword(arg[iarg]))
            fail("keyword 'law': law " + law_name_ + " expects " + what);
        return arg[iarg++];
    };
    auto normal_arg = [&](bool required) -> const rs_law * {
        if (iarg + 1 < narg && std::strcmp(arg[iarg], "normal") == 0) {
            const rs_law *n = rs_law_find(arg[iarg + 1]);
            if (!n)
                fail(std::string("keyword 'law': law ") + law_name_ + ": 'normal " +
                     arg[iarg + 1] +
                     "' is not a built-in law (hertz, hooke, bonded_interface, "
                     "linear_softening, coulomb)");
            iarg += 2;
            return n;
        }
        if (required)
            fail("keyword 'law': law " + law_name_ +
                 " expects 'normal LAW' (a built-in law giving the "
                 "contact pressure)");
        return NULL;
    };
    int rc = RS_OK;
    if (law_name_ == "liggghts") {
        /* LIGGGHTS's own words, up to the next keyword of wall/rigid */
        std::vector<std::string> words;
        while (iarg < narg && !is_keyword(arg[iarg]))
            words.push_back(arg[iarg++]);
        lig_ = new LiggghtsLaw(lmp, id, words);
        lig_desc_.name = "liggghts";
        lig_desc_.nprops = 0;
        lig_desc_.nstatev = lig_->nhistory();
        /* the model reads the overlap, the frame and its own history only */
        lig_desc_.skips = RS_LAW_SKIPS_STRESS | RS_LAW_SKIPS_ENERGY | RS_LAW_SKIPS_SLIP |
                          RS_LAW_SKIPS_DRDISP1;
        law_ = &lig_desc_;
        law_kind_ = LAW_LIGGGHTS;
        return iarg;
    }
    if (law_name_ == "user") {
        const char *lib = lib_arg("a shared library and a symbol: user LIB.so SYMBOL");
        const char *sym = lib_arg("a symbol after the library: user LIB.so SYMBOL");
        rc = rs_law_load_c(lib, sym, &loaded_, &err);
        law_kind_ = LAW_LOADED;
    } else if (law_name_ == "vuinter") {
        const char *lib = lib_arg(
            "a shared library or Fortran file holding vuinter: vuinter LIB.so|FILE.f");
        rc = rs_law_load_vuinter(lib, &loaded_, &err);
        law_kind_ = LAW_LOADED;
    } else if (law_name_ == "uinter") {
        const char *lib = lib_arg(
            "a shared library or Fortran file holding uinter: uinter LIB.so|FILE.f");
        const rs_law *normal = normal_arg(false);
        rc = rs_law_load_uinter(lib, normal, &loaded_, &err);
        law_kind_ = LAW_LOADED;
    } else if (law_name_ == "fric") {
        const char *lib = lib_arg(
            "a shared library or Fortran file holding fric: fric LIB.so|FILE.f normal "
            "LAW");
        const rs_law *normal = normal_arg(true);
        rc = rs_law_load_fric(lib, normal, &loaded_, &err);
        law_kind_ = LAW_LOADED;
    } else {
        law_ = rs_law_find(law_name_.c_str());
        if (!law_) {
            std::string known;
            for (int i = 0; i < rs_law_count(); i++)
                known += std::string(i ? ", " : "") + rs_law_at(i)->name;
            fail("keyword 'law': unknown law '" + law_name_ + "'; expected one of " +
                 known + ", user, vuinter, uinter or fric");
        }
        law_kind_ = LAW_BUILTIN;
        hertz_ = std::strcmp(law_->name, "hertz") == 0;
        hooke_ = std::strcmp(law_->name, "hooke") == 0;
        return iarg;
    }
    if (rc != RS_OK)
        fail(std::string("keyword 'law': ") + err.msg);
    loaded_ok_ = true;
    law_ = &loaded_;
    /* A routine built from source: the compiler's warnings, as one line on rank 0. */
    const rs_build_warnings *w = rs_law_warnings(&loaded_);
    if (w && w->count > 0 && comm->me == 0) {
        std::ostringstream o;
        o << "fix wall/rigid: law " << loaded_.name << ": the Fortran compiler gave "
          << w->count << (w->count == 1 ? " warning" : " warnings")
          << "; the first: " << w->first << " (all of them: " << w->log << ")";
        error->warning(FLERR, o.str().c_str());
    }
    return iarg;
}
