#!/usr/bin/python3
"""LIGGGHTS's mesh-wall tutorials run with their mesh walls swapped by the migration
table of docs/migration.md, and end as stock LIGGGHTS ends them.

Tutorials (liggghts-doc, Tutorials_public), shortened, each run twice: by stock
`liggghts` as written, and by `liggghts-rigidsurf` with every `fix mesh/surface` +
`fix wall/gran ... mesh` (+ `fix move/mesh`) wall replaced by one `fix wall/rigid ...
surface inline mesh` line:

- meshGran: 400 spheres (R = 5 mm) stream onto a CAD chute (STL in mm: scale 0.001,
  rotated -90 deg about x) and settle.
- movingMeshGran: 1500 spheres (R = 40 mm) settle in a box of primitive walls; a bucket
  (STL: move, scale, two rotations) then becomes a wall, moves linearly into the bed for
  0.75 s, turns about the y axis (period 2 s) for 0.5 s, stops, and the bed settles.
- conveyor: spheres of 15 and 25 mm stream for 0.8 s onto a belt (`surface_vel -4.5 0 0`)
  in a box; the belt carries them off along -x.
- chute_wear: 600 spheres of 1.5 and 2.5 mm run down a chute (`mesh/surface/stress ...
  wear finnie`, here `wear finnie` and `vtk`) for 0.3 s.

Pins: the same number of particles at the end; the bed's centre of mass in the same
place to within one particle diameter; both beds at rest (kinetic energy below 1% of
m g H, H the box height); for the bucket, that it did touch the bed; on the conveyor,
the bed moving along -x at the stock run's mean velocity to within a tenth of the belt's
speed; on the chute, the chute's total wear (the sum over its facets of the VTK's
`wear`) within 10% of the stock run's (the beds' paths part, as any two DEM runs do).
"""
import os
import shutil
import subprocess

import liglib as L

ROOT = "/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public"
REFERENCE = "/usr/bin/liggghts"
BED = ('variable cx equal xcm(all,x)\nvariable cy equal xcm(all,y)\n'
       'variable cz equal xcm(all,z)\nvariable n equal count(all)\nvariable m equal mass(all)\n'
       'variable ke equal ke\nprint "BED ${n} ${cx} ${cy} ${cz} ${ke} ${m}"\n')


def edit(text, pairs):
    for a, b in pairs:
        if a not in text:
            raise SystemExit("tutorial text changed: %r not found" % a)
        text = text.replace(a, b)
    return text


def no_dumps(text):
    return "\n".join(l for l in text.splitlines() if not l.strip().startswith("dump")) + "\n"


def meshgran():
    src = open(os.path.join(ROOT, "meshGran", "in.meshGran")).read()
    ref = edit(no_dumps(src), [("nparticles 10000 particlerate 1000",
                                "nparticles 400 particlerate 1000"),
                               ("run\t\t\t10000 upto", "run\t\t\t8000 upto")]) + BED
    ours = edit(ref, [
        ("fix\t\tcad all mesh/surface file meshes/mesh.stl type 1 scale 0.001 move 0. 0. 0. "
         "rotate axis 1. 0. 0. angle -90. #temperature 100.\n", ""),
        ("fix granwalls all wall/gran model hooke tangential history mesh n_meshes 1 meshes cad",
         "fix granwalls all wall/rigid surface inline mesh meshes/mesh.stl scale 0.001 "
         "place 0 0 0 1 0 0 0 0 -1 sides 2 law hooke type 1")])
    return "meshGran", ref, ours, 0.005, 1.23, None


def movingmeshgran():
    src = open(os.path.join(ROOT, "movingMeshGran", "in.movingMeshGran")).read()
    ref = edit(no_dumps(src), [("run\t\t29999 upto", "run\t\t19999 upto"),
                               ("run\t\t30000 upto", "run\t\t20000 upto"),
                               ("run\t\t\t25000", "run\t\t\t10000\nunfix movecad2\nrun 15000")])
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
         "place 0.5 0 0.1 0.5 0 -0.9 -0.5 0 0.1 sides 2 law hooke type 1 "
         "move linear v_bvx 0 v_bvz rotate origin 0.375 0 0.225 axis 0 1 0 omega v_bom\n"
         "variable nc equal f_bucket_wall[7]\n"
         "fix ncmax all ave/time 100 1 100 v_nc\nvariable ncmax equal f_ncmax\n"
         "thermo_style custom step atoms ke v_nc"),
        ("fix\t\tmovecad1 all move/mesh mesh cad1  linear -0.5 0. -0.3\n", ""),
        ("unfix\t\tmovecad1\n", ""),
        ("fix\t\t\tmovecad2 all move/mesh mesh cad1   rotate origin 0. 0. 0. axis 0. 1. 0. "
         "period 2.\n", ""),
        ("unfix movecad2\n", "")])
    return "movingMeshGran", ref, ours, 0.04, 1.0, "v_nc"


