#!/usr/bin/python3
"""fix wall/rigid's servo moves its wall as LIGGGHTS's mesh/surface/stress/servo does.

The reference is LIGGGHTS itself, in the same executable: the same STL plate, once as
`fix mesh/surface/stress/servo` with `fix wall/gran ... mesh`, once as `fix wall/rigid
surface inline mesh ... law liggghts ... servo ...` with the same servo words.

- A single sphere resting on a floor is pressed by the plate. With a proportional
  controller the trajectory equals LIGGGHTS's to 1e-9 (the plate's rate is the same
  function of the same force; only rounding differs), and the force on the plate ends at
  the target (a closed form: the controller's fixed point is pv = target).
- With the derivative and integral terms the controller divides force differences by
  dt, which amplifies rounding: 1e-6.
- A bed of about 130 spheres compressed by the plate: the plate's height over time
  agrees with LIGGGHTS's within 1 % of the plate's travel; its force, averaged over
  1000 steps, within 1 % of the target while the plate goes down to 90 % of the target
  and over the last 5000 steps. In between the bed rearranges under the plate, and the
  rounding differences of the mesh's distances (1e-16) have grown in the bed as in any
  granular packing: single samples differ by up to 7 % there, the heights do not. The
  gain keeps the loop stable: a step moves the plate by dt vel_max kp |error| / |target|,
  which changes the force by k dz with k, the compressed bed's stiffness, about 2e6 N/m;
  the loop gain k dt vel_max kp / |target| is 0.6 for kp 0.5 (above 2, as for kp 2, the
  plate chatters between two heights every step in LIGGGHTS and in rigidsurf).
- The bed reaches the target force (within 1 % at the end of the run), with the STL
  plate and with an analytic plate (a CYLINDER profile).
- A run stopped and restarted from a restart file continues the controller: the plate's
  force and the sphere equal those of the run without the stop (to 1e-9).
- Bad servo words stop the run with one ERROR naming the problem.
"""
import liglib as L

R, RHO, DT = 0.005, 2500.0, 1.0e-5
H = 2 * R + 0.002
BOX = (-0.1, 0.1, -0.1, 0.1, -0.05, 0.2)
SCALES = {"x": R, "y": R, "z": R, "vx": 1.0, "vy": 1.0, "vz": 1.0,
          "omegax": 1.0 / R, "omegay": 1.0 / R, "omegaz": 1.0 / R}
FLOOR = "fix floor all wall/gran model hertz tangential history primitive type 2 zplane 0.0\n"
MODEL = "model hertz tangential history"


def plate(s, half, z, name="plate.stl"):
    tris = [((-half, -half, z), (half, -half, z), (half, half, z)),
            ((-half, -half, z), (half, half, z), (-half, half, z))]
    s.write(name, L.stl_text(tris, "plate"))


def walls(kind, servo, z):
    """The plate (with its servo) and the floor; variables pf (force on the plate along
    z) and, for LIGGGHTS's, pz (its centre's height)."""
    if kind == "gran":
        w = ("fix plate all mesh/surface/stress/servo file plate.stl type 2 %s\n"
             "fix wp all wall/gran %s mesh n_meshes 1 meshes plate\n"
             "variable pf equal f_plate[3]\nvariable pz equal f_plate[9]\n" % (servo, MODEL))
    elif kind == "rigid":
        w = ("fix wp all wall/rigid surface inline mesh plate.stl law liggghts %s type 2 "
             "servo %s\nvariable pf equal f_wp[3]\nvariable pz equal %r+f_wp[17]\n"
             % (MODEL, servo, z))
    else:  # an analytic plane z = z0 facing down, the CYLINDER of docs/migration.md
        w = ("fix wp all wall/rigid surface inline cylinder a 0 0 %r b 1 0 %r c 0 1 %r "
             "profile START -1 0 LINE 1 0 end law liggghts %s type 2 servo %s\n"
             "variable pf equal f_wp[3]\nvariable pz equal %r+f_wp[17]\n"
             % (z, z, z, MODEL, servo, z))
    return w + FLOOR


def deck(s, kind, servo, atoms, steps, tag, z=H, extra=""):
    d = L.header(BOX, DT, ntypes=2)
    d += atoms
    d += "fix grav all gravity 9.81 vector 0 0 -1\n"
    d += walls(kind, servo, z)
    d += "fix integr all nve/sphere\n"
    d += L.dump_lines("d", 5, tag + ".dump")
    d += 'fix pr all print 100 "PLATE $(step) ${pf} ${pz}" screen no file %s.plate\n' % tag
    d += extra
    d += "run %d\n" % steps
    return d


