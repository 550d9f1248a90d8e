#!/usr/bin/python3
"""Keyword fused: the law's fused kernel against the staged calls, in the fix.

The static, flowing and bouncing decks of bench/liggghts/bench_walls.py (sections 1, 1b
and 1e: a monolayer of spheres pressed on the inside of a REVOLUTION cylinder by a radial
push, at rest, rolling around it, or kicked off it and bouncing back), each run with
`law hertz` as it is (where every sphere of a block holds one contact, the tracker, the
law and the loads run in one pass: on the revolved LINE per run of spheres) and with
`fused no` (every block through the staged calls). The positions, velocities and spins of
every sphere and the wall's per-atom array (peratom yes) at the end are the same, bit for
bit, and so they are when the bouncing bed also rolls around the cylinder with its atoms
sorted every 20 steps, so that spheres change places in the atom arrays while some hold
their contact and others fly (LIGGGHTS's atom sort permutes the wall's per-particle
history through its copy callback), and when that bed mixes two sphere materials (per
type properties: the line path's runs hold one type each); the wall's
global sums agree to rounding (1e-12 relative: the line path adds them up per run of
spheres, the staged calls per block). So they are for the bouncing bed in the
4000-triangle STL cylinder of section 1g, both sides acting and the inward side alone,
where the fused law takes the spheres held on a face's clear zone per run of spheres
(rs_mesh_held_faces) and the rest through the candidate lists. And so they are for the
bouncing bed on the cylinder and in the STL cylinder with LIGGGHTS's own Hertz model
(`law liggghts model hertz tangential history`), which the wall calls per contact on the
line path (rs_law.force_one) and per block in the staged calls.
"""
import subprocess
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "bench", "liggghts"))
import liglib as L  # noqa: E402
import bench_walls as B  # noqa: E402

N = 1500


def deck(s, kind, fused):
    data, height = B.write_bed(s.dir, N, None, "mono_%s.data" % kind)
    bouncing = kind.startswith("bouncing")
    steps = 400 if not bouncing else 600
    variant = {"bouncing_mesh": "ours_mesh", "bouncing_mesh1": "ours_mesh1",
               "bouncing_mesh_liggghts": "ours_mesh"}.get(kind, "ours")
    if variant != "ours" and not os.path.exists(s.path("cyl.stl")):
        subprocess.run([sys.executable, os.path.join(os.path.dirname(B.__file__), "make_stl.py"),
                        s.path("cyl.stl"), repr(B.RC), "-0.002", repr(height + 0.002),
                        "200", "10"], check=True)
    d = B.wall_deck(variant, data, steps, height, flow=kind == "flowing",
                    kick=B.VKICK if bouncing else 0.0)
    if kind == "bouncing_sorted":
        # the bouncing bed rolling around the cylinder too, kicked at speeds that differ
        # from sphere to sphere, its atoms sorted by bins of R every 20 steps: spheres
        # change places in the atom arrays while some hold their contact and others fly
        d = d.replace("atom_modify map array\n",
                      "atom_modify map array sort 20 %r\n" % B.R)
        d = d.replace("set group all vx v_kx vy v_ky\n",
                      "variable hx atom (1.0+0.6*sin(id))*v_kx-%r*y/sqrt(x*x+y*y)\n"
                      "variable hy atom (1.0+0.6*sin(id))*v_ky+%r*x/sqrt(x*x+y*y)\n"
                      "set group all vx v_hx vy v_hy\n" % (B.VFLOW, B.VFLOW))
    if kind == "bouncing_types":
        # the sorted bouncing bed of two sphere materials, types 1 and 3 (Young's modulus
        # 1e7 and 3e7, restitution 0.5 and 0.8 on the wall, friction 0.5 and 0.3), mixed
        # half and half at random: the line path's runs hold one type each and take that
        # type's properties
        d = d.replace("atom_modify map array\n",
                      "atom_modify map array sort 20 %r\n" % B.R)
        with open(data) as f:
            text = f.read()
        with open(data, "w") as f:
            f.write(text.replace("2 atom types", "3 atom types"))
        mats = ("fix m1 all property/global youngsModulus peratomtype 1e7 1e8 3e7\n"
                "fix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3\n"
                "fix m3 all property/global coefficientRestitution peratomtypepair 3 "
                "0.5 0.5 0.6 0.5 0.5 0.8 0.6 0.8 0.7\n"
                "fix m4 all property/global coefficientFriction peratomtypepair 3 "
                "0.5 0.5 0.4 0.5 0.5 0.3 0.4 0.3 0.4\n")
        head, rest = d.split("fix m1 ", 1)
        rest = rest.split("fix m4 ", 1)[1].split("\n", 1)[1]
        d = head + mats + rest
        d = d.replace("set group all vx v_kx vy v_ky\n",
                      "set group all vx v_kx vy v_ky\nset type 1 type/fraction 3 0.5 4711\n"
                      "group t3 type 3\nvariable n3 equal count(t3)\n"
                      "print \"spheres of type 3: ${n3}\"\n")
    law = "hertz"
    if kind.endswith("_liggghts"):
        # LIGGGHTS's own model through law liggghts: the wall hands it each contact of a
        # sphere that holds one on the line path
        law = "liggghts model hertz tangential history"
    fix = "law %s type 2 peratom yes%s\n" % (law, "" if fused else " fused no")
    d = d.replace("law hertz type 2\n", fix)
    tag = "%s_%s" % (kind, "fused" if fused else "staged")
    out = ("thermo_style custom step f_w[1] f_w[2] f_w[7] f_w[8] f_w[11]\n"
           "thermo_modify format float %.17g\n")
    out += L.dump_lines("d", steps, tag + ".dump",
                        L.DUMP_COLS + " f_w[1] f_w[2] f_w[3] f_w[4] f_w[5] f_w[6]")
    return d.replace("run %d\n" % steps, out + "run %d\n" % steps), tag, steps


