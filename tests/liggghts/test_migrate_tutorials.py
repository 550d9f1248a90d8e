#!/usr/bin/python3
"""Every Tutorials_public deck with a `fix wall/gran`, run by stock LIGGGHTS as written
and by liggghts-rigidsurf as rigidsurf-migrate rewrites it, and compared.

Each deck is first shortened or lengthened (DECKS, STEPS: the reason), its dumps taken
out and a monitor added (liglib.MONITOR: count, KE, mean vx every 1000 steps); that deck
is what stock LIGGGHTS runs and what the tool migrates. Two comparisons:
- DECKS, at the end, where both beds are at rest (KE below REST of m g H over the last
  5000 steps): the same number of particles, the bed's centre of mass within a tenth of
  a particle diameter of stock's, at rest in both runs;
- STEPS, at matching steps (every 1000 of a shortened run, with the bed's centre of mass
  every 500) against stock's own rounding: stock runs the deck a second time with its
  time step one unit of the last place larger, and at every step the migrated run's
  count, KE, mean vx and centre of mass must be as close to stock's as that second run
  is, within two decades (the largest difference over the run, at least 1e-12 of the
  value): a difference of the walls beyond rounding stands out by many decades there,
  before the bed's chaos has grown the rounding.
Decks that stock Debian LIGGGHTS cannot run or that need other couplings are named in
EXCLUDED with the reason; the tool is still run on each and must translate its walls
(exit 0), keep them (exit 3) or refuse the deck (exit 1) as the table says. Decks whose
walls the tool keeps (KEPT) have nothing to compare; their report lines are checked.

The table in docs/migration.md (between the `migrate-table` markers) must equal the one
this test prints from its own results' pins (the rows are the decks, what was migrated
and what was compared), and the deck shown there with the tool's output must equal the
tool's output. RS_MIGRATE_DECKS (comma-separated names) runs only those decks (and checks
only their rows of the doc's table); RS_MIGRATE_PART runs one of PARTS, as CTest does.
"""
import os
import re
import shutil
import subprocess

import liglib as L

HERE = os.path.dirname(os.path.abspath(__file__))
SRC = os.path.normpath(os.path.join(HERE, "..", ".."))
DOC = os.path.join(SRC, "docs", "migration.md")
REST = 1e-4

# name: (folder, deck, particle radius, bed height H for m g H, pins, shortening as
# (stock text, replacement) pairs, why; a pair (None, text) appends text to the deck).
# pins: "rest" or ("stream", first, last step).
DECKS = {
    "newModels": ("contactModels", "in.newModels", 0.0025, 0.15, "rest",
                  [("particles_in_region 1800", "particles_in_region 600"),
                   ("run\t\t\t\t50000 upto", "run\t\t\t\t100000 upto")],
                  "600 spheres (not 1800), run to step 100000 (not 50000): friction 0.05 "
                  "and restitution 0.95, the bed is still at 5e-3 m g H at step 50000"),
    "heatTransfer_1": ("heatTransfer_1", "in.heatGran", 0.004, 0.15, "rest", [], "as written"),
    "heatTransfer_2": ("heatTransfer_2", "in.heatGran", 0.004, 0.15, "rest", [], "as written"),
    "multisphere": ("multisphere_stone_restitution", "in.multisphere", 0.01, 0.5, "rest",
                    [("fix\t\tintegr all multisphere\n", "fix\t\tintegr all multisphere "
                      "allow_group_and_set yes\n"),
                     ("run\t\t40000 upto", "run\t\t80000 upto")],
                    "allow_group_and_set yes, for the bed's centre of mass; run to step 80000 "
                    "(not 40000): the stones still bounce at step 40000"),
    "packing": ("packing", "in.packing", 0.0065, 0.15, "rest", [], "as written"),
    "hydrogel_default": ("hydrogel_multicontact", "in.hydrogel_default", 0.005, 0.41, "rest",
                         [(None, "unfix piston_move\nrun 20000\n")],
                         "20000 steps more with the piston stopped: as written the deck ends "
                         "with the piston rising and the gel beads still moving"),
}
# Decks compared at matching steps (name: folder, deck, shortening pairs, the time step
# as written, why). The monolayers (spheres of 1.5 mm on the floor of a 10 cm cylinder,
# friction 0.05, restitution 0.9, no rolling friction) come to rest only after about
# step 65000; ParScale's packing (10 spheres, restitution 0.97, in a box periodic in x
# and y) never does.
MONO = ("a monolayer rolling on the floor without rolling friction, at rest only after "
        "step 65000: run to step 15000 (not 50000), the 1000 spheres inserted and landed")
