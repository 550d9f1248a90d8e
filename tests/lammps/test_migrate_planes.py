#!/usr/bin/python3
"""LAMMPS's `fix wall/gran` planes and zcylinder, with wiggle, shear and contacts, run by
stock lmp as written and by lmp-rigidsurf as rigidsurf-migrate rewrites them: every dumped
quantity to 1e-9 relative.

Each deck holds spheres that touch only the walls (pair_style none), gravity where the
spheres rest, and one fix wall/gran; rigidsurf-migrate must exit 0 on it and write fix
wall/rigid with law lammps and the same model words (checked on its output). The cases:

- zplane lo hi (two planes of one fix, both bounds), hertz/history with damping: a sphere
  dropped spinning onto the floor, one thrown up to the ceiling, one sliding in with
  backspin;
- xplane NULL hi and yplane lo NULL, granular (hertz/material, mindlin, rolling sds,
  twisting marshall, tsuji damping): spheres thrown spinning at the side walls, no
  gravity;
- zplane with shear x V (hooke/history): spheres resting on a floor whose material slides
  (LAMMPS gives every contact the wall velocity V along x; wall/rigid's surface_vel);
- zplane with wiggle y A P (granular mindlin): spheres resting on a floor shaken along
  itself (LAMMPS's wall velocity A w sin(w (step - s0) dt), the plane in place; the
  migrated plane moves along itself at that rate, which leaves it where it is);
- zplane lo hi with wiggle z, xplane lo with wiggle x: spheres resting on a floor (on a
  wall, gravity along -x) shaken along its normal, and one thrown to the ceiling (LAMMPS
  places the planes at lo + A (1 - cos w t) with the velocity A w sin w t; the migrated
  planes by `move variable` at the same place and velocity);
- zcylinder R with wiggle z (hertz/history with friction): spheres inside and outside the
  cylinder (LAMMPS's zcylinder acts on both sides) hitting it while it wiggles along its
  axis; and with shear z (granular);
- yplane lo hi with limit_damping (hooke), and contacts: the dumped f_w[2-4] (the contact
  force) against the migrated deck's f_force_w[1-3];
- exit 3: a zcylinder with shear x, which the tool keeps as LAMMPS's (LAMMPS's wall
  velocity there sums over the particles it touches), beside a floor it migrates: the
  deck runs in lmp-rigidsurf as in stock lmp.

The planes are exact in both, the models are LAMMPS's own code in both, and the wall's
velocity is LAMMPS's formula evaluated at the same step: the runs agree to rounding.
"""
import lmplib as M
import migratelib as G

R, RHO, DT, STEPS = 0.005, 2500.0, 1.0e-5, 10000
BOX = (-0.1, 0.1, -0.1, 0.1, -0.05, 0.2)
HERTZ = "hertz/history 2e8 NULL 5e3 NULL 0.5 1"
GRANULAR = ("granular hertz/material 1e7 0.3 0.3 tangential mindlin NULL 1.0 0.5 rolling "
            "sds 1e3 1e1 0.1 twisting marshall damping tsuji")
COLS = M.COLS


def deck(name, wall, spheres, gravity="0 0 -1", cols=COLS, steps=STEPS):
    d = M.header(BOX, DT)
    for k, (x, r, v, w) in enumerate(spheres):
        d += M.sphere(k + 1, x, r, RHO, v, w)
    if gravity:
        d += "fix grav all gravity 9.81 vector %s\n" % gravity
    d += wall + "\n"
    d += "fix integr all nve/sphere\n"
    d += M.dump_lines("d", 50, name + ".dump", cols)
    d += "run %d\n" % steps
    return d


FLOOR = [((-0.04, 0.0, 0.012), R, (0.15, 0.0, 0.0), (0.0, 30.0, 0.0)),
         ((0.04, 0.0, 0.8 * R), 0.8 * R, (-0.2, 0.0, 0.0), (0.0, -30.0, 0.0)),
         ((0.0, 0.02, 0.045), 0.9 * R, (0.0, 0.0, 0.9), (0.0, 0.0, 0.0))]
SIDES = [((0.03, 0.0, 0.05), R, (0.4, 0.05, 0.0), (0.0, 20.0, 10.0)),
         ((0.0, -0.02, 0.05), 0.8 * R, (0.03, -0.3, 0.0), (15.0, 0.0, -5.0))]
RESTING = [((-0.03, 0.0, R), R, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)),
           ((0.03, 0.01, 0.8 * R), 0.8 * R, (0.05, 0.0, 0.0), (0.0, 0.0, 0.0))]
# inside the zcylinder of radius 0.05 (one each side of the mantle's inner face) and
# outside it
DRUM = [((0.038, 0.0, 0.05), R, (0.3, 0.05, 0.2), (0.0, 0.0, 0.0)),
        ((0.0, -0.037, 0.06), 0.8 * R, (0.02, -0.25, -0.1), (5.0, 0.0, 0.0)),
        ((0.065, 0.0, 0.04), R, (-0.3, 0.0, 0.1), (0.0, 0.0, 0.0))]
