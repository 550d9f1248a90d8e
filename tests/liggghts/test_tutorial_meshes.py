#!/usr/bin/python3
"""LIGGGHTS's mesh-wall tutorials run as rigidsurf-migrate rewrites them, and end as stock
LIGGGHTS ends them.

Tutorials (liggghts-doc, Tutorials_public), each run twice: by stock `liggghts` as
written (shortened or lengthened below), and by `liggghts-rigidsurf` as
`rigidsurf-migrate` rewrites that deck: every `fix mesh/surface` + `fix wall/gran ...
mesh` (+ `fix move/mesh`) wall one `fix wall/rigid ... surface inline mesh` line with the
default sides (both, as LIGGGHTS's mesh walls), the tool's exit status 0. Each runs
until both beds are at rest, or in steady flow, and they are compared there. The environment variable
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
import re
import subprocess

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


def migrate(s, name, text, after=None):
    """text as rigidsurf-migrate rewrites it (the tool run in the tutorial's folder, where
    the deck names its meshes); after: (the start of a wall/rigid line, text to add after
    that command), for what only the migrated run can print."""
    path = s.write(name + ".stock.in", text)
    p = subprocess.run([MIGRATE, path], capture_output=True, text=True, timeout=60,
                       cwd=os.path.join(ROOT, name))
    s.ck.check(name + ": the tool migrates every wall (exit 0)", p.returncode == 0 and not
               re.search(r"^\s*fix\s+\S+\s+\S+\s+wall/gran", p.stdout, re.M),
               p.stderr.strip().splitlines()[-1] if p.stderr.strip() else "", p.stderr)
    out = p.stdout
    if after:
        k = out.index(after[0])
        while out[out.index("\n", k) - 1] == "&":
            k = out.index("\n", k) + 1
        k = out.index("\n", k) + 1
        out = out[:k] + after[1] + out[k:]
    return out


def meshgran(s):
    src = open(os.path.join(ROOT, "meshGran", "in.meshGran")).read()
    ref = edit(no_dumps(src), [("nparticles 10000 particlerate 1000",
                                "nparticles 400 particlerate 1000"),
                               ("run\t\t\t10000 upto", "run\t\t\t8000 upto"),
                               ("run\t\t\t40000 upto", "run\t\t\t60000 upto")]) + BED
    return dict(name="meshGran", ref=ref, ours=migrate(s, "meshGran", ref), radius=0.005,
                height=1.23)


def movingmeshgran(s):
    src = open(os.path.join(ROOT, "movingMeshGran", "in.movingMeshGran")).read()
    ref = edit(no_dumps(src), [("run\t\t29999 upto", "run\t\t19999 upto"),
                               ("run\t\t30000 upto", "run\t\t20000 upto"),
                               ("run\t\t\t25000", "run\t\t\t10000\nunfix movecad2\nrun 40000")])
    ref += BED
    # the bucket's contacts, which only wall/rigid's output gives (f_ID[7])
    ours = migrate(s, "movingMeshGran", ref, (
        "fix cad1 all wall/rigid",
        "variable nc equal f_cad1[7]\nthermo_style custom step atoms ke v_nc\n"))
    return dict(name="movingMeshGran", ref=ref, ours=ours, radius=0.04, height=1.0,
                contacts=True)


def conveyor(s):
    src = open(os.path.join(ROOT, "conveyor", "in.conveyor")).read()
    ref = edit(no_dumps(src), [("run\t\t\t140000 upto", "run\t\t\t80000 upto")])
    ref += "run 400000 upto\n" + BED
    return dict(name="conveyor", ref=ref, ours=migrate(s, "conveyor", ref), radius=0.025,
                height=0.55, rest=1e-3, stream=(50000, 80000))


def chute_wear(s):
    src = open(os.path.join(ROOT, "chute_wear", "in.chute_wear")).read()
    ref = edit(no_dumps(src), [("#insert particles",
                      "dump dumpstress all mesh/gran/VTK 50000 post/mesh_*.vtk stress wear cad\n"
                      "#insert particles")]) + BED
    # the dump of the chute's stress and wear: the wall's vtk, the same files
    return dict(name="chute_wear", ref=ref, ours=migrate(s, "chute_wear", ref),
                radius=0.0025, stream=(80000, 100000))


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
    cases = [case(s) for case in (meshgran, movingmeshgran, conveyor, chute_wear)
             if not only or case.__name__ == only.lower()]
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
    SES = L.Session(__doc__)
    MIGRATE = os.environ.get("RS_MIGRATE") or os.path.join(os.path.dirname(SES.exe), "..",
                                                           "rigidsurf-migrate")
    L.main_guard(SES, body)
