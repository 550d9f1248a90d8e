#!/usr/bin/python3
"""Contact history of fix wall/rigid survives write_restart / read_restart.

Run 2N steps in one process, or N steps + write_restart and, in a new process,
read_restart + N steps: every sphere's position, velocity and spin are identical (the
restart file holds doubles in binary, and setup recomputes forces without updating the
history, so nothing may change by even one bit).

Case: a drum turning at 6 rad/s about z, gravity -y, three spheres that do not touch
each other. Sphere 1 cannot spin (fix nve): the mantle drags it up to the
friction-limited angle where it sticks and slips, so at the restart point its friction
force lives only in the tangential history. Spheres 2 and 3 spin (fix nve/sphere).
The drum's rotation angle must also carry over the restart.

Second case, for the history slots beyond the first: one sphere pressed into the
concave corner between the turning mantle and the bottom cap of a closed drum holds two
contacts (mantle and cap, so two history slots) at the restart point; the restarted run
is again identical to the continuous one.

Fourth case, the restart layout version: the first case's file made into one of layout
version 5 (whose directory entries were the feature f, empty -1, where version 6 writes
f + 1, empty 0) is read and converted, so the restarted run is again identical; a file
of an unknown version (4) is refused with a message naming the versions read.

Third case, for slots that grew during the run and a turning mesh: a sphere settling
into the apex of a 12-facet STL cone (MESH) that turns about its axis holds 12 contacts
at the restart point, so its fix grew from 4 slots; the restarted fix starts with 4
again and takes 12 from the file.

Fifth case, the slot's layout: a file written with hertz as a loaded C law (its slots
keep the last call's stress and energies: 17 doubles) is read by law hertz (8) and the
run continues identically. Sixth, law liggghts with rolling friction epsd2: the model's
own history (shear and rolling torque) comes through the restart, identically.
Seventh, a drum that turns and spins about a crossed axis at a rate that changes in
time: the spin's state comes through the restart, identically.
"""
import math
import os
import shutil
import struct

import liglib as L

R, RHO, DT, RC, N = 0.004, 2500.0, 2.0e-5, 0.05, 3000
WALL = ("fix w all wall/rigid surface drum.inp law hertz type 2 peratom yes rotate origin 0 0 0 "
        "axis 0 0 1 omega 6")


def setup_lines(wall):
    return ("fix grav all gravity 9.81 vector 0 -1 0\n" + wall + "\n"
            "fix i1 g1 nve\nfix i2 g2 nve/sphere\n")


def deck_atoms():
    d = L.header((-0.06, 0.06, -0.06, 0.06, -0.05, 0.05), DT, mu=0.4)
    for k, (ang, z) in enumerate(((-90.0, 0.0), (-100.0, 0.02), (-60.0, -0.02))):
        r0 = RC - R + 1e-5
        c, sn = math.cos(math.radians(ang)), math.sin(math.radians(ang))
        d += L.sphere(k + 1, (r0 * c, r0 * sn, z), R, RHO)
    d += "group g1 id 1\ngroup g2 id 2 3\n"
    return d


def restarted_deck(restart, setup):
    """Reads restart, defines the materials again (read_restart brings the rest) and
    appends setup."""
    d = "atom_modify map array\ncommunicate single vel yes\n"
    d += "read_restart %s\n" % restart
    head = L.header((0, 1, 0, 1, 0, 1), DT, mu=0.4)
    keep = [l for l in head.splitlines()
            if l.startswith(("newton", "fix m", "pair_", "timestep", "neighbor", "neigh_modify"))]
    return d + "\n".join(keep) + "\n" + setup