CASES = [
    ("zplane_lo_hi", "fix w all wall/gran %s zplane 0.0 0.06" % HERTZ, FLOOR, "0 0 -1",
     lambda a: a["z"] < 1.001 * R or a["z"] > 0.06 - 1.001 * R),
    ("xplane_hi_granular", "fix w all wall/gran %s xplane NULL 0.05" % GRANULAR, SIDES[:1],
     None, lambda a: a["x"] > 0.05 - 1.001 * R),
    ("yplane_lo_granular", "fix w all wall/gran %s yplane -0.05 NULL" % GRANULAR, SIDES[1:],
     None, lambda a: a["y"] < -0.05 + 1.001 * R),
    ("zplane_shear", "fix w all wall/gran hooke/history 2e5 NULL 50 NULL 0.5 1 zplane 0 "
     "NULL shear x 0.3", RESTING, "0 0 -1", lambda a: a["vx"] > 0.06),
    ("zplane_wiggle", "fix w all wall/gran %s zplane 0 NULL wiggle y 0.002 0.02" % GRANULAR,
     RESTING, "0 0 -1", lambda a: abs(a["vy"]) > 1e-3),
    ("zplane_wiggle_normal", "fix w all wall/gran %s zplane 0.0 0.06 wiggle z 0.0005 0.02"
     % HERTZ, RESTING + FLOOR[2:], "0 0 -1", lambda a: a["z"] > R + 4e-4),
    ("xplane_wiggle_normal", "fix w all wall/gran hooke/history 2e5 NULL 50 NULL 0.5 1 "
     "xplane -0.05 NULL wiggle x 0.004 0.05", [((-0.05 + R, 0.0, 0.05), R, (0.0, 0.1, 0.0),
                                               (0.0, 0.0, 0.0))], "-1 0 0",
     lambda a: a["x"] > -0.05 + R + 1e-3),
    ("zcylinder_wiggle", "fix w all wall/gran hertz/history 2e8 NULL 5e3 NULL 0.5 1 "
     "zcylinder 0.05 wiggle z 0.003 0.01", DRUM, None, lambda a: at_drum(a)),
    ("zcylinder_shear", "fix w all wall/gran granular hertz 2e8 0.3 tangential "
     "linear_history 1e5 1.0 0.5 zcylinder 0.05 shear z 0.2", DRUM, None,
     lambda a: at_drum(a)),
    ("yplane_limit_damping_contacts", "fix w all wall/gran hooke 2e5 NULL 50 NULL 0.5 1 "
     "limit_damping yplane -0.05 0.05 contacts", SIDES, None,
     lambda a: abs(a["y"]) > 0.05 - 1.001 * R),
]


def at_drum(a):
    """Whether a sphere (R or 0.8 R) touches the zcylinder of radius 0.05."""
    return abs((a["x"] ** 2 + a["y"] ** 2) ** 0.5 - 0.05) < R


def kept(s):
    """Exit 3: a deck whose zcylinder with shear x stays LAMMPS's (its wall velocity sums
    over the particles it touches) runs in lmp-rigidsurf as in stock lmp, its migrated
    floor beside it."""
    name = "kept_zcylinder_shear_x"
    wall = ("fix w all wall/gran hooke/history 2e5 NULL 50 NULL 0.5 1 zcylinder 0.05 shear "
            "x 0.2\nfix f all wall/gran hooke/history 2e5 NULL 50 NULL 0.5 1 zplane 0.0 NULL")
    stock, rigid, err, text = G.pair(s, name, deck(name, wall, DRUM[:2]), want_rc=3)
    s.ck.check(name + ": the zcylinder kept as written, the floor migrated",
               "zcylinder 0.05 shear x 0.2\n" in text and "fix f all wall/rigid" in text and
               "LINE %d: fix w: the wall is kept as LAMMPS's" % (
                   text.splitlines().index(wall.splitlines()[0]) + 1) in err,
               why=text + err)
    s.ck.check(name + ": stock's walls reached the spheres",
               any(at_drum(a) or a["z"] < 1.001 * R for _, f in stock for a in f.values()))
    M.L.check_trajectories(s, name, rigid, stock, M.scales(R), 1e-9, ref="stock lmp's")


def body(s):
    kept(s)
    for name, wall, spheres, gravity, reached in CASES:
        contacts = wall.endswith("contacts")
        cols = COLS + (" f_w[2] f_w[3] f_w[4]" if contacts else "")
        stock, rigid, err, text = G.pair(s, name, deck(name, wall, spheres, gravity, cols))
        model = wall.split(" wall/gran ")[1].split(" zplane")[0].split(" xplane")[0] \
            .split(" yplane")[0].split(" zcylinder")[0]
        flat = " ".join(text.replace("&\n", " ").split())
        s.ck.check(name + ": the migrated deck has wall/rigid with law lammps and the "
                   "model words", "wall/rigid" in text and "wall/gran" not in text and
                   ("law lammps " + model in flat or
                    "law lammps reff region " + model in flat), why=text)
        s.ck.check(name + ": stock's wall reached the spheres",
                   any(reached(a) for _, f in stock for a in f.values()))
        M.L.check_trajectories(s, name, rigid, stock, M.scales(R), 1e-9, ref="stock lmp's")
        if contacts:
            worst = max(M.rel_diff(a["f_force_w[%d]" % k], b["f_w[%d]" % (k + 1)], 1.0)
                        for (_, fa), (_, fb) in zip(rigid, stock) for i, a in fa.items()
                        for b in (fb[i],) for k in (1, 2, 3))
            s.ck.check(name + ": f_w[2-4] of stock's contacts equal f_force_w[1-3] to 1e-9",
                       worst <= 1e-9, "worst rel %.3g" % worst)


if __name__ == "__main__":
    M.L.main_guard(G.session(__doc__), body)