def conveyor():
    src = open(os.path.join(ROOT, "conveyor", "in.conveyor")).read()
    ref = edit(no_dumps(src), [("run\t\t\t140000 upto", "run\t\t\t80000 upto")]) + BED
    ref += 'variable vbx equal vcm(all,x)\nprint "BELT ${vbx}"\n'
    ours = edit(ref, [
        ("fix\t\tcv all mesh/surface file meshes/conveyor.stl type 1 surface_vel -4.5 0. 0.\n",
         ""),
        ("fix\t\tbx all mesh/surface file meshes/box.stl      type 1 \n", ""),
        ("fix wall all wall/gran model hertz tangential history mesh n_meshes 2 meshes bx cv",
         "fix belt all wall/rigid surface inline mesh meshes/conveyor.stl sides 2 law hertz "
         "type 1 surface_vel -4.5 0 0\n"
         "fix box all wall/rigid surface inline mesh meshes/box.stl sides 2 law hertz type 1")])
    return "conveyor", ref, ours, 0.025, None, None


def chute_wear():
    src = open(os.path.join(ROOT, "chute_wear", "in.chute_wear")).read()
    ref = edit(no_dumps(src), [("nparticles 6000", "nparticles 600"),
                               ("run    100000 upto", "run    30000 upto")])
    ref = edit(ref, [("#insert particles",
                      "dump dumpstress all mesh/gran/VTK 30000 post/mesh_*.vtk stress wear cad\n"
                      "#insert particles")]) + BED
    ours = edit(ref, [
        ("fix  cad all mesh/surface/stress file meshes/simple_chute.stl type 1 wear finnie\n",
         ""),
        ("fix  granwalls all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad",
         "fix  granwalls all wall/rigid surface inline mesh meshes/simple_chute.stl sides 2 "
         "law hertz type 1 wear finnie vtk post/mesh_*.vtk 30000"),
        ("dump dumpstress all mesh/gran/VTK 30000 post/mesh_*.vtk stress wear cad\n", "")])
    return "chute_wear", ref, ours, 0.0025, None, None


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
    d = os.path.join(s.dir, name + "_" + tag)
    shutil.copytree(src_dir, d)
    with open(os.path.join(d, "in.test"), "w") as f:
        f.write(deck)
    p = subprocess.run([exe, "-in", "in.test", "-log", "log." + tag], cwd=d,
                       capture_output=True, text=True, errors="replace", timeout=600)
    out = p.stdout + p.stderr
    s.ck.check("%s %s: the run ends without error" % (name, tag), p.returncode == 0,
               "exit %d" % p.returncode, "\n".join(out.splitlines()[-8:]))
    bed = [l.split()[1:] for l in out.splitlines() if l.startswith("BED ")]
    return out, ([float(v) for v in bed[-1]] if bed else None)


def body(s):
    if not s.ck.check("stock tutorials present", os.path.isdir(ROOT), ROOT,
                      "install liggghts-doc (tools/setup-deps does)"):
        return
    for case in (meshgran, movingmeshgran, conveyor, chute_wear):
        name, ref, ours, radius, height, contacts = case()
        src_dir = os.path.join(ROOT, name)
        out_ref, a = run(s, name, "liggghts", REFERENCE, src_dir, ref)
        out, b = run(s, name, "rigidsurf", s.exe, src_dir, ours)
        if not (a and b):
            continue
        s.ck.check(name + ": the same number of particles", a[0] == b[0] and a[0] > 0,
                   "%d vs %d" % (a[0], b[0]))
        dcom = max(abs(x - y) for x, y in zip(a[1:4], b[1:4]))
        s.ck.check(name + ": the bed's centre of mass in the same place (one diameter)",
                   dcom <= 2 * radius, "%.3g m apart (radius %g)" % (dcom, radius))
        for tag, r in (("liggghts", a), ("rigidsurf", b)) if height else ():
            s.ck.check(name + ": %s's bed at rest (KE < 1%% of m g H)" % tag,
                       r[4] < 0.01 * r[5] * 9.81 * height,
                       "KE %.3g J, m g H %.3g J" % (r[4], r[5] * 9.81 * height))
        if name == "chute_wear":
            wa, wb = (total_wear(os.path.join(s.dir, name + "_" + tag, "post",
                                              "mesh_30000.vtk"))
                      for tag in ("liggghts", "rigidsurf"))
            s.ck.check(name + ": the chute wears as stock LIGGGHTS's does (10%)",
                       wa > 0 and abs(wb - wa) <= 0.1 * wa,
                       "total wear %.5g (stock %.5g)" % (wb, wa))
        elif height is None:  # the conveyor: the belt carries the bed along -x
            va, vb = (float([l for l in o.splitlines() if l.startswith("BELT ")][-1].split()[1])
                      for o in (out_ref, out))
            s.ck.check(name + ": the belt carries the bed as stock LIGGGHTS's does",
                       va < 0 and vb < 0 and abs(va - vb) <= 0.1 * 4.5,
                       "mean vx %.4g m/s (stock %.4g m/s, belt -4.5 m/s)" % (vb, va))
        if contacts:
            nc = [float(l.split()[3]) for l in out.splitlines()
                  if len(l.split()) == 4 and l.split()[0].isdigit()]
            s.ck.check(name + ": the moving bucket touched the bed", nc and max(nc) >= 5,
                       "most contacts %s" % (max(nc) if nc else "none"))


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