def check_identical(s, tag):
    """The last frames of TAG_full.dump and TAG_restarted.dump agree bit for bit."""
    a = L.read_dump(s.path(tag + "_full.dump"))[-1]
    b = L.read_dump(s.path(tag + "_restarted.dump"))[-1]
    s.ck.check(tag + ": both runs end at step %d" % (2 * N), a[0] == b[0] == 2 * N,
               "%d, %d" % (a[0], b[0]))
    worst = max((abs(a[1][i][c] - b[1][i][c]), i, c) for i in a[1]
                for c in L.DUMP_COLS.split()[1:])
    s.ck.check(tag + ": restarted run identical to the continuous one", worst[0] == 0.0,
               "worst |diff| %.3g in %s of atom %d" % (worst[0], worst[2], worst[1]))


def body(s):
    s.write("drum.inp", L.drum(RC, -0.05, 0.05))
    for tag, wall in (("ours", WALL),):
        full = deck_atoms() + setup_lines(wall)
        full += L.dump_lines("mid", N, tag + "_mid.dump", L.DUMP_COLS + " f_w[4] f_w[5] f_w[6]")
        full += "run %d\nundump mid\n" % N
        full += L.dump_lines("d", N, tag + "_full.dump") + "run %d\n" % N
        s.run(tag + "_full", full)

        first = deck_atoms() + setup_lines(wall)
        first += "run %d\nwrite_restart %s.restart\n" % (N, tag)
        s.run(tag + "_first", first)

        second = restarted_deck(tag + ".restart",
                                "group g1 id 1\ngroup g2 id 2 3\n" + setup_lines(wall))
        second += L.dump_lines("d", N, tag + "_restarted.dump") + "run %d\n" % N
        s.run(tag + "_restarted", second)

        mid = L.read_dump(s.path(tag + "_mid.dump"))[-1][1]
        ang = math.degrees(math.atan2(mid[1]["x"], -mid[1]["y"]))
        # the shear stress against the pressure: friction, within the Coulomb limit 0.4
        shear = math.hypot(mid[1]["f_w[5]"], mid[1]["f_w[6]"]) / mid[1]["f_w[4]"]
        s.ck.check(tag + ": at the restart point sphere 1 is held up by friction",
                   ang > 5.0 and 0.0 < shear <= 0.4 * (1 + 1e-12),
                   "%.2f deg from the bottom, shear/pressure %.3g" % (ang, shear))
        check_identical(s, tag)
    corner_case(s)
    pocket_case(s)
    version_case(s)
    layout_case(s)
    liggghts_case(s)
    spin_case(s)


def spin_case(s):
    """A drum that turns and spins about a crossed axis through one of its points (the
    wall's orientation S accumulated step by step): the spin's angle, rate and S come
    through the restart (layout version 7), so the restarted run is identical."""
    wall = ("fix w all wall/rigid surface drum.inp law hertz type 2 rotate origin 0 0 0 "
            "axis 0 0 1 omega 6 spin origin 0 0 0.01 axis 1 0 0 omega v_ws")
    # of step, not time: LIGGGHTS's time starts again from 0 after read_restart
    lines = ("variable ws equal 0.2+1e-4*step\n" + setup_lines(wall) +
             "variable nc equal f_w[7]\n")
    restart_case(s, "spin", deck_atoms(), lines, 3, "three contacts")


def liggghts_case(s):
    """law liggghts with rolling friction: the model's own history (shear and rolling
    torque) lives in the contact's slot and comes through the restart."""
    wall = ("fix w all wall/rigid surface drum.inp law liggghts model hertz tangential "
            "history rolling_friction epsd2 type 2 rotate origin 0 0 0 axis 0 0 1 omega 6")
    lines = ("fix m5 all property/global coefficientRollingFriction peratomtypepair 2 "
             "0.1 0.1 0.1 0.1\n" + setup_lines(wall) + "variable nc equal f_w[7]\n")
    restart_case(s, "liggghts", deck_atoms(), lines, 3, "three contacts")


