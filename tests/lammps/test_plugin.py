#!/usr/bin/python3
"""wallrigidplugin.so, loaded as LAMMPS's `plugin load` loads a plugin, runs a deck as
lmp-rigidsurf does.

plugin_host (plugin_host.cpp) is Debian's LAMMPS with the loader of a LAMMPS built with
PLUGIN: it opens the plugin with RTLD_NOW | RTLD_GLOBAL and calls its lammpsplugin_init,
which registers wall/rigid and wall/rigid/force for the LAMMPS version the plugin was
built for (29 Sep 2021). The deck: spheres that touch only the walls falling in a drum
that turns (law user: a C law in a module that calls back into rigidsurf,
rs_law_find("hertz"), so the plugin must export rigidsurf's functions) onto an STL baffle
inside it (law lammps hertz/history), with store_force and peratom. Every dumped value
(positions, velocities, spins, forces, torques, the stored force, the per-atom array) at
every 50 steps equals lmp-rigidsurf's bit for bit, and so does the wall's global vector.
A second deck drops ellipsoids (atom_style ellipsoid, fix nve/asphere) of two shapes into
the turning drum (law hooke with friction): the plugin takes LAMMPS's ellipsoids as
lmp-rigidsurf does, every dumped value bit for bit.
"""
import math
import os
import subprocess

import lmplib as M

R, RHO, DT, STEPS, ESTEPS = 0.002, 2500.0, 1.0e-5, 8000, 8000
HERTZ = "props 5e7 0.3 5e7 0.3 0.3 0.5 0"


def deck(tag):
    d = M.header((-0.055, 0.055, -0.055, 0.055, -0.012, 0.012), DT)
    k = 0
    for i in range(6):
        for j in range(3):
            k += 1
            d += M.sphere(k, (-0.04 + 0.016 * i, -0.014 + 0.005 * j, -0.006 + 0.006 * j), R, RHO,
                          (0.1 * math.sin(k), 0, 0), (0, 0, 10.0 * math.cos(k)))
    d += "fix grav all gravity 9.81 vector 0 -1 0\n"
    d += ("fix drum all wall/rigid surface drum.inp law user %s hertz_all statev 2 %s "
          "peratom yes rotate origin 0 0 0 axis 0 0 1 omega 3\n" % (HERTZ_LIB, HERTZ))
    d += ("fix baffle all wall/rigid surface inline mesh baffle.stl law lammps hertz/history "
          "2e8 NULL 2e4 NULL 0.5 1 store_force yes\n")
    d += "fix integr all nve/sphere\n"
    cols = M.COLS + " f_drum[1] f_drum[4] f_force_baffle[1] f_force_baffle[2]"
    d += M.dump_lines("d", 50, tag + ".dump", cols=cols)
    d += "variable fx equal f_drum[1]\nvariable fy equal f_drum[2]\nvariable mz equal f_drum[6]\n"
    d += "variable bx equal f_baffle[1]\nvariable by equal f_baffle[2]\n"
    d += ('fix pr all print 50 "${fx} ${fy} ${mz} ${bx} ${by}" screen no file %s.tot\n' % tag)
    d += "run %d\n" % STEPS
    return d


HERTZ_LIB = "HERTZ_LIB"


def ellipsoids(tag):
    d = M.ellipsoid_header((-0.055, 0.055, -0.055, 0.055, -0.012, 0.012), DT)
    for k in range(6):
        half = (0.002, 0.003, 0.005) if k % 2 else (0.003, 0.003, 0.004)
        d += M.ellipsoid(k + 1, (-0.02 + 0.008 * k, -0.035, 0.0), half, RHO,
                         (math.cos(k), math.sin(k), 0.5), 15.0 * k, (0.1 * math.sin(k), 0, 0))
    d += "fix grav all gravity 9.81 vector 0 -1 0\n"
    d += ("fix drum all wall/rigid surface drum.inp law hooke props 1e4 1e4 0.3 0.3 0.5 "
          "rotate origin 0 0 0 axis 0 0 1 omega 3\n")
    d += "fix integr all nve/asphere\n"
    d += M.dump_lines("d", 50, tag + ".dump", cols=M.ECOLS)
    d += "run %d\n" % ESTEPS
    return d


def host_run(s, tag, deck_text):
    """The deck run by plugin_host with the plugin loaded: (exit status, output)."""
    inp = s.write(tag + ".in", deck_text)
    env = dict(os.environ)
    env.update(M.L.MPI_ENV)
    p = subprocess.run([s.args.host, s.args.plugin, "-in", inp, "-log", tag + ".log",
                        "-echo", "none"], cwd=s.dir, capture_output=True, text=True, env=env)
    return p.returncode, p.stdout + p.stderr


def body(s):
    global HERTZ_LIB
    HERTZ_LIB = s.args.hertz_all
    s.write("drum.inp", M.L.drum(0.05, -1.0, 1.0))
    h = 0.03
    s.write("baffle.stl", M.L.stl_text([((-h, -0.02, -h), (h, -0.02, -h), (h, -0.02, h)),
                                        ((-h, -0.02, -h), (h, -0.02, h), (-h, -0.02, h))]))
    s.run("rigid", deck("rigid"))
    rc, out = host_run(s, "host", deck("host"))
    s.ck.check("the plugin's run ends without error", rc == 0,
               why="\n".join(out.splitlines()[-8:]))
    s.ck.check("lammpsplugin_init registers wall/rigid and wall/rigid/force for 29 Sep 2021",
               "fix style wall/rigid from a plugin for LAMMPS 29 Sep 2021" in out
               and "fix style wall/rigid/force from a plugin" in out)
    fa, fb = M.read_dump(s.path("rigid.dump")), M.read_dump(s.path("host.dump"))
    s.ck.check("the spheres hit the drum and the baffle",
               sum(a["f_drum[1]"] > 0 for _, f in fa for a in f.values()) >= 3
               and sum(a["f_force_baffle[2]"] > 0 for _, f in fa for a in f.values()) >= 3)
    diff = M.exact_frames(fa, fb)
    s.ck.check("the plugin's run = lmp-rigidsurf's, every dumped value bit for bit",
               diff is None and len(fa) == STEPS // 50 + 1, "first difference: %s" % (diff,))
    ta, tb = M.read_table(s.path("rigid.tot")), M.read_table(s.path("host.tot"))
    s.ck.check("the walls' global vectors, bit for bit", ta == tb and len(ta) > STEPS // 50)

    s.run("ell_rigid", ellipsoids("ell_rigid"))
    rc, out = host_run(s, "ell_host", ellipsoids("ell_host"))
    s.ck.check("the plugin's run of ellipsoids ends without error", rc == 0,
               why="\n".join(out.splitlines()[-8:]))
    fa, fb = M.read_dump(s.path("ell_rigid.dump")), M.read_dump(s.path("ell_host.dump"))
    hit = sum(1 for i in fa[-1][1] if fa[-1][1][i]["y"] < -0.04)
    diff = M.exact_frames(fa, fb)
    s.ck.check("ellipsoids: the plugin's run = lmp-rigidsurf's, bit for bit",
               diff is None and len(fa) == ESTEPS // 50 + 1 and hit >= 3,
               "%d on the drum's floor; first difference: %s" % (hit, diff))


if __name__ == "__main__":
    M.L.main_guard(M.L.Session(__doc__, extra=[M.STOCK, ("--host", "plugin_host"),
                                               ("--plugin", "wallrigidplugin.so"),
                                               ("--hertz-all", "hertz_all law module")]), body)
