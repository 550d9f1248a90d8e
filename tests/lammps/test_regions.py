#!/usr/bin/python3
"""law lammps on a cylinder and a cone against LAMMPS's region walls, static and rotating.

One sphere (R = 12 or 15 mm) hits the inside of a cylinder (Rc = 50 mm) or of a cone
(half-angle 31 degrees, contact where its radius is 50 mm) head-on at 0.5 m/s, with no
gravity: `fix wall/gran/region hertz/history kn NULL 0 0 xmu 0` on `region cylinder|cone
... side in` in stock lmp, `fix wall/rigid surface <REVOLUTION> law lammps hertz/history
...` (the same words) in lmp-rigidsurf. The contact is elastic (no damping): the sphere
leaves at 0.5 m/s.

The difference that the test states and bounds is the wall's curvature in the Hertz
force F = kn delta sqrt(delta Reff), Reff = R rwall / (R + rwall):
- stock's region walls take rwall = -2 r, r the radius of the circle the region's
  cross-section makes through the contact point (region_cylinder.cpp and
  region_cone.cpp: contact[].radius);
- law lammps by default gives the exact effective radius of the wall's principal
  curvatures (0 along the generator, -cos(beta)/r around the hoop):
  Reff = R / sqrt(1 - R cos(beta) / r);
- `reff region` gives rwall = 2/k of the most curved direction: -2 r / cos(beta), which
  is stock's on a cylinder (beta = 0).
The energy (2/5) kn sqrt(Reff) delta^(5/2) = m v^2 / 2 makes the deepest overlap scale as
Reff^(-1/5): each run's deepest overlap against stock's is that ratio (to 2 % of its
distance from 1; it is 1.0025 to 1.004 here). On the cylinder, `reff region` gives stock's
trajectory to 1e-9.

Rotating (100 rad/s about the axis: the wall's surface moves at 5 m/s, stock's region by
`rotate v_theta`, ours by `rotate ... omega`), with friction xmu = 0.5: the sphere slides
throughout the contact, so the tangential impulse is xmu times the normal one, 2 m v,
whatever Reff: it leaves with a tangential velocity 2 xmu v and a spin 5 xmu v / R (the
lever arm of LAMMPS's models is R). Those agree with stock's to 1e-5, and with the
closed forms to 1 % (the sphere slides round the wall during the contact, so its normal
turns by about 0.01 rad, and the shear spring takes a few steps to slide). A wall at rest
adds no energy: there the sphere leaves at its speed of impact, to 1e-4 (the time step's
error).
"""
import math

import lmplib as M

V, DT, STEPS, KN, RHO, W = 0.5, 1.0e-6, 2000, 2e8, 2500.0, 100.0
RC = 0.05
CONE = (0.02, 0.08, 0.0, 0.1)  # radius at lo, radius at hi, lo, hi (along z)
BOX = (-0.1, 0.1, -0.1, 0.1, -0.05, 0.15)


def geometry(kind):
    """(R, contact point, inward normal, r of the cross-section there, cos beta)."""
    if kind == "cylinder":
        return 0.015, (RC, 0.0, 0.0), (-1.0, 0.0, 0.0), RC, 1.0
    rlo, rhi, lo, hi = CONE
    zc = 0.05
    rc = rlo + (zc - lo) * (rhi - rlo) / (hi - lo)
    L = math.hypot(hi - lo, rhi - rlo)
    cb, sb = (hi - lo) / L, (rhi - rlo) / L  # cos beta, sin beta (beta from the axis)
    return 0.012, (rc, 0.0, zc), (-cb, 0.0, sb), rc, cb


def surface(kind):
    if kind == "cylinder":
        return M.L.drum(RC, -1.0, 1.0, name="wall")
    rlo, rhi, lo, hi = CONE
    return ("*SURFACE, TYPE=REVOLUTION, NAME=wall\n0, 0, 0, 0, 0, 1\n"
            "START, %r, %r\nLINE, %r, %r\n" % (rlo, lo, rhi, hi))


def deck(kind, tag, wall, rotating):
    R, xc, n, _, _ = geometry(kind)
    x0 = [xc[d] + n[d] * (R + 1e-4) for d in range(3)]
    d = M.header(BOX, DT)
    d += M.sphere(1, x0, R, RHO, [-V * c for c in n])
    d += "variable theta equal %r*step*dt\n" % (W if rotating else 0.0)
    if kind == "cylinder":
        d += "region wall cylinder z 0 0 %r -1 1 side in" % RC
    else:
        d += "region wall cone z 0 0 %r %r %r %r side in" % CONE
    d += (" rotate v_theta 0 0 0 0 0 1\n" if rotating else "\n")
    d += wall + "\n"
    d += "fix integr all nve/sphere\n"
    d += M.dump_lines("d", 1, tag + ".dump")
    d += "run %d\n" % STEPS
    return d