def layout_case(s):
    """A restart file whose slots keep every field (written with hertz as a loaded C law,
    which declares nothing it skips: 17 doubles a slot) read by law hertz, whose slots
    keep what it reads (8: no stress, no energies, no slip, no rdisp1). The restarted run equals the
    continuous one of law hertz bit for bit, so the tracker's fields and the shear history
    came through the change of layout."""
    lib = os.environ.get("RS_HERTZ_ALL", "")
    if not s.ck.check("layout: the hertz_all law library is built", os.path.isfile(lib), lib):
        return
    props = "props 5e7 0.3 2e8 0.25 0.7 0.4 0"
    rot = "rotate origin 0 0 0 axis 0 0 1 omega 6"
    ours = "fix w all wall/rigid surface drum.inp law hertz %s type 2 %s" % (props, rot)
    user = ("fix w all wall/rigid surface drum.inp law user %s hertz_all statev 2 %s "
            "type 2 %s" % (lib, props, rot))
    full = deck_atoms() + setup_lines(ours) + "run %d\n" % N
    full += L.dump_lines("d", N, "layout_full.dump") + "run %d\n" % N
    s.run("layout_full", full)
    s.run("layout_first", deck_atoms() + setup_lines(user) +
          "run %d\nwrite_restart layout.restart\n" % N)
    second = restarted_deck("layout.restart",
                            "group g1 id 1\ngroup g2 id 2 3\n" + setup_lines(ours))
    second += L.dump_lines("d", N, "layout_restarted.dump") + "run %d\n" % N
    s.run("layout_restarted", second)
    check_identical(s, "layout")


def restart_case(s, tag, atoms, lines, ncontacts, what):
    """TAG_full: 2N steps in one run (f_w[7], the touching contacts, printed at step N);
    TAG_first: N steps and write_restart; TAG_restarted: read_restart and N steps. At the
    restart point the sphere holds ncontacts, and both runs end identical."""
    full = atoms + lines
    full += 'fix pr all print %d "NC ${nc}" screen yes\n' % N
    full += "run %d\nunfix pr\n" % N
    full += L.dump_lines("d", N, tag + "_full.dump") + "run %d\n" % N
    _, out = s.run(tag + "_full", full)
    s.run(tag + "_first", atoms + lines + "run %d\nwrite_restart %s.restart\n" % (N, tag))
    second = restarted_deck(tag + ".restart", lines)
    second += L.dump_lines("d", N, tag + "_restarted.dump") + "run %d\n" % N
    s.run(tag + "_restarted", second)
    nc = [float(l.split()[1]) for l in out.splitlines() if l.startswith("NC ")]
    s.ck.check("%s: at the restart point the sphere holds %s" % (tag, what),
               len(nc) > 0 and nc[-1] == float(ncontacts), "active contacts %s" % nc)
    check_identical(s, tag)


def pocket_case(s):
    """The apex of a 12-facet cone: the slots grow past the 4 of the fix line."""
    ring = [(0.05 * math.tan(math.radians(30)) * math.cos(2 * math.pi * k / 12),
             0.05 * math.tan(math.radians(30)) * math.sin(2 * math.pi * k / 12), 0.05)
            for k in range(12)]
    stl = "solid cone\n" + "".join(
        " facet normal 0 0 0\n  outer loop\n" +
        "".join("   vertex %r %r %r\n" % p for p in ((0.0, 0.0, 0.0), ring[k], ring[(k + 1) % 12]))
        + "  endloop\n endfacet\n" for k in range(12)) + "endsolid cone\n"
    s.write("cone.stl", stl)

    def atoms():
        d = L.header((-0.06, 0.06, -0.06, 0.06, -0.01, 0.06), DT, mu=0.4)
        # on the axis, touching all 12 facets (each plane is at angle a to the axis), and
        # spinning about it so that every contact carries a tangential history
        a = math.atan(math.tan(math.radians(30)) * math.cos(math.pi / 12))
        d += L.sphere(1, (0.0, 0.0, R / math.sin(a) - 2e-5), R, RHO, omega=(0.0, 0.0, 20.0))
        return d

    lines = ("fix grav all gravity 9.81 vector 0 0 -1\n"
             "fix w all wall/rigid surface inline mesh cone.stl law hertz type 2 "
             "rotate origin 0 0 0 axis 0 0 1 omega 3\n"
             "fix i all nve/sphere\nvariable nc equal f_w[7]\n")
    restart_case(s, "pocket", atoms(), lines, 12, "12 contacts (grown slots)")