DT = "timestep\t0.00001"
STEPS = {
    "cohesion": ("cohesion", "in.cohesion",
                 [("run\t\t\t50000 upto", "run\t\t\t15000 upto")], DT, MONO),
    "noCohesion": ("cohesion", "in.noCohesion",
                   [("run\t\t\t50000 upto", "run\t\t\t15000 upto")], DT, MONO),
    "hysteresis": ("hysteresis", "in.hysteresis",
                   [("run\t\t\t50000 upto", "run\t\t\t15000 upto")], DT, MONO),
    "noHysteresis": ("hysteresis", "in.noHysteresis",
                     [("run\t\t\t50000 upto", "run\t\t\t15000 upto")], DT, MONO),
    "ParScale_init": ("ParScale/fluidizedBedTempParScale", "in.liggghts_init",
                      [("run             200000", "run             20000")],
                      "timestep\t${timeStep}",
                      "its variables from the included in.DEM; run to step 20000 (not "
                      "200000): 10 spheres with restitution 0.97 bounce on the floor and "
                      "never rest"),
}
DECADES = 2
# The CTest tests (RS_MIGRATE_PART), side by side: about 100, 70 and 25 s of CPU.
PARTS = {"beds": ["newModels", "heatTransfer_1", "heatTransfer_2"],
         "others": ["multisphere", "packing", "hydrogel_default"],
         "steps": ["cohesion", "noCohesion", "hysteresis", "noHysteresis", "ParScale_init"]}
# Decks whose walls the tool keeps: (folder, deck, the report the tool must give).
KEPT = {
    "hydrogel_multicontact": ("hydrogel_multicontact", "in.hydrogel_multicontact",
                              "model words 'model hertz tangential history surface multicontact'"
                              ": surface multicontact needs LIGGGHTS's own wall"),
}
# Decks not run: (folder, deck, why, the tool's exit status and a report it must give
# or None, the deck's -var arguments).
EXCLUDED = {
    "oldModels": ("contactModels", "in.oldModels", "LIGGGHTS 2's pair_style "
                  "gran/hertz/history: Debian's 3.8.0 stops with 'Invalid pair style'",
                  (1, "LIGGGHTS 2's numeric arguments are not LIGGGHTS 3.8's"), []),
    "superquadric": ("superquadric", "in.particle_particle", "atom_style superquadric: "
                     "Debian's build stops with 'Invalid atom style'",
                     (3, "rolling_friction epsd2 surface superquadric"),
                     ["-var", "blockiness1", "2", "-var", "blockiness2", "2", "-var",
                      "angle", "0"]),
    "ParScale_run": ("ParScale/fluidizedBedTempParScale", "in.liggghts_run",
                     "needs couple/pascal and couple/cfd (ParScale, CFDEM)", (0, None), []),
    "ParScale_bed": ("ParScale/heatTransferBed_paScal", "in.liggghts",
                     "ParScale's particletemplate options: Debian's build stops", (0, None),
                     []),
}


def migrate(s, name, text, folder=None, args=()):
    """The tool's exit status, output and reports for text, written in the scratch folder
    (or in a copy of the tutorial's folder, for the files it names)."""
    d = s.dir
    if folder:
        d = os.path.join(s.dir, name + "_tool")
        if not os.path.isdir(d):
            shutil.copytree(folder, d)
    path = os.path.join(d, name + ".stock.in")
    with open(path, "w") as f:
        f.write(text)
    p = subprocess.run([MIGRATE, path] + list(args), capture_output=True, text=True,
                       timeout=60)
    return p.returncode, p.stdout, p.stderr


def edit(text, pairs):
    for a, b in pairs:
        if a is None:  # appended after the deck's last line
            text += b
            continue
        if a not in text:
            raise SystemExit("tutorial text changed: %r not found" % a)
        text = text.replace(a, b)
    return text


