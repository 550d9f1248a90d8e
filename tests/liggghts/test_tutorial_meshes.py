#!/usr/bin/python3
"""LIGGGHTS's mesh-wall tutorials run with their mesh walls swapped by the migration
table of docs/migration.md, and end as stock LIGGGHTS ends them.

Tutorials (liggghts-doc, Tutorials_public), each run twice: by stock `liggghts` as
written, and by `liggghts-rigidsurf` with every `fix mesh/surface` + `fix wall/gran ...
mesh` (+ `fix move/mesh`) wall replaced by one `fix wall/rigid ... surface inline mesh`
line with the default sides (both, as LIGGGHTS's mesh walls). Each runs until both beds
are at rest, or in steady flow, and they are compared there. The environment variable
RS_TUTORIAL names one tutorial to run alone (CTest runs each as a test of its own). Every deck prints its atom
count, kinetic energy and mean x velocity every 1000 steps (`TUT` lines), from which:

- meshGran: 400 spheres (R = 5 mm) stream onto a CAD chute (STL in mm: scale 0.001,
  rotated -90 deg about x) and settle, to step 60000 (the tutorial stops at 40000 with
  10000 spheres; with 400 the bed still moves there, with KE about 2e-3 of m g H, and
  is at rest, below 1e-7 of it, from about step 52000 in both runs).
- movingMeshGran: 1500 spheres (R = 40 mm) settle in a box of primitive walls; a bucket
  (STL: move, scale, two rotations) then becomes a wall, moves linearly into the bed for
  0.75 s, turns about the y axis (period 2 s) for 0.5 s, stops, and the bed settles for
  40000 steps, to step 85000 (the bed comes below 1e-4 of m g H about 20000 steps after
  the bucket stops; with a friction of 0.05 it keeps creeping at about 1e-5 of m g H,
  with short slides, in both runs).
- conveyor: spheres of 15 and 25 mm stream for 0.8 s onto a belt (`surface_vel -4.5 0 0`)
  in a box; the belt carries them along -x in a steady stream while they are fed
  (compared over steps 50000-80000) and then piles them against the box's end, where
  they lie on the sliding belt (compared at step 400000, where KE has fallen from 25 J
  in the stream to below 1e-3 of m g H).
- chute_wear: spheres of 1.5 and 2.5 mm are fed at 0.1 kg/s onto a chute
  (`mesh/surface/stress ... wear finnie`, here `wear finnie` and `vtk`) and run down
  it, as in the tutorial, for 100000 steps; inflow and outflow balance from about step
  75000 (about 830 spheres on the chute), and the two runs are compared over steps
  80000-100000.

Pins: the same number of particles at the end (on the chute: the mean over the steady
window, within 10%); the bed's centre of mass in the same place to within one particle
diameter (not on the chute, whose stream is fed and leaves); beds at rest (KE below 1e-4
of m g H, H the box height, over the last 10000 steps); for the bucket, that it did touch
the bed; on the conveyor, the streaming bed moving along -x at the stock run's mean
velocity to within a tenth of the belt's speed and the piled bed's KE below 1e-3 of
m g H; on the chute, a steady flow in both runs (the count within 5% of its mean over the
window), the mean x velocity within 10% of stock's, and the chute's total wear (the sum
over its facets of the VTK's `wear`) within 10% of the stock run's (the beds' paths
part, as any two DEM runs do). Each run's wall-clock and CPU time is printed.
"""
import os

import liglib as L

ROOT = L.TUTORIALS
REFERENCE = L.STOCK_LIGGGHTS
BED = L.BED
no_dumps = L.no_dumps
window = L.window


def edit(text, pairs):
    for a, b in pairs:
        if a not in text:
            raise SystemExit("tutorial text changed: %r not found" % a)
        text = text.replace(a, b)
    return text


def meshgran():
    src = open(os.path.join(ROOT, "meshGran", "in.meshGran")).read()
    ref = edit(no_dumps(src), [("nparticles 10000 particlerate 1000",
                                "nparticles 400 particlerate 1000"),
                               ("run\t\t\t10000 upto", "run\t\t\t8000 upto"),
                               ("run\t\t\t40000 upto", "run\t\t\t60000 upto")]) + BED
    ours = edit(ref, [
        ("fix\t\tcad all mesh/surface file meshes/mesh.stl type 1 scale 0.001 move 0. 0. 0. "
         "rotate axis 1. 0. 0. angle -90. #temperature 100.\n", ""),
        ("fix granwalls all wall/gran model hooke tangential history mesh n_meshes 1 meshes cad",
         "fix granwalls all wall/rigid surface inline mesh meshes/mesh.stl scale 0.001 "
         "place 0 0 0 1 0 0 0 0 -1 law hooke type 1")])
    return dict(name="meshGran", ref=ref, ours=ours, radius=0.005, height=1.23)


