#!/usr/bin/python3
"""law lammps on a plane against LAMMPS's own plane walls: every dumped quantity to 1e-9.

The same deck runs in stock lmp with `fix wall/gran MODEL zplane 0 NULL` (and `yplane` for
two models) and in lmp-rigidsurf with `fix wall/rigid surface plane.inp law lammps MODEL`:
the model words of fix wall/gran unchanged, for every model style of LAMMPS 29Sep2021's
walls (hooke, hooke/history, hertz/history, granular with each normal model, the damping
models, the tangential models, rolling sds and twisting marshall and sds, limit_damping).
Three spheres that touch only the wall: one dropped sideways with spin (it bounces, slides
and rolls), one that slides in with a backspin, one dropped head-on. Positions,
velocities, spins, forces and torques are dumped every 50 steps with 17 digits and agree
to 1e-9 relative (scaled by R, 1 m/s, 1 N, 1 N m below those).

DMT is checked head-on only: its critical friction force in LAMMPS 29Sep2021
(FixWallGran::granular, F_pulloff = 4 pi coh Reff) reads the variable coh, which only the
JKR branch sets, so stock's sliding limit under DMT is an uninitialised value: with no
tangential motion the limit never acts, and the normal force, whose cohesion term reads
normal_coeffs[3], is LAMMPS's.
"""
import lmplib as M

R, RHO, DT, STEPS = 0.005, 2500.0, 1.0e-5, 10000
BOX = (-0.1, 0.1, -0.1, 0.1, -0.05, 0.2)
MODELS = [
    ("hooke", "hooke 2e5 NULL 50 NULL 0.5 1"),
    ("hooke_history", "hooke/history 2e5 NULL 50 NULL 0.5 1"),
    ("hertz_history", "hertz/history 2e8 NULL 5e3 NULL 0.5 1 limit_damping"),
    ("granular_mindlin_roll", "granular hertz/material 1e7 0.3 0.3 tangential mindlin NULL "
     "1.0 0.5 rolling sds 1e3 1e1 0.1 twisting marshall damping tsuji"),
    ("granular_hooke_nohistory", "granular hooke 2e5 0.3 tangential linear_nohistory 1.0 "
     "0.5 damping mass_velocity"),
    ("granular_hertz_force", "granular hertz 2e8 0.3 tangential mindlin_rescale/force 1e5 "
     "1.0 0.5 twisting sds 1e2 1e-1 0.1 damping velocity limit_damping"),
    ("granular_jkr", "granular jkr 1e7 0.1 0.3 50 tangential mindlin_rescale NULL 1.0 0.5 "
     "damping viscoelastic"),
    ("granular_dmt", "granular dmt 1e7 0.1 0.3 5 tangential linear_history 1e4 1 0.5"),
]
# the plane z = 0 (n = +z) and y = 0 (n = +y), as CYLINDER profiles (liglib.plane_z)
PLANE_Y = ("*SURFACE, TYPE=CYLINDER, NAME=floor\n0, 0, 0, 1, 0, 0\n0, 0, 1\n"
           "START, -1, 0\nLINE, 1, 0\n")


def spheres(axis, head_on_only):
    """The three spheres, 'up' along axis (2: z, 1: y)."""
    def at(t, h):
        p = [t, 0.0, 0.0]
        p[axis] = h
        return p

    def vel(t, n):
        v = [t, 0.0, 0.0]
        v[axis] = n
        return v
    spin = [0.0, 0.0, 0.0]
    spin[3 - axis] = 30.0  # about the horizontal axis normal to x
    d = ""
    if not head_on_only:
        d += M.sphere(1, at(-0.04, 0.012), R, RHO, vel(0.15, 0.0), spin)
        d += M.sphere(2, at(0.04, 0.8 * R), 0.8 * R, RHO, vel(-0.2, 0.0),
                      [-s for s in spin])
    d += M.sphere(3 if not head_on_only else 1, at(0.0, 0.008), 0.9 * R, RHO,
                  vel(0.0, -0.3))
    return d


def deck(tag, wall, axis, head_on_only):
    d = M.header(BOX, DT)
    d += spheres(axis, head_on_only)
    g = ["0", "0", "0"]
    g[axis] = "-1"
    d += "fix grav all gravity 9.81 vector %s\n" % " ".join(g)
    d += wall + "\n"
    d += "fix integr all nve/sphere\n"
    d += M.dump_lines("d", 50, tag + ".dump")
    d += "run %d\n" % STEPS
    return d


def body(s):
    s.write("plane_z.inp", M.L.plane_z(0.0))
    s.write("plane_y.inp", PLANE_Y)
    cases = [(n, m, 2) for n, m in MODELS]
    cases += [(n + "_yplane", m, 1) for n, m in MODELS if n in ("hertz_history",
                                                                "granular_mindlin_roll")]
    for name, model, axis in cases:
        head_on = name.startswith("granular_dmt")
        plane = "zplane" if axis == 2 else "yplane"
        stock = "fix w all wall/gran %s %s 0.0 NULL" % (model, plane)
        ours = "fix w all wall/rigid surface %s law lammps %s" % (
            "plane_z.inp" if axis == 2 else "plane_y.inp", model)
        s.run(name + "_stock", deck(name + "_stock", stock, axis, head_on),
              exe=s.args.lmp)
        s.run(name + "_rigid", deck(name + "_rigid", ours, axis, head_on))
        fa = M.read_dump(s.path(name + "_rigid.dump"))
        fb = M.read_dump(s.path(name + "_stock.dump"))
        up = "xyz"[axis]
        touched = any(a[up] < 1.001 * R for _, f in fb for a in f.values())
        s.ck.check(name + ": stock's wall touched the spheres", touched)
        M.L.check_trajectories(s, name, fa, fb, M.scales(R), 1e-9, ref="stock lmp's")


if __name__ == "__main__":
    M.L.main_guard(M.L.Session(__doc__, extra=[M.STOCK]), body)