def compare(s, name, spec, rows):
    folder, deck, radius, height, pins, pairs, why = spec
    src_dir = os.path.join(L.TUTORIALS, folder)
    stock = edit(L.no_dumps(open(os.path.join(src_dir, deck)).read()), pairs) + L.BED
    rc, ours, err = migrate(s, name, stock, src_dir)
    walls = len(re.findall(r"^fix\s+\S+\s+\S+\s+wall/gran", stock, re.M))
    left = len(re.findall(r"^\s*fix\s+\S+\s+\S+\s+wall/gran", ours, re.M))
    s.ck.check(name + ": the tool translates every wall (exit 0)", rc == 0 and not left,
               "exit %d, %d of %d wall/gran left" % (rc, left, walls), err)
    _, a, ta, ca = L.run_tutorial(s, name, "liggghts", L.STOCK_LIGGGHTS, src_dir, stock)
    _, b, tb, cb = L.run_tutorial(s, name, "rigidsurf", s.exe, src_dir, ours)
    if not (a and b and ta and tb):
        rows.append((name, "%s/%s" % (folder, deck), why, "", "did not run"))
        return ca + cb
    end = max(ta)
    same_n = a[0] == b[0] and a[0] > 0
    s.ck.check(name + ": the same number of particles", same_n, "%d vs %d" % (a[0], b[0]))
    dcom = max(abs(x - y) for x, y in zip(a[1:4], b[1:4]))
    s.ck.check(name + ": the bed's centre of mass within a tenth of a diameter of stock's",
               dcom <= 0.2 * radius, "%.3g m apart (diameter %g)" % (dcom, 2 * radius))
    rest = True
    for tag, r, t in (("liggghts", a, ta), ("rigidsurf", b, tb)):
        ke, _ = L.window(t, end - 5000, end, 1)
        mgh = r[5] * 9.81 * height
        rest &= s.ck.check(name + ": %s's bed at rest (KE < %g m g H over steps %d-%d)"
                           % (tag, REST, end - 5000, end), max(ke) < REST * mgh,
                           "KE up to %.3g J, m g H %.3g J" % (max(ke), mgh))
    ok = same_n and dcom <= 0.2 * radius and rest
    rows.append((name, "%s/%s" % (folder, deck), why, "%d" % a[0],
                 "same count, centre of mass within 0.1 d, at rest" if ok else "FAILS"))
    return ca + cb


# the bed's centre of mass every 500 steps (`TZ` lines), beside liglib.MONITOR
CENTRE = ('variable tzx equal xcm(all,x)\nvariable tzy equal xcm(all,y)\n'
          'variable tzz equal xcm(all,z)\n'
          'fix tzprint all print 500 "TZ $(step) ${tzx} ${tzy} ${tzz}"\n')


def series(out):
    """{step: values} of the TUT lines (count, KE, mean vx) and TZ lines (centre)."""
    rows = {}
    for line in out.splitlines():
        w = line.split()
        if w[:1] in (["TUT"], ["TZ"]) and len(w) > 2:
            rows.setdefault((w[0], int(w[1])), [float(x) for x in w[2:]])
    return rows


def compare_steps(s, name, spec, rows):
    """The migrated run against stock's, and stock's against its own run with a time
    step larger by one unit of the last place, at every monitored step."""
    folder, deck, pairs, dt, why = spec
    src_dir = os.path.join(L.TUTORIALS, folder)
    stock = edit(L.no_dumps(open(os.path.join(src_dir, deck)).read()), pairs)
    stock = stock.replace(L.MONITOR, L.MONITOR + CENTRE)
    twin = stock.replace(dt, "timestep\t1.0000000000000002e-05")
    s.ck.check(name + ": the twin run's time step differs", twin != stock)
    rc, ours, err = migrate(s, name, stock, src_dir)
    s.ck.check(name + ": the tool translates every wall (exit 0)", rc == 0 and not
               re.search(r"^\s*fix\s+\S+\s+\S+\s+wall/gran", ours, re.M), "exit %d" % rc, err)
    cpu, got = 0.0, {}
    for tag, exe, text in (("liggghts", L.STOCK_LIGGGHTS, stock),
                           ("liggghts_twin", L.STOCK_LIGGGHTS, twin),
                           ("rigidsurf", s.exe, ours)):
        out, _, _, c = L.run_tutorial(s, name, tag, exe, src_dir, text)
        got[tag], cpu = series(out), cpu + c
    a, b, c = got["liggghts"], got["liggghts_twin"], got["rigidsurf"]
    keys = sorted(k for k in a if k in b and k in c)
    names = {"TUT": ("count", "KE", "mean vx"), "TZ": ("x_c", "y_c", "z_c")}
    ok, worst = bool(keys), []
    for kind in ("TUT", "TZ"):
        for j, label in enumerate(names[kind]):
            ks = [k for k in keys if k[0] == kind]
            if not ks:
                ok = False
                continue
            scale = max(abs(a[k][j]) for k in ks) or 1.0
            base = max(abs(b[k][j] - a[k][j]) for k in ks)
            mine = max(abs(c[k][j] - a[k][j]) for k in ks)
            bound = 10 ** DECADES * max(base, 1e-12 * scale)
            ok &= mine <= bound
            worst.append("%s %.2g (stock's own %.2g)" % (label, mine / scale, base / scale))
    s.ck.check(name + ": at every monitored step to step %d, as close to stock as stock's "
               "twin run is (within %d decades)" % (max(k[1] for k in keys) if keys else 0,
                                                    DECADES),
               ok, "; ".join(worst))
    tut = [k for k in keys if k[0] == "TUT"]
    rows.append((name, "%s/%s" % (folder, deck), why, "%d" % a[tut[-1]][0] if tut else "",
                 "matching steps: count, KE, mean vx, centre of mass as close as stock's "
                 "twin" if ok else "FAILS"))
    return cpu


