#!/usr/bin/python3
"""Bad fix wall/rigid lines in LAMMPS end the run with one clear ERROR.

Each line runs in a one-sphere deck of lmp-rigidsurf; the run must end with exit status 1
(no signal, no abort, no uncaught exception) and one ERROR message that names the fix
(`Fix wall/rigid w`) and what was wrong: the keyword and what it expects, or the file.
Errors that LAMMPS's own fix wall/gran parser finds in the model words of law lammps keep
LAMMPS's message; LAMMPS then names the command on its `Last command:` line. Two of the
lines also run on 2 ranks (error->all on every rank: still one message). Particles the fix
does not take: atom_style body of a style other than rounded/polyhedron (nparticle), an
ellipsoid style whose particle was given no shape, law lammps (LAMMPS's sphere-wall
models) on ellipsoids, and an ellipsoid that appears during a run that began without one.
Bad rounded polyhedra (non-convex, law lammps): tests/lammps/test_bodies.py.
"""
import lmplib as M

BASE = "fix w all wall/rigid surface plane.inp"
HOOKE = " law lammps hooke/history 2e5 NULL 50 NULL 0.5 1"
MATS = (" youngsModulus 5e7 5e7 poissonsRatio 0.3 0.3 coefficientRestitution 0.7 0.7 "
        "coefficientFriction 0.5 0.5")
CASES = [
    ("unknown keyword", BASE + " law hertz" + MATS + " bogus 1",
     ["Fix wall/rigid w", "unknown keyword 'bogus'"]),
    ("missing mesh file", "fix w all wall/rigid surface inline mesh nothere.stl" + HOOKE,
     ["Fix wall/rigid w", "nothere.stl"]),
    ("unknown law", BASE + " law lamps", ["unknown law 'lamps'", "lammps"]),
    ("unknown LAMMPS model", BASE + " law lammps hertzian 1 2 3", ["law lammps expects",
                                                                    "got 'hertzian'"]),
    ("a LAMMPS wall in the model words", BASE + HOOKE + " zplane 0 NULL",
     ["'zplane' belongs to its wall"]),
    ("a word after the LAMMPS model", BASE + HOOKE + " bogus 1",
     ["law lammps hooke/history expects", "'bogus' is neither that nor a keyword"]),
    ("LAMMPS model short of numbers", BASE + " law lammps hooke 2e5 NULL 50",
     ["law lammps hooke expects kn kt gamma_n gamma_t xmu dampflag", "got 3"]),
    ("reff without a mode", BASE + " law lammps reff rounded hertz/history 2e8 NULL 50 NULL 0.5 1",
     ["'reff' expects exact, region or flat", "'rounded'"]),
    ("material with one value for two types", BASE + " law hertz youngsModulus 5e7",
     ["keyword 'youngsModulus' expects 2 numbers, one per atom type"]),
    ("material not a number", BASE + " law hertz youngsModulus 5e7 abc",
     ["keyword 'youngsModulus' expects 2 numbers", "'abc'"]),
    ("law hertz without its materials", BASE + " law hertz youngsModulus 5e7 5e7",
     ["law hertz reads the material property poissonsRatio",
      "'poissonsRatio V1 .. V2'"]),
    ("conduction", BASE + " law hertz" + MATS + " temperature 300 conduction liggghts",
     ["'conduction liggghts'", "LAMMPS keeps no per-atom temperature"]),
    ("predef without its vector", BASE + " law linear_softening props 1e5 predef nothere",
     ["keyword 'predef'", "d_nothere"]),
    ("props with law lammps", BASE + HOOKE + " props 1 2", ["law lammps", "'props' does not apply"]),
]


def deck(line, style="sphere"):
    d = M.header((-0.1, 0.1, -0.1, 0.1, -0.05, 0.2), 1e-5).replace(
        "atom_style sphere", "atom_style " + style)
    if style == "sphere":
        d += M.sphere(1, (0, 0, 0.02), 0.005, 2500.0)
    else:
        d += "create_atoms 1 single 0 0 0.02 units box\nmass * 1.0\n"
    d += line + "\nfix integr all nve%s\nrun 10\n" % ("/sphere" if style == "sphere" else "")
    return d