def plate_series(s, tag, col=2):
    """{step: the plate's force (col 2) or height (col 3)}."""
    out = {}
    for line in open(s.path(tag + ".plate")):
        w = line.split()
        if len(w) == 4 and w[0] == "PLATE":
            out[int(w[1])] = float(w[col])
    return out


def compare(s, name, ours, ref, tol):
    L.check_trajectories(s, name, L.read_dump(s.path(ours + ".dump")),
                         L.read_dump(s.path(ref + ".dump")), SCALES, tol)


def single(s):
    one = L.sphere(1, (0, 0, R), R, RHO)
    plate(s, 0.02, H)
    target = 0.5
    for name, gains, tol in (("P", "kp 5", 1e-9), ("PID", "kp 5 ki 0.5 kd 0.001", 1e-6)):
        servo = ("com 0 0 %r ctrlPV force axis 0 0 1 target_val %r vel_max 0.05 %s"
                 % (H, -target, gains))
        for kind in ("gran", "rigid"):
            s.run("one_%s_%s" % (name, kind),
                  deck(s, kind, servo, one, 20000, "one_%s_%s" % (name, kind)))
        ref = plate_series(s, "one_%s_gran" % name)
        s.ck.check("single %s: LIGGGHTS's plate pressed the sphere" % name,
                   max(ref.values()) > 0.01, "largest force %.4g N" % max(ref.values()))
        compare(s, "single sphere, " + name, "one_%s_rigid" % name, "one_%s_gran" % name,
                tol)
        ours = plate_series(s, "one_%s_rigid" % name)
        if name == "P":
            end = ours[max(ours)]
            s.ck.check("single P: the force on the plate ends at the target",
                       abs(end - target) <= 1e-6 * target, "%.9g N, target %g" % (end, target))


def bed_atoms(n_side=6, layers=4):
    out, k = "", 0
    for lz in range(layers):
        for ix in range(n_side):
            for iy in range(n_side - (lz % 2)):
                k += 1
                x = (ix - (n_side - 1) / 2) * 2.05 * R + (lz % 2) * 1.0 * R
                y = (iy - (n_side - 1) / 2) * 2.05 * R + (lz % 2) * 1.0 * R
                out += L.sphere(k, (x, y, R + lz * 1.9 * R + 1e-4 * (k % 7)), R, RHO)
    return out, k


def bed(s):
    atoms, n = bed_atoms()
    z0 = 6.4 * R
    plate(s, 0.05, z0)
    target = 2.0
    servo = ("com 0 0 %r ctrlPV force axis 0 0 1 target_val %r vel_max 0.1 kp 0.5"
             % (z0, -target))
    # a box keeps the bed under the plate
    side = ("fix sx all wall/gran %s primitive type 2 xplane -0.04\n"
            "fix sx2 all wall/gran %s primitive type 2 xplane 0.04\n"
            "fix sy all wall/gran %s primitive type 2 yplane -0.04\n"
            "fix sy2 all wall/gran %s primitive type 2 yplane 0.04\n" % ((MODEL,) * 4))
    runs = {}
    for kind in ("gran", "rigid", "plane"):
        tag = "bed_" + kind
        s.run(tag, deck(s, kind, servo, atoms + side, 40000, tag, z=z0), timeout=600)
        runs[kind] = plate_series(s, tag)
    ref, ours, plane = runs["gran"], runs["rigid"], runs["plane"]
    s.ck.check("bed: LIGGGHTS's plate pressed the bed", max(ref.values()) > 0.5 * target,
               "largest force %.4g N" % max(ref.values()))
    zr, zo = plate_series(s, "bed_gran", 3), plate_series(s, "bed_rigid", 3)
    steps = sorted(set(zr) & set(zo))
    travel = z0 - min(zr.values())
    worst = max(abs(zr[t] - zo[t]) for t in steps)
    s.ck.check("bed: the plate's height follows LIGGGHTS's within 1 % of its travel",
               len(steps) > 100 and worst <= 0.01 * travel,
               "worst %.3g m, travel %.3g m" % (worst, travel))
    win = 10  # samples of 100 steps
    reach = next((t for t in steps if ref[t] >= 0.9 * target), steps[-1])
    early = [t for t in steps if t <= reach]
    means = lambda ser, ts: [sum(ser[t] for t in ts[i:i + win]) / win
                             for i in range(0, len(ts) - win + 1, win)]
    mr, mo = means(ref, early), means(ours, early)
    worst = max(abs(a - b) for a, b in zip(mr, mo))
    s.ck.check("bed: the plate's force over 1000 steps follows LIGGGHTS's within 1 %% of "
               "the target up to 90 %% of the target (step %d)" % reach,
               len(mr) > 5 and worst <= 0.01 * target,
               "worst %.4g N over %d windows" % (worst, len(mr)))
    last = steps[-50:]
    a, b = (sum(ser[t] for t in last) / len(last) for ser in (ref, ours))
    s.ck.check("bed: the last 5000 steps' force equals LIGGGHTS's within 1 % of the target",
               abs(a - b) <= 0.01 * target, "%.5g vs %.5g N" % (b, a))
    fa = L.read_dump(s.path("bed_rigid.dump"))
    fb = L.read_dump(s.path("bed_gran.dump"))
    top = lambda fr: max(a["z"] for a in fr[-1][1].values())
    s.ck.check("bed: the compressed bed's top equals LIGGGHTS's within a tenth of R",
               abs(top(fa) - top(fb)) <= 0.1 * R,
               "%.6g vs %.6g m" % (top(fa), top(fb)))
    for nm, ser in (("STL plate", ours), ("analytic plate", plane)):
        end = ser[max(ser)]
        s.ck.check("bed, %s: the force reaches the target within 1 %%" % nm,
                   abs(end - target) <= 0.01 * target, "%.6g N, target %g" % (end, target))