def corner_case(s):
    """A sphere in the mantle / bottom-cap corner: two contacts through the restart."""
    s.write("closed.inp", L.drum(RC, -0.05, 0.05, caps=True))
    wall = ("fix w all wall/rigid surface closed.inp law hertz type 2 "
            "rotate origin 0 0 0 axis 0 0 1 omega 6")
    mass = RHO * 4.0 / 3.0 * math.pi * R ** 3

    def atoms():
        d = L.header((-0.06, 0.06, -0.06, 0.06, -0.06, 0.06), DT, mu=0.4)
        d += L.sphere(1, (0.0, -(RC - R + 1e-5), -0.05 + R - 1e-5), R, RHO)
        return d

    def lines():
        # gravity presses it on the mantle, a push along -z into the bottom cap
        return ("fix grav all gravity 9.81 vector 0 -1 0\n"
                "fix push all addforce 0 0 %r\n" % (-9.81 * mass) + wall + "\n"
                "fix i all nve/sphere\nvariable nc equal f_w[7]\n")

    restart_case(s, "corner", atoms(), lines(), 2, "two contacts (two slots)")


def version_case(s):
    """ours.restart as version 5 (converted on reading) and as version 4 (refused)."""
    with open(s.path("ours.restart"), "rb") as f:
        data = bytearray(f.read())
    cap = 4.0
    head = struct.pack("<2d", 7.0, cap)
    at = [k for k in range(len(data)) if data.startswith(head, k)]
    nstatev, npred = struct.unpack_from("<2d", data, at[0] + 16) if at else (-1, -1)
    s.ck.check("version: one wall/rigid global record of version 7 in the file",
               len(at) == 1 and nstatev >= 0 and npred == 0, "at %s" % at)
    if len(at) != 1:
        return
    # each atom's record: its length + 1, the capacity, then the directory (row first);
    # a hertz slot keeps n, t1 and the state variables (hertz reads neither its last
    # stress nor its energies nor the accumulated slip and rdisp1: rs_law.skips)
    atom_size = (cap + 1 + npred) + cap * (6 + nstatev)
    rec = struct.pack("<2d", 2.0 + atom_size, cap)
    recs = [k for k in range(len(data)) if data.startswith(rec, k)]
    old = bytearray(data)
    struct.pack_into("<d", old, at[0], 5.0)
    dirs = []
    for k in recs:
        d = list(struct.unpack_from("<4d", data, k + 16))
        dirs.append(d)
        struct.pack_into("<4d", old, k + 16, *[e - 1.0 for e in d])
    s.ck.check("version: three atom records, each with one live slot of the drum",
               len(recs) == 3 and all(sum(e >= 1.0 for e in d) == 1 and
                                      sum(e == 0.0 for e in d) == 3 for d in dirs),
               "directories %s" % dirs)
    with open(s.path("v5.restart"), "wb") as f:
        f.write(old)
    struct.pack_into("<d", old, at[0], 4.0)
    with open(s.path("v4.restart"), "wb") as f:
        f.write(old)
    setup = "group g1 id 1\ngroup g2 id 2 3\n" + setup_lines(WALL)
    second = restarted_deck("v5.restart", setup)
    second += L.dump_lines("d", N, "v5_restarted.dump") + "run %d\n" % N
    s.run("v5_restarted", second)
    shutil.copy(s.path("ours_full.dump"), s.path("v5_full.dump"))
    check_identical(s, "v5")
    rc, out = s.run("v4_restarted", restarted_deck("v4.restart", setup) + "run 10\n",
                    expect_ok=False)
    s.ck.check("version: a file of layout version 4 is refused, naming what is read",
               rc != 0 and "layout version 4;" in out and "versions 5 to 7" in out,
               [l for l in out.splitlines() if "ERROR" in l][-1:].__repr__())


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
