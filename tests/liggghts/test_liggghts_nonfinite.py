#!/usr/bin/python3
"""law liggghts where LIGGGHTS's own wall/gran stops with a segmentation fault.

A sphere (R = 5 mm) lands on a plane, rests, and an upward force that grows from m g to
40 m g pulls it off (the deck of test_liggghts_models.py, without spin), once through
`fix wall/gran ... primitive zplane` (stock) and once through `fix wall/rigid` with
`law liggghts` and the same model words.

- thornton_ning (Thornton and Ning's JKR contact) with surfaceEnergy 0.01: its force is
  LIGGGHTS's formula in F + fc (fc = 3/2 pi gamma R, the pull-off force), which it
  takes the square root of. At dt = 1e-5 the pull unloads the contact past its whole
  adhesive branch in one step (the force falls from +2e-3 N to -2e-3 N, where
  fc = 2.4e-4 N), the model returns NaN, and stock LIGGGHTS loses the sphere and
  crashes at the next neighbour build. wall/rigid stops at that contact with exit 1
  and one ERROR that names the model, the particle, the last force and the pull-off
  force. At dt = 1e-6 the branch is followed: both runs end and their trajectories
  agree to 1e-9.
- easo/capillary/viscous on a plane of material type 1: once the sphere has left the
  plane, the liquid bridge's close branch reads "atom j" (LIGGGHTS's primitive walls
  pass j = -type, so atom->v[-1], before the array: stock crashes there). wall/rigid
  makes j the wall, at rest, and runs to the end. While the sphere touches, the two
  agree to 1e-9; after it has left, the force of the bridge on the sphere is the
  model's closed form (Soulie et al.'s capillary force at the gap, Nase's viscous
  force at the sphere's velocity, the wall at rest) to 1e-9 of the largest force.
"""
import math
import re

import liglib as L

R, RHO = 0.005, 2500.0
MASS = RHO * 4.0 / 3.0 * math.pi * R ** 3
G = 9.81
PULL = 40.0
BOX = (-0.05, 0.05, -0.05, 0.05, -0.01, 0.1)
SCALES = {"x": R, "y": R, "z": R, "vx": 1.0, "vy": 1.0, "vz": 1.0,
          "omegax": 1.0 / R, "omegay": 1.0 / R, "omegaz": 1.0 / R}
PLANE = ("surface inline cylinder a 0 0 0 b 1 0 0 c 0 -1 0 profile START -1 0 LINE 1 0 "
         "end")
TN = "model thornton_ning tangential history"
TN_PROPS = ("fix m5 all property/global surfaceEnergy peratomtypepair 2 0.01 0.01 0.01 0.01\n"
            "fix m6 all property/global coefficientYieldRatio peratomtype 0.5 0.5\n")
EASO = "model hertz tangential history cohesion easo/capillary/viscous"
# liquid: content 1 % of the sphere's volume, tension 5 N/m, viscosity 1e-3 Pa s, contact
# angle 0.5 degrees, bridge from 1.01 to 1.1 of the radii
SLC, SIGMA, MU, THETA, SMIN, SMAX = 0.01, 5.0, 0.001, 0.5, 1.01, 1.1
EASO_PROPS = ("fix m5 all property/global surfaceLiquidContentInitial scalar %r\n"
              "fix m6 all property/global surfaceTension scalar %r\n"
              "fix m7 all property/global fluidViscosity scalar %r\n"
              "fix m8 all property/global contactAngle peratomtype %r %r\n"
              "fix m9 all property/global minSeparationDistanceRatio scalar %r\n"
              "fix m10 all property/global maxSeparationDistanceRatio scalar %r\n"
              % (SLC, SIGMA, MU, THETA, THETA, SMIN, SMAX))
COLS = "id x y z vx vy vz omegax omegay omegaz fz"