def body(s):
    for kind in ("static", "flowing", "bouncing", "bouncing_sorted", "bouncing_types",
                 "bouncing_mesh", "bouncing_mesh1", "bouncing_liggghts",
                 "bouncing_mesh_liggghts"):
        texts, outs = [], []
        for fused in (True, False):
            d, tag, steps = deck(s, kind, fused)
            _, out = s.run(tag, d, timeout=600)
            outs.append(out)
            with open(s.path(tag + ".dump")) as f:
                dump = f.read()
            # the wall's sums at the last step, from the thermo line
            wall = [l for l in out.splitlines() if l.split()[:1] == [str(steps)]]
            texts.append((dump, wall[-1] if wall else ""))
        (da, wa), (db, wb) = texts
        rows = [l for l in da.splitlines() if l and l[0].isdigit() and len(l.split()) > 10]
        s.ck.check(kind + ": the dump holds every sphere at the end", len(rows) >= N,
                   "%d rows" % len(rows))
        touching = sum(1 for l in rows if float(l.split()[10]) > 0.0)
        s.ck.check(kind + ": spheres press the wall at the end (rdisp1 > 0)", touching > 0,
                   "%d of %d" % (touching, len(rows)))
        if kind == "bouncing_types":
            n3 = [int(l.split()[-1]) for l in outs[0].splitlines()
                  if l.startswith("spheres of type 3:")]
            s.ck.check(kind + ": both sphere types in the bed",
                       len(n3) == 1 and N // 3 < n3[0] < 2 * N // 3, "type 3: %s" % n3)
        s.ck.check(kind + ": fused and staged give the same spheres, bit for bit", da == db)
        va = [float(v) for v in wa.split()[1:]]
        vb = [float(v) for v in wb.split()[1:]]
        worst = max((abs(a - b) / max(abs(b), 1e-300) for a, b in zip(va, vb)), default=1.0)
        s.ck.check(kind + ": fused and staged give the same wall sums to 1e-12",
                   len(va) == 5 and len(vb) == 5 and va[2] == vb[2] and worst <= 1e-12,
                   "fused %s, staged %s" % (wa.strip(), wb.strip()))


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
