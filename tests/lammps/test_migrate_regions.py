#!/usr/bin/python3
"""LAMMPS's `fix wall/gran/region` on each region style, still, turning and moving, run by
stock lmp as written and by lmp-rigidsurf as rigidsurf-migrate rewrites it.

The impacts of test_regions.py (one sphere head-on against a cylinder's or a cone's inside
at 0.5 m/s, elastic, `hertz/history` with no damping; turning at 100 rad/s by `rotate
v_theta` with theta = 100 step dt, with friction 0.5), with the region walls as the deck
writes them and the tool's rewrite. The tool writes `law lammps reff region` on
cylinders and cones, whose wall radius is LAMMPS's on a cylinder (-2 Rc), so there:

- a cylinder, still and turning: stock's trajectory to 1e-9;
- a cone, still and turning: the difference test_regions.py states and bounds, LAMMPS's
  -2 r against reff region's -2 r / cos(beta): the deepest overlap against stock's is
  (Reff_stock / Reff)^(1/5) (to 2 % of its distance from 1), and turning, the sphere
  leaves with stock's tangential velocity and spin to 1e-5.

Elsewhere the wall radius is LAMMPS's and the runs agree to 1e-9 (positions against R,
velocities against 1 m/s, spins against 1/R, forces against 1 N):

- a sphere region, inside and (side out) outside (LAMMPS takes -Rs and +Rs, the exact
  effective radius, which the tool leaves law lammps to compute);
- a block (a closed triangle mesh the tool writes): a sphere settling into a corner,
  touching three faces; a prism with a tilted face, hooke/history;
- a plane region moved by `move NULL NULL v_z` (z = A sin(w t)) under a resting sphere,
  and a block turned by `rotate v_th` about z and moved by `move v_x NULL NULL` under a
  sphere resting on its floor, with friction: LAMMPS's wall velocity is the change of
  the variables over the step, which the tool's rates are; a cylinder turned about a
  point off its axis and moved, standing away from its definition when the wall is made
  (the tool writes it there); the block again in two runs
  of 5000 steps, the second to 1e-6: LAMMPS's region has no velocity in the setup of a
  run after the first (Region::init forgets its last step), wall/rigid its last step's
  (measured 6e-8);
- an intersection of two planes (a V trough, an extruded profile), a sphere on each
  face; an intersection of a cylinder and a plane normal to its axis (a drum with a
  floor); a union of a cylinder and a cone (a hopper: one REVOLUTION), a sphere hitting
  the cylinder's face (to 1e-9) and one the cone's (its overlap as on the cone above);
- a union of members that are all open (LAMMPS's granregion funnel: a cone open at both
  ends over a pipe open at its top): each member a wall of its own, a sphere dropped onto
  the pipe's plug and one thrown at its wall, to 1e-9;
- a closed drum with spheres dropped onto its lid from above: LAMMPS's region wall leaves a
  particle outside its region alone, so they fall through the lid and land on the floor
  (wall/rigid's behind none), to 1e-9;
- a cylinder open at both ends (`open 1 open 2`: LAMMPS makes it two-sided): a sphere
  hitting its inside (to 1e-9), and one its outside, where LAMMPS's open branch takes the
  wall flat (rwall 0) and reff region +2 Rc: the deepest overlap against stock's is
  (R / Reff)^(1/5), Reff = R 2Rc / (R + 2Rc).
"""
import math

import lmplib as M
import migratelib as G
import test_regions as T

V, DT, STEPS, KN, RHO, W = T.V, T.DT, T.STEPS, T.KN, T.RHO, T.W
ELASTIC = "hertz/history %r NULL 0 0 %%r 0" % KN
SCALES = lambda R: dict(M.scales(R), fx=1.0, fy=1.0, fz=1.0)  # noqa: E731


def head_on(R, xc, n, speed=V):
    """A sphere of radius R just off the wall point xc (normal n into the region), moving
    at speed into the wall."""
    return M.sphere(1, [xc[d] + n[d] * (R + 1e-4) for d in range(3)], R, RHO,
                    [-speed * c for c in n])