def deck(wall, props, dt, tag, vel=(0.1, 0.05, -0.05), omega=(20.0, -30.0, 40.0),
         gap=2.0e-4):
    """Phase 1 (0.015 s): land (from gap above the plane) and rest; phase 2 (0.007 s):
    pulled off."""
    n1, n2 = int(round(0.015 / dt)), int(round(0.007 / dt))
    d = L.header(BOX, dt, e=0.3, extra_props=props)
    d += L.sphere(1, (0.0, 0.0, R + gap), R, RHO, v=vel, omega=omega)
    d += "fix grav all gravity %r vector 0 0 -1\nfix integr all nve/sphere\n" % G
    d += wall + "\n"
    d += L.dump_lines("d", max(1, n1 // 300), tag + ".dump", cols=COLS)
    d += "run %d\n" % n1
    d += "variable fup equal %r*(1.0+%r*(step-%d)/%d)\n" % (MASS * G, PULL - 1.0, n1, n2)
    d += "fix up all addforce 0 0 v_fup\nrun %d\n" % n2
    return d, n1, n2


def walls(model, wall_type):
    return ("fix w all wall/gran %s primitive type %d zplane 0" % (model, wall_type),
            "fix w all wall/rigid %s law liggghts %s type %d" % (PLANE, model, wall_type))


def thornton_ning(s):
    stock, ours = walls(TN, 2)
    d, _, _ = deck(stock, TN_PROPS, 1e-5, "tn_stock")
    rc, out = s.run("tn_stock", d, expect_ok=False)
    print("stock LIGGGHTS, thornton_ning at dt 1e-5: exit %s%s" % (
        rc, " (segmentation fault)" if rc == 139 or "Segmentation" in out else ""))
    d, _, _ = deck(ours, TN_PROPS, 1e-5, "tn_ours")
    rc, out = s.run("tn_ours", d, expect_ok=False)
    # the message, as wall/rigid prints it and as LIGGGHTS's error->one repeats it
    errs = {re.sub(r" \(\S+:\d+\)$", "", l) for l in L.error_lines(out)}
    want = ["law liggghts " + TN, "particle 1", "not finite",
            "below the pull-off force -fc = -0.000235619"]
    s.ck.check("thornton_ning past its pull-off force within one step: exit 1 with one "
               "ERROR naming the model, the particle and the pull-off force",
               rc == 1 and len(errs) == 1 and all(w in e for e in errs for w in want),
               "; ".join(errs)[:160], "exit %s: %s" % (rc, " | ".join(out.splitlines()[-4:])))
    for tag, wall in (("tn_fine_stock", stock), ("tn_fine_ours", ours)):
        s.run(tag, deck(wall, TN_PROPS, 1e-6, tag)[0])
    fa, fb = (L.read_dump(s.path(t + ".dump")) for t in ("tn_fine_ours", "tn_fine_stock"))
    s.ck.check("thornton_ning at dt 1e-6: the sphere touched and was pulled off",
               min(f[1]["z"] for _, f in fb) < R and fb[-1][1][1]["z"] > R + 1e-4,
               "lowest centre %.6g, last %.6g" % (min(f[1]["z"] for _, f in fb),
                                                  fb[-1][1][1]["z"]))
    L.check_trajectories(s, "thornton_ning at dt 1e-6", fa, fb, SCALES, 1e-9)


def bridge_force(gap, vn):
    """easo/capillary/viscous's close branch on a wall: the force along the normal on a
    sphere at gap (> 0) moving away at vn from a wall at rest (Debian's LIGGGHTS 3.8.0,
    cohesion_model_easo_capillary_viscous.h: the wall's radius is the sphere's, the sum
    of the radii the sphere's, the wall dry, the effective contact angle
    0.5 theta_i theta_j, the angles given in degrees)."""
    vol_i = 1333.333333 * math.pi * R ** 3 * SLC
    vol_bond = 0.5 * vol_i * (1.0 - math.sqrt(1.0 - R * R / (R * R)))
    scaled = vol_bond / R * 0.001 / R / R
    a = -1.1 * scaled ** -0.53
    th = 0.5 * math.radians(THETA) ** 2
    b = (-0.148 * math.log(scaled) - 0.96) * th * th - 0.0082 * math.log(scaled) + 0.48
    c = 0.0018 * math.log(scaled) + 0.078
    fcap = -math.pi * SIGMA * R * (math.exp(a * gap / R + b) + c)
    reff = 0.5 * R
    fvisc = -6.0 * math.pi * MU * reff * vn / max(SMIN, gap / reff)
    return fcap + fvisc


def easo(s):
    stock, ours = walls(EASO, 1)
    runs = {}
    for tag, wall in (("easo_stock", stock), ("easo_ours", ours)):
        d, n1, n2 = deck(wall, EASO_PROPS, 1e-5, tag, vel=(0.0, 0.0, -0.05),
                         omega=(0.0, 0.0, 0.0))
        rc, out = s.run(tag, d, expect_ok=tag == "easo_ours")
        runs[tag] = L.read_dump(s.path(tag + ".dump"))
        if tag == "easo_stock":
            print("stock LIGGGHTS, easo/capillary/viscous on a plane of type 1: exit %s%s"
                  % (rc, " (segmentation fault)" if rc == 139 or "Segmentation" in out
                     else ""))
    fa, fb = runs["easo_ours"], runs["easo_stock"]
    touching = [k for k, (_, at) in enumerate(fb) if at[1]["z"] < R]
    s.ck.check("easo: the sphere touched the plane", len(touching) > 10,
               "%d frames" % len(touching))
    upto = touching[-1] + 1 if touching else 0
    L.check_trajectories(s, "easo while the sphere touches", fa[:upto], fb[:upto], SCALES,
                         1e-9)
    worst, n, fmax = 0.0, 0, 0.0
    for step, at in fa:
        a = at[1]
        gap = a["z"] - R
        if step <= n1 or gap <= 0.0:
            continue
        up = MASS * G * (1.0 + (PULL - 1.0) * (step - n1) / n2)
        wall_fz = a["fz"] + MASS * G - up
        v_half = a["vz"] - a["fz"] * 1e-5 / (2.0 * MASS)
        want = bridge_force(gap, v_half) if gap < (SMAX - 1.0) * 2 * R else 0.0
        worst = max(worst, abs(wall_fz - want))
        fmax = max(fmax, abs(want))
        n += want != 0.0
    s.ck.check("easo: after the sphere has left, the bridge's force is the closed form "
               "with the wall at rest (1e-9 of the largest)",
               n > 10 and worst <= 1e-9 * fmax,
               "%d frames with a bridge, worst %.3g N of %.3g N" % (n, worst, fmax))
    s.ck.check("easo: wall/rigid runs to the end", fa[-1][0] == n1 + n2,
               "last frame %d" % fa[-1][0])


def body(s):
    thornton_ning(s)
    easo(s)


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