def restart(s):
    one = L.sphere(1, (0, 0, R), R, RHO)
    plate(s, 0.02, H)
    servo = "com 0 0 %r ctrlPV force axis 0 0 1 target_val -0.5 vel_max 0.05 kp 5 ki 0.5" % H
    s.run("rst_whole", deck(s, "rigid", servo, one, 12000, "rst_whole"))
    first = deck(s, "rigid", servo, one, 6000, "rst_a").replace(
        "run 6000\n", "run 6000\nwrite_restart rst.restart\n")
    s.run("rst_a", first)
    second = ("atom_style granular\natom_modify map array\nboundary f f f\nnewton off\n"
              "communicate single vel yes\nunits si\nread_restart rst.restart\n"
              "neighbor 0.002 bin\nneigh_modify delay 0\n"
              + L.header(BOX, DT, ntypes=2).split("create_box 2 box\n", 1)[1]
              .split("neighbor 0.002 bin\nneigh_modify delay 0\n", 1)[1]
              + "fix grav all gravity 9.81 vector 0 0 -1\n" + walls("rigid", servo, H)
              + "fix integr all nve/sphere\n" + L.dump_lines("d", 5, "rst_b.dump")
              + 'fix pr all print 100 "PLATE $(step) ${pf} ${pz}" screen no file rst_b.plate\n'
              + "run 6000\n")
    s.run("rst_b", second)
    whole = plate_series(s, "rst_whole")
    b = plate_series(s, "rst_b")
    common = [t for t in b if t in whole and t > 6000]
    worst = max(abs(whole[t] - b[t]) for t in common) if common else float("inf")
    s.ck.check("restart: the controller continues (plate force as without the stop)",
               len(common) > 10 and worst <= 1e-9 * 0.5, "worst %.3g N" % worst)


def bad_input(s):
    plate(s, 0.02, H)
    base = ("fix wp all wall/rigid surface inline mesh plate.stl law liggghts %s type 2 "
            % MODEL)
    cases = [
        ("servo without target", base + "servo com 0 0 0 ctrlPV force axis 0 0 1 vel_max 1",
         ["servo", "target_val"]),
        ("servo unknown word", base + "servo com 0 0 0 ctrlPV force axis 0 0 1 target_val 1 "
         "vel_max 1 speed 3", ["unknown word 'speed'"]),
        ("servo and move", base + "move linear 0 0 1 servo com 0 0 0 ctrlPV force axis 0 0 1 "
         "target_val 1 vel_max 1", ["servo", "move"]),
        ("servo zero axis", base + "servo com 0 0 0 ctrlPV force axis 0 0 0 target_val 1 "
         "vel_max 1", ["axis"]),
        ("servo vel_max too large", base + "servo com 0 0 0 ctrlPV force axis 0 0 1 "
         "target_val 1 vel_max 1000", ["vel_max", "skin"]),
        ("servo zero gains", base + "servo com 0 0 0 ctrlPV force axis 0 0 1 target_val 1 "
         "vel_max 1 kp 0", ["kp, ki and kd"]),
    ]
    for name, line, want in cases:
        rc, out = s.run("bad_" + name.replace(" ", "_"), L.one_sphere_deck(line),
                        expect_ok=False)
        L.check_rejected(s.ck, name, line, want, rc, out)


def body(s):
    single(s)
    restart(s)
    bad_input(s)
    bed(s)


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