def body(s):
    s.write("plane.inp", M.L.plane_z(0.0))
    for k, (name, line, want) in enumerate(CASES):
        for np in ((1, 2) if k < 2 else (1,)):
            rc, out = s.run("bad%d_%d" % (k, np), deck(line), np=np, expect_ok=False)
            M.L.check_rejected(s.ck, "%s (%d rank%s)" % (name, np, "s" if np > 1 else ""),
                               line, want, rc, out)
    # LAMMPS's own parser of the model words: its message, and the command named
    line = BASE + " law lammps granular hertz/material 1e7 0.3 0.3 tangential sticky 1 2"
    rc, out = s.run("lammps_parser", deck(line), expect_ok=False)
    M.L.check_rejected(s.ck, "LAMMPS's parser on a granular model", line,
                       ["tangential model not recognized"], rc, out)
    s.ck.check("LAMMPS names the command", "Last command: " + line in out)
    # atom_style atomic: no radius, spin or torque
    for name, line in (("law lammps", BASE + HOOKE), ("law hertz", BASE + " law hertz" + MATS)):
        rc, out = s.run("atomic_" + name.split()[1], deck(line, "atomic"), expect_ok=False)
        M.L.check_rejected(s.ck, name + " in atom_style atomic", line,
                           ["Fix wall/rigid w", "atom_style sphere"], rc, out)
    particles(s)


def particle_deck(style, atoms, line, integrator):
    d = M.header((-0.1, 0.1, -0.1, 0.1, -0.05, 0.2), 1e-5).replace(
        "atom_style sphere", "atom_style " + style)
    return d + atoms + line + "\nfix integr all %s\nrun 10\n" % integrator


def particles(s):
    hertz = BASE + " law hertz" + MATS
    one = "create_atoms 1 single 0 0 0.02 units box\n"
    cases = [
        ("atom_style body", "body nparticle 1 4", one + "set atom 1 mass 1.0\n", hertz,
         "nve", ["Fix wall/rigid w", "atom_style body", "rounded/polyhedron bodies only",
                 "not nparticle"]),
        ("an ellipsoid style without a shape", "ellipsoid", one + "set atom 1 mass 1.0\n",
         hertz, "nve", ["Fix wall/rigid w", "particle 1 of group all",
                        "neither a body, an ellipsoid nor a sphere", "set ... shape"]),
        ("law lammps on ellipsoids", "hybrid sphere ellipsoid",
         M.ellipsoid(1, (0, 0, 0.02), (0.004, 0.005, 0.006), 2500.0, hybrid=True),
         BASE + HOOKE,
         "nve/asphere", ["Fix wall/rigid w", "law lammps", "ellipsoids and bodies take rigidsurf's laws"]),
    ]
    for name, style, atoms, line, integrator, want in cases:
        for np in (1, 2):
            rc, out = s.run("particles_%s_%d" % (name.split()[-1], np),
                            particle_deck(style, atoms, line, integrator), np=np,
                            expect_ok=False)
            M.L.check_rejected(s.ck, "%s (%d rank%s)" % (name, np, "s" if np > 1 else ""),
                               line, want, rc, out)
    # a sphere given a shape between the parts of a run (pre no: no init between them) is
    # an ellipsoid the run did not begin with; found on its rank (error->one, MPI_Abort)
    atoms = "create_atoms 1 single 0 0 0.02 units box\nset atom 1 diameter 0.01 density 2500\n"
    deck = particle_deck("hybrid sphere ellipsoid", atoms, hertz, "nve/sphere").replace(
        "run 10", 'run 20 pre no every 10 "set atom 1 shape 0.01 0.01 0.01"')
    rc, out = s.run("particles_midrun", deck, expect_ok=False)
    errs = M.L.error_lines(out)
    s.ck.check("an ellipsoid appearing during a run: one error naming the fix and the particle",
               rc == 1 and len(set(errs)) == 1 and "Segmentation" not in out
               and all(w in errs[0] for w in ("Fix wall/rigid w", "particle 1 of group all",
                                              "became a body during a run")),
               errs[0] if errs else "exit %s, no error" % rc)


if __name__ == "__main__":
    M.L.main_guard(M.L.Session(__doc__, extra=[M.STOCK]), body)