def deck(name, regions, wall, atoms, gravity=None, steps=STEPS, dt=DT, pre="", runs=1):
    d = M.header(T.BOX, dt) + pre + atoms
    if gravity:
        d += "fix grav all gravity 9.81 vector %s\n" % gravity
    d += regions + wall + "\n" + "fix integr all nve/sphere\n"
    d += M.dump_lines("d", 10, name + ".dump")
    return d + "run %d\n" % (steps // runs) * runs


def exact(s, name, d, R):
    stock, rigid, err, text = G.pair(s, name, d)
    touched = any(abs(a["fx"]) + abs(a["fy"]) + abs(a["fz"]) > 0 for _, f in stock
                  for a in f.values())
    s.ck.check(name + ": stock's wall pushed the spheres", touched)
    M.L.check_trajectories(s, name, rigid, stock, SCALES(R), 1e-9, ref="stock lmp's")
    return stock, rigid, err, text


def ratio(s, name, stock, rigid, gap, want):
    """The deepest overlap (R - gap(atom)) against stock's: want, to 2 % of its distance
    from 1."""
    deep = [max(gap(a) for _, f in frames for a in f.values()) for frames in (stock, rigid)]
    got = deep[1] / deep[0]
    s.ck.check("%s: deepest overlap / stock's = (Reff_stock / Reff)^(1/5)" % name,
               deep[0] > 1e-5 and abs(got - want) <= 0.02 * abs(want - 1.0) + 1e-9,
               "%.7f, predicted %.7f" % (got, want))


def impacts(s):
    """test_regions.py's cylinder and cone, still and turning, as the tool migrates
    them."""
    for kind in ("cylinder", "cone"):
        R = T.geometry(kind)[0]
        for rotating in (False, True):
            xmu = 0.5 if rotating else 0.0
            name = "%s_%s" % (kind, "turning" if rotating else "still")
            wall = "fix w all wall/gran/region %s region wall" % (ELASTIC % xmu)
            stock, rigid, err, text = G.pair(s, name, T.deck(kind, name, wall, rotating))
            s.ck.check(name + ": law lammps reff region with the model words",
                       "law lammps reff region " + ELASTIC % xmu in
                       " ".join(text.replace("&\n", " ").split()), why=text)
            if kind == "cylinder":
                M.L.check_trajectories(s, name, rigid, stock, SCALES(R), 1e-9,
                                       ref="stock lmp's")
                continue
            want = (T.predicted_reff(kind, "stock") / T.predicted_reff(kind, "region")) ** 0.2
            ratio(s, name, stock, rigid, lambda a: max(T.overlaps(kind, [(0, {1: a})])),
                  want)
            if rotating:
                a, b = rigid[-1][1][1], stock[-1][1][1]
                dv = M.rel_diff(a["vy"], b["vy"], 1e-12)
                dw = max(M.rel_diff(a["omega" + c], b["omega" + c], 1e-12 / R) for c in "xz")
                s.ck.check(name + ": tangential velocity and spin equal stock's to 1e-5",
                           dv <= 1e-5 and dw <= 1e-5, "rel %.2g, %.2g" % (dv, dw))


def spheres_blocks(s):
    R = 0.01
    # inside a sphere region of radius 0.08 about (0, 0, 0.05), and outside one of 0.03
    d = deck("sphere_in", "region s sphere 0 0 0.05 0.08 units box\n",
             "fix w all wall/gran/region granular hertz 2e8 0.3 tangential linear_history "
             "1e5 1.0 0.5 region s", head_on(R, (0.08 * 0.6, 0.0, 0.05 + 0.08 * 0.8),
                                                  (-0.6, 0.0, -0.8)))
    exact(s, "sphere_in", d, R)
    d = deck("sphere_out", "region s sphere 0 0 0.05 0.03 side out units box\n",
             "fix w all wall/gran/region hertz/history 2e8 NULL 50 NULL 0.5 1 region s",
             M.sphere(1, (0.0402, 0.0, 0.05), R, RHO, (-0.5, 0.1, 0.0)))
    exact(s, "sphere_out", d, R)
    # a sphere let fall into the corner of a block, sliding toward it
    d = deck("block_corner", "region b block -0.05 0.05 -0.06 0.04 0 0.12 units box\n",
             "fix w all wall/gran/region hooke/history 2e5 NULL 50 NULL 0.5 1 region b",
             M.sphere(1, (0.035, 0.025, 0.03), R, RHO, (0.2, 0.15, 0.0), (0, 0, 10)),
             gravity="0 0 -1", dt=1e-5, steps=20000)
    exact(s, "block_corner", d, R)
    d = deck("prism", "region p prism -0.05 0.05 -0.05 0.05 0 0.1 0 0.04 0 units box\n",
             "fix w all wall/gran/region hooke/history 2e5 NULL 50 NULL 0.5 1 region p",
             M.sphere(1, (0.05, 0.0, 0.05), R, RHO, (1.0, 0.1, 0.0)), dt=1e-5, steps=5000)
    exact(s, "prism", d, R)


def moving(s):
    R = 0.005
    pre = "variable z equal 0.002*sin(2*PI*20*time)\n"
    d = deck("plane_moving", "region p plane 0 0 0 0 0 1 move NULL NULL v_z units box\n",
             "fix w all wall/gran/region hertz/history 2e8 NULL 5e3 NULL 0.5 1 region p",
             M.sphere(1, (0.0, 0.0, R), R, RHO), gravity="0 0 -1", dt=1e-5, steps=10000,
             pre=pre)
    exact(s, "plane_moving", d, R)
    pre = "variable th equal 2*time\nvariable x equal 0.01*time\n"
    d = deck("block_turning", "region b block -0.05 0.05 -0.05 0.05 0 0.12 move v_x NULL "
             "NULL rotate v_th 0 0 0 0 0 1 units box\n",
             "fix w all wall/gran/region hertz/history 2e8 NULL 5e3 NULL 0.5 1 region b",
             M.sphere(1, (0.02, 0.0, R), R, RHO), gravity="0 0 -1", dt=1e-5, steps=10000,
             pre=pre)
    exact(s, "block_turning", d, R)
    # a cylinder turned about a point off its axis and moved, standing away from its
    # definition when the wall is made (x = 5 mm, th = 0.3): the wall starts there
    pre = "variable th equal 0.3+20*time\nvariable x equal 0.005+0.5*time\n"
    d = deck("cylinder_orbiting", "region c cylinder z 0 0 0.05 -1 1 move v_x NULL NULL "
             "rotate v_th 0.01 0 0 0 0 1 units box\n",
             "fix w all wall/gran/region hertz/history 2e8 NULL 5e3 NULL 0.5 1 region c",
             M.sphere(1, (0.0, 0.0, 0.05), R, RHO, (0.0, 0.4, 0.0)) +
             M.sphere(2, (0.0, 0.0, 0.0), R, RHO, (-0.3, -0.1, 0.0)), dt=1e-5, steps=10000,
             pre=pre)
    exact(s, "cylinder_orbiting", d, R)
    # the same in two runs: in the second run's setup LAMMPS's region has no velocity
    # (Region::init forgets the last step, set_velocity differences the step with itself),
    # wall/rigid the last step's rates
    d = deck("block_turning_two_runs", "region b block -0.05 0.05 -0.05 0.05 0 0.12 move "
             "v_x NULL NULL rotate v_th 0 0 0 0 0 1 units box\n",
             "fix w all wall/gran/region hertz/history 2e8 NULL 5e3 NULL 0.5 1 region b",
             M.sphere(1, (0.02, 0.0, R), R, RHO), gravity="0 0 -1", dt=1e-5, steps=10000,
             pre=pre, runs=2)
    stock, rigid, _, _ = G.pair(s, "block_turning_two_runs", d)
    first = [(n, f) for n, f in stock if n <= 5000], [(n, f) for n, f in rigid if n <= 5000]
    M.L.check_trajectories(s, "block_turning_two_runs: the first run", first[1], first[0],
                           SCALES(R), 1e-9, ref="stock lmp's")
    M.L.check_trajectories(s, "block_turning_two_runs: both runs", rigid, stock, SCALES(R),
                           1e-6, ref="stock lmp's")


def combined(s):
    R = 0.006
    rg = ("region a plane 0 0 0 1 0 1 units box\nregion b plane 0 0 0 -1 0 1 units box\n"
          "region v intersect 2 a b\n")
    atoms = M.sphere(1, (0.03, 0.0, 0.06), R, RHO, (0.0, 0.1, 0.0)) + \
        M.sphere(2, (-0.04, 0.0, 0.07), R, RHO, (0.05, 0.0, 0.0))
    d = deck("trough", rg, "fix w all wall/gran/region hooke/history 2e5 NULL 50 NULL 0.5 1 "
             "region v", atoms, gravity="0 0 -1", dt=1e-5, steps=15000)
    exact(s, "trough", d, R)
    rg = ("region c cylinder z 0 0 0.05 -1 1 units box\nregion f plane 0 0 0.01 0 0 1 units "
          "box\nregion d intersect 2 c f\n")
    d = deck("drum_floor", rg, "fix w all wall/gran/region hertz/history 2e8 NULL 5e3 NULL "
             "0.5 1 region d", M.sphere(1, (0.0, 0.02, 0.03), R, RHO, (0.0, 0.3, 0.0)),
             gravity="0 0 -1", dt=1e-5, steps=15000)
    exact(s, "drum_floor", d, R)
    # a hopper: the cone of test_regions.py under a cylinder of its top radius
    rlo, rhi, lo, hi = T.CONE
    rg = ("region k cone z 0 0 %r %r %r %r units box\nregion c cylinder z 0 0 %r %r 0.2 "
          "units box\nregion h union 2 k c\n" % (rlo, rhi, lo, hi, rhi, hi))
    wall = "fix w all wall/gran/region %s region h" % (ELASTIC % 0.0)
    Rc = 0.012
    d = deck("hopper_cylinder", rg, wall, head_on(Rc, (rhi, 0.0, 0.125), (-1.0, 0.0, 0.0)))
    exact(s, "hopper_cylinder", d, Rc)
    R, xc, n, _, _ = T.geometry("cone")
    stock, rigid, _, _ = G.pair(s, "hopper_cone", deck("hopper_cone", rg, wall,
                                                       head_on(R, xc, n)))
    want = (T.predicted_reff("cone", "stock") / T.predicted_reff("cone", "region")) ** 0.2
    ratio(s, "hopper_cone", stock, rigid, lambda a: max(T.overlaps("cone", [(0, {1: a})])),
          want)


def funnel(s):
    """LAMMPS's granregion funnel example's walls: a union of a cone open at both ends and a
    pipe open at its top below it (each member then acts as it would alone), a sphere
    dropped onto the pipe's plug and one thrown at the pipe's wall, both from inside."""
    R = 0.004
    rg = ("region pipe cylinder z 0 0 0.02 -0.04 0.02 open 2 units box\n"
          "region cone cone z 0 0 0.02 0.09 0.02 0.12 open 1 open 2 units box\n"
          "region hop union 2 cone pipe\n")
    wall = "fix w all wall/gran/region hertz/history 2e8 NULL 5e3 NULL 0.5 1 region hop"
    atoms = M.sphere(1, (0.0, 0.005, -0.02), R, RHO, (0.0, 0.0, -0.3)) + \
        M.sphere(2, (-0.005, 0.0, -0.01), R, RHO, (-0.4, 0.1, 0.0))
    exact(s, "funnel", deck("funnel", rg, wall, atoms, gravity="0 0 -1", dt=1e-5,
                            steps=8000), R)


def through_lid(s):
    """A closed drum (a cylinder region side in, its lid at z = 0.1) with spheres dropped
    onto its lid from above: LAMMPS's region wall leaves a particle outside its region
    alone, so they fall through the lid into the drum and land on its floor; the tool's
    wall/rigid leaves them alone by behind none."""
    R = 0.005
    rg = "region d cylinder z 0 0 0.05 0 0.1 units box\n"
    wall = "fix w all wall/gran/region hooke/history 2e5 NULL 50 NULL 0.5 1 region d"
    atoms = M.sphere(1, (0.0, 0.01, 0.11), R, RHO, (0.0, 0.0, -0.5)) + \
        M.sphere(2, (0.045, 0.0, 0.12), R, RHO, (0.0, 0.0, -0.3))
    stock, rigid, _, text = exact(s, "through_lid", deck(
        "through_lid", rg, wall, atoms, gravity="0 0 -1", dt=1e-5, steps=15000), R)
    s.ck.check("through_lid: stock's spheres fell through the lid onto the floor, as the "
               "migrated deck's (behind none)", "behind none" in text and
               all(a["z"] < 0.02 for a in stock[-1][1].values()),
               str([a["z"] for a in stock[-1][1].values()]))


def open_cylinder(s):
    R, Rc = 0.012, T.RC
    rg = "region c cylinder z 0 0 %r -1 1 open 1 open 2 units box\n" % Rc
    wall = "fix w all wall/gran/region %s region c" % (ELASTIC % 0.0)
    d = deck("open_inside", rg, wall, head_on(R, (Rc, 0.0, 0.0), (-1.0, 0.0, 0.0)))
    exact(s, "open_inside", d, R)
    stock, rigid, _, _ = G.pair(s, "open_outside", deck(
        "open_outside", rg, wall, head_on(R, (Rc, 0.0, 0.0), (1.0, 0.0, 0.0))))
    reff = R * 2 * Rc / (R + 2 * Rc)
    ratio(s, "open_outside", stock, rigid,
          lambda a: R - (math.hypot(a["x"], a["y"]) - Rc), (R / reff) ** 0.2)


def body(s):
    impacts(s)
    spheres_blocks(s)
    moving(s)
    combined(s)
    funnel(s)
    through_lid(s)
    open_cylinder(s)


if __name__ == "__main__":
    M.L.main_guard(G.session(__doc__), body)