def movingmeshgran():
    src = open(os.path.join(ROOT, "movingMeshGran", "in.movingMeshGran")).read()
    ref = edit(no_dumps(src), [("run\t\t29999 upto", "run\t\t19999 upto"),
                               ("run\t\t30000 upto", "run\t\t20000 upto"),
                               ("run\t\t\t25000", "run\t\t\t10000\nunfix movecad2\nrun 40000")])
    ref += BED
    # The bucket's placement: LIGGGHTS moves (-50, -250, 0), scales by 0.002 and turns
    # 90 deg about y, then about z; that is x = a + 0.002 (X ex + Y ey + Z ez) with
    # ex = (0, 0, -1), ey = (-1, 0, 0), a = 0.002 Rz Ry (-50, -250, 0) = (0.5, 0, 0.1).
    # The moves become rates: -0.5, 0, -0.3 m/s for 15000 steps, then 2 pi / 2 rad/s
    # about y through the origin, which the translation has carried to
    # -(-0.375, 0, -0.225) in the reference configuration.
    ours = edit(ref, [
        ("fix\t\tcad1 all mesh/surface file meshes/bucket.stl type 1  move -50. -250. 0. &\n"
         "\t\tscale 0.002  rotate axis 0. 1. 0. angle 90.  rotate axis 0. 0. 1. angle 90.\n", ""),
        ("fix bucket_wall all wall/gran model hooke tangential history mesh n_meshes 1 meshes cad1",
         "variable bvx equal (step>20000)*(step<=35000)*(-0.5)\n"
         "variable bvz equal (step>20000)*(step<=35000)*(-0.3)\n"
         "variable bom equal (step>35000)*(step<=45000)*2*PI/2.0\n"
         "fix bucket_wall all wall/rigid surface inline mesh meshes/bucket.stl scale 0.002 "
         "place 0.5 0 0.1 0.5 0 -0.9 -0.5 0 0.1 law hooke type 1 "
         "move linear v_bvx 0 v_bvz rotate origin 0.375 0 0.225 axis 0 1 0 omega v_bom\n"
         "variable nc equal f_bucket_wall[7]\n"
         "fix ncmax all ave/time 100 1 100 v_nc\nvariable ncmax equal f_ncmax\n"
         "thermo_style custom step atoms ke v_nc"),
        ("fix\t\tmovecad1 all move/mesh mesh cad1  linear -0.5 0. -0.3\n", ""),
        ("unfix\t\tmovecad1\n", ""),
        ("fix\t\t\tmovecad2 all move/mesh mesh cad1   rotate origin 0. 0. 0. axis 0. 1. 0. "
         "period 2.\n", ""),
        ("unfix movecad2\n", "")])
    return dict(name="movingMeshGran", ref=ref, ours=ours, radius=0.04, height=1.0,
                contacts=True)


def conveyor():
    src = open(os.path.join(ROOT, "conveyor", "in.conveyor")).read()
    ref = edit(no_dumps(src), [("run\t\t\t140000 upto", "run\t\t\t80000 upto")])
    ref += "run 400000 upto\n" + BED
    ours = edit(ref, [
        ("fix\t\tcv all mesh/surface file meshes/conveyor.stl type 1 surface_vel -4.5 0. 0.\n",
         ""),
        ("fix\t\tbx all mesh/surface file meshes/box.stl      type 1 \n", ""),
        ("fix wall all wall/gran model hertz tangential history mesh n_meshes 2 meshes bx cv",
         "fix belt all wall/rigid surface inline mesh meshes/conveyor.stl law hertz "
         "type 1 surface_vel -4.5 0 0\n"
         "fix box all wall/rigid surface inline mesh meshes/box.stl law hertz type 1")])
    return dict(name="conveyor", ref=ref, ours=ours, radius=0.025, height=0.55, rest=1e-3,
                stream=(50000, 80000))


def chute_wear():
    src = open(os.path.join(ROOT, "chute_wear", "in.chute_wear")).read()
    ref = edit(no_dumps(src), [("#insert particles",
                      "dump dumpstress all mesh/gran/VTK 50000 post/mesh_*.vtk stress wear cad\n"
                      "#insert particles")]) + BED
    ours = edit(ref, [
        ("fix  cad all mesh/surface/stress file meshes/simple_chute.stl type 1 wear finnie\n",
         ""),
        ("fix  granwalls all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad",
         "fix  granwalls all wall/rigid surface inline mesh meshes/simple_chute.stl "
         "law hertz type 1 wear finnie vtk post/mesh_*.vtk 50000"),
        ("dump dumpstress all mesh/gran/VTK 50000 post/mesh_*.vtk stress wear cad\n", "")])
    return dict(name="chute_wear", ref=ref, ours=ours, radius=0.0025, stream=(80000, 100000))