def overlaps(kind, frames):
    """The sphere's overlap with the wall at each frame, from its centre."""
    R, xc, n, _, _ = geometry(kind)
    out = []
    for _, f in frames:
        a = f[1]
        rho = math.hypot(a["x"], a["y"])
        if kind == "cylinder":
            gap = RC - rho
        else:
            rlo, rhi, lo, hi = CONE
            # distance from the cone's generator line in the (rho, z) plane
            L = math.hypot(hi - lo, rhi - rlo)
            gap = ((rlo - rho) * (hi - lo) + (a["z"] - lo) * (rhi - rlo)) / L
        out.append(R - gap)
    return out


def predicted_reff(kind, mode):
    R, _, _, r, cb = geometry(kind)
    if mode == "stock":
        rwall = -2.0 * r
    elif mode == "region":
        rwall = -2.0 * r / cb
    else:
        return R / math.sqrt(1.0 - R * cb / r)
    return R * rwall / (R + rwall)


def body(s):
    for kind in ("cylinder", "cone"):
        s.write(kind + ".inp", surface(kind))
        R = geometry(kind)[0]
        for rotating in (False, True):
            xmu = 0.5 if rotating else 0.0
            model = "hertz/history %r NULL 0 0 %r 0" % (KN, xmu)
            name = kind + ("_rotating" if rotating else "_static")
            motion = " rotate origin 0 0 0 axis 0 0 1 omega %r" % W if rotating else ""
            runs = {
                "stock": "fix w all wall/gran/region %s region wall" % model,
                "exact": "fix w all wall/rigid surface %s.inp law lammps %s%s"
                         % (kind, model, motion),
                "region": "fix w all wall/rigid surface %s.inp law lammps reff region %s%s"
                          % (kind, model, motion)}
            frames = {}
            for mode, wall in runs.items():
                tag = name + "_" + mode
                s.run(tag, deck(kind, tag, wall, rotating),
                      exe=s.args.lmp if mode == "stock" else None)
                frames[mode] = M.read_dump(s.path(tag + ".dump"))
            deepest = {m: max(overlaps(kind, f)) for m, f in frames.items()}
            s.ck.check(name + ": stock's wall made contact", deepest["stock"] > 1e-5,
                       "deepest overlap %.6g m" % deepest["stock"])
            for mode in ("exact", "region"):
                want = (predicted_reff(kind, "stock") / predicted_reff(kind, mode)) ** 0.2
                got = deepest[mode] / deepest["stock"]
                s.ck.check("%s: reff %s: deepest overlap / stock's = (Reff_stock / Reff)^(1/5)"
                           % (name, mode), abs(got - want) <= 0.02 * abs(want - 1.0) + 1e-9,
                           "%.7f, predicted %.7f" % (got, want))
            if kind == "cylinder":
                M.L.check_trajectories(s, name + ": reff region", frames["region"],
                                       frames["stock"], M.scales(R), 1e-9,
                                       ref="stock lmp's")
            last = {m: f[-1][1][1] for m, f in frames.items()}
            for mode, a in (last.items() if not rotating else ()):
                speed_n = sum(a["v" + c] * nc for c, nc in zip("xyz", geometry(kind)[2]))
                s.ck.check("%s: %s: the sphere leaves at its speed of impact (no energy added)"
                           % (name, mode), abs(speed_n - V) <= 1e-4 * V,
                           "normal speed %.8f m/s" % speed_n)
            if not rotating:
                continue
            # the sliding contact's impulse: tangential velocity along +y, spin about the
            # axis normal to n and y
            n = geometry(kind)[2]
            spin_axis = (n[1] * 0 - n[2] * 1, n[2] * 0 - n[0] * 0, n[0] * 1 - n[1] * 0)
            for mode, a in last.items():
                vt = a["vy"]
                wt = -sum(a["omega" + c] * ax for c, ax in zip("xyz", spin_axis))
                s.ck.check("%s: %s: tangential velocity 2 xmu v, spin 5 xmu v / R" % (name, mode),
                           abs(vt - 2 * xmu * V) <= 1e-2 * 2 * xmu * V
                           and abs(wt - 5 * xmu * V / R) <= 1e-2 * 5 * xmu * V / R,
                           "%.6f m/s, %.5f rad/s" % (vt, wt))
                if mode != "stock":
                    dv = M.rel_diff(vt, last["stock"]["vy"], 1e-12)
                    dw = M.rel_diff(wt, -sum(last["stock"]["omega" + c] * ax
                                             for c, ax in zip("xyz", spin_axis)), 1e-12)
                    s.ck.check("%s: %s: tangential velocity and spin equal stock's to 1e-5"
                               % (name, mode), dv <= 1e-5 and dw <= 1e-5,
                               "rel %.2g, %.2g" % (dv, dw))


if __name__ == "__main__":
    M.L.main_guard(M.L.Session(__doc__, extra=[M.STOCK]), body)