def body(s):
    if not s.ck.check("stock tutorials present", os.path.isdir(L.TUTORIALS), L.TUTORIALS):
        return
    only = os.environ.get("RS_MIGRATE_DECKS")
    only = set(only.split(",")) if only else None
    part = os.environ.get("RS_MIGRATE_PART")
    s.ck.check("the parts run every deck once",
               sorted(sum(PARTS.values(), [])) == sorted(list(DECKS) + list(STEPS))
               and (part is None or part in PARTS), "part %s" % part)
    if part in PARTS:
        only = set(PARTS[part])
    # every deck with a wall/gran is in one of the tables
    found = set()
    for root, _, files in os.walk(L.TUTORIALS):
        for f in files:
            p = os.path.join(root, f)
            if f.startswith("in.") and re.search(r"^\s*fix\s+\S+\s+\S+\s+wall/gran",
                                                 open(p, errors="replace").read(), re.M):
                found.add(os.path.relpath(p, L.TUTORIALS))
    listed = {os.path.join(v[0], v[1]) for t in (DECKS, STEPS, KEPT, EXCLUDED)
              for v in t.values()}
    listed |= {os.path.join(f, d) for f, d in MESH_DECKS.values()}
    s.ck.check("every tutorial deck with a fix wall/gran is listed", found <= listed,
               "%d decks" % len(found), "not listed: %s" % sorted(found - listed))
    for name, (folder, deck, want) in KEPT.items():
        src = os.path.join(L.TUTORIALS, folder)
        rc, out, err = migrate(s, name, open(os.path.join(src, deck)).read(), src)
        lines = [l for l in err.splitlines() if l.startswith("LINE ")]
        s.ck.check(name + ": the tool keeps its walls and says why, line by line (exit 3)",
                   rc == 3 and want in err and all(re.match(r"LINE \d+: ", l) for l in lines),
                   "%d report lines" % len(lines), err)
    for name, (folder, deck, why, (want_rc, want), args) in EXCLUDED.items():
        src = os.path.join(L.TUTORIALS, folder)
        rc, out, err = migrate(s, name, open(os.path.join(src, deck)).read(), src, args)
        s.ck.check(name + ": excluded (%s); the tool exits %d%s" % (
            why, want_rc, " naming '%s'" % want if want else ""),
            rc == want_rc and (want is None or want in err), "exit %d" % rc, err)
    rows, cpu = [], 0.0
    for name, spec in DECKS.items():
        if only is None or name in only:
            cpu += compare(s, name, spec, rows)
    for name, spec in STEPS.items():
        if only is None or name in only:
            cpu += compare_steps(s, name, spec, rows)
    print("CPU of the runs: %.0f s" % cpu)
    for name, (folder, deck, want) in KEPT.items():
        rows.append((name, "%s/%s" % (folder, deck), "not run", "", "walls kept: " + want))
    for name, (folder, deck, why, (want_rc, want), _) in EXCLUDED.items():
        rows.append((name, "%s/%s" % (folder, deck), "excluded: " + why, "",
                     "the tool exits %d" % want_rc))
    table = "\n".join("| %s |" % " | ".join(r) for r in rows)
    print(table)
    # The doc's rows are the decks' rows in table order; a run of some decks
    # (RS_MIGRATE_DECKS, one CTest test per group) checks the rows of its decks.
    doc = open(DOC).read()
    m = re.search(r"<!-- migrate-table -->\n(.*?)\n<!-- /migrate-table -->", doc, re.S)
    have = [l for l in (m.group(1).splitlines() if m else []) if l.startswith("| ")
            and not l.startswith("| deck")]
    names = [n for t in (DECKS, STEPS, KEPT, EXCLUDED) for n in t]
    s.ck.check("docs/migration.md's table has one row per deck, in order",
               [l.split(" | ")[0][2:] for l in have] == names,
               why="the doc's rows:\n%s" % "\n".join(have))
    mine = set(table.splitlines())
    ran = [l for l in have if l.split(" | ")[0][2:] in {r[0] for r in rows}]
    s.ck.check("docs/migration.md's rows of these decks are this run's",
               sorted(ran) == sorted(mine), "%d rows" % len(mine),
               "the doc's rows:\n%s" % "\n".join(ran))


MESH_DECKS = {"meshGran": ("meshGran", "in.meshGran"),
              "movingMeshGran": ("movingMeshGran", "in.movingMeshGran"),
              "conveyor": ("conveyor", "in.conveyor"),
              "chute_wear": ("chute_wear", "in.chute_wear")}

if __name__ == "__main__":
    SES = L.Session(__doc__)
    MIGRATE = os.environ.get("RS_MIGRATE") or os.path.join(os.path.dirname(SES.exe), "..",
                                                           "rigidsurf-migrate")
    L.main_guard(SES, body)