def total_wear(path):
    """The sum of the cell array `wear` of a polydata VTK (LIGGGHTS's FIELD array or our
    SCALARS)."""
    toks = open(path).read().split("CELL_DATA", 1)[1].split()
    n = int(toks[0])
    i = toks.index("wear")
    # LIGGGHTS: "wear 1 N double v ...", rigidsurf: "wear double 1 LOOKUP_TABLE default v ..."
    first = i + 4 if toks[i + 1] == "1" else i + 5
    return sum(float(v) for v in toks[first:first + n])


def run(s, name, tag, exe, src_dir, deck):
    return L.run_tutorial(s, name, tag, exe, src_dir, deck)[:3]


def body(s):
    if not s.ck.check("stock tutorials present", os.path.isdir(ROOT), ROOT,
                      "install liggghts-doc (tools/setup-deps does)"):
        return
    # RS_TUTORIAL names one tutorial (CTest runs each as a test of its own); unset, all
    only = os.environ.get("RS_TUTORIAL")
    cases = [case() for case in (meshgran, movingmeshgran, conveyor, chute_wear)]
    if only and not s.ck.check("tutorial %s known" % only,
                               any(c["name"] == only for c in cases)):
        return
    for c in cases:
        name = c["name"]
        if only and name != only:
            continue
        src_dir = os.path.join(ROOT, name)
        out_ref, a, ta = run(s, name, "liggghts", REFERENCE, src_dir, c["ref"])
        out, b, tb = run(s, name, "rigidsurf", s.exe, src_dir, c["ours"])
        if not (a and b and ta and tb):
            continue
        end = max(ta)
        stream = c.get("stream")
        if stream and name == "chute_wear":
            (na, ma), (nb, mb) = (window(t, stream[0], stream[1], 0) for t in (ta, tb))
            for tag, n, m in (("liggghts", na, ma), ("rigidsurf", nb, mb)):
                s.ck.check(name + ": %s's flow steady over steps %d-%d (count within 5%%)"
                           % (tag, stream[0], stream[1]),
                           max(abs(x - m) for x in n) <= 0.05 * m,
                           "%.0f spheres, %d to %d" % (m, min(n), max(n)))
            s.ck.check(name + ": as many spheres on the chute (10%)",
                       abs(mb - ma) <= 0.1 * ma, "%.0f vs %.0f" % (mb, ma))
            va, vb = (window(t, stream[0], stream[1], 2)[1] for t in (ta, tb))
            s.ck.check(name + ": the stream as fast as stock's (10%)",
                       va < 0 and abs(vb - va) <= 0.1 * abs(va),
                       "mean vx %.4g m/s (stock %.4g m/s)" % (vb, va))
            wa, wb = (total_wear(os.path.join(s.dir, name + "_" + tag, "post",
                                              "mesh_%d.vtk" % end))
                      for tag in ("liggghts", "rigidsurf"))
            s.ck.check(name + ": the chute wears as stock LIGGGHTS's does (10%)",
                       wa > 0 and abs(wb - wa) <= 0.1 * wa,
                       "total wear %.5g (stock %.5g)" % (wb, wa))
            continue
        s.ck.check(name + ": the same number of particles", a[0] == b[0] and a[0] > 0,
                   "%d vs %d" % (a[0], b[0]))
        dcom = max(abs(x - y) for x, y in zip(a[1:4], b[1:4]))
        s.ck.check(name + ": the bed's centre of mass in the same place (one diameter)",
                   dcom <= 2 * c["radius"], "%.3g m apart (radius %g)" % (dcom, c["radius"]))
        rest = c.get("rest", 1e-4)
        for tag, r, t in (("liggghts", a, ta), ("rigidsurf", b, tb)):
            ke, _ = window(t, end - 9000, end, 1)
            mgh = r[5] * 9.81 * c["height"]
            s.ck.check(name + ": %s's bed at rest (KE < %g m g H over steps %d-%d)"
                       % (tag, rest, end - 9000, end), max(ke) < rest * mgh,
                       "KE up to %.3g J, m g H %.3g J" % (max(ke), mgh))
        if stream:  # the conveyor: the fed belt carries the bed along -x
            va, vb = (window(t, stream[0], stream[1], 2)[1] for t in (ta, tb))
            s.ck.check(name + ": the belt carries the bed as stock LIGGGHTS's does",
                       va < 0 and vb < 0 and abs(va - vb) <= 0.1 * 4.5,
                       "mean vx %.4g m/s over steps %d-%d (stock %.4g m/s, belt -4.5 m/s)"
                       % (vb, stream[0], stream[1], va))
        if c.get("contacts"):
            nc = [float(l.split()[3]) for l in out.splitlines()
                  if len(l.split()) == 4 and l.split()[0].isdigit()]
            s.ck.check(name + ": the moving bucket touched the bed", nc and max(nc) >= 5,
                       "most contacts %s" % (max(nc) if nc else "none"))


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
