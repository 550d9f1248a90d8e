#!/usr/bin/python3
"""Every Tutorials_public deck with a `fix wall/gran`, run by stock LIGGGHTS as written
and by liggghts-rigidsurf as rigidsurf-migrate rewrites it, and compared.

Each deck is first shortened (DECKS: fewer particles, fewer steps, the reason), its
dumps taken out and a monitor added (liglib.MONITOR: count, KE, mean vx every 1000
steps); the shortened deck is what stock LIGGGHTS runs and what the tool migrates. The
comparison, at the end, where both beds are at rest (KE below REST of m g H over the
last 5000 steps) or in steady flow:
- the same number of particles;
- the bed's centre of mass within a tenth of a particle diameter of stock's;
- at rest in both runs, or (a stream) the same mean x velocity over the window, to 10%.
Decks that stock Debian LIGGGHTS cannot run, that need other couplings, or whose beds
come to rest only past the test's CPU budget, are named in EXCLUDED with the reason; the tool is still run on each and must name the walls it keeps
(exit 3) or translate them (exit 0) as the table says. Decks whose walls the tool keeps
(KEPT) have nothing to compare; their report lines are checked.

The table in docs/migration.md (between the `migrate-table` markers) must equal the one
this test prints from its own results' pins (the rows are the decks, what was migrated
and what was compared), and the deck shown there with the tool's output must equal the
tool's output. RS_MIGRATE_DECKS (comma-separated names) runs only those decks (and checks
only their rows of the doc's table); RS_MIGRATE_PART runs one of PARTS, as CTest does.
"""
import os
import re
import subprocess
import sys

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
# The CTest tests (RS_MIGRATE_PART), side by side: about 100 and 70 s of CPU.
PARTS = {"beds": ["newModels", "heatTransfer_1", "heatTransfer_2"],
         "others": ["multisphere", "packing", "hydrogel_default"]}
# Decks whose walls the tool keeps: (folder, deck, the report the tool must give).
KEPT = {
    "hydrogel_multicontact": ("hydrogel_multicontact", "in.hydrogel_multicontact",
                              "model words 'model hertz tangential history surface multicontact'"
                              ": surface multicontact needs LIGGGHTS's own wall"),
}
# Decks not run: (folder, deck, why, the report the tool must give or None).
MONOLAYER = ("a monolayer rolling on the floor without rolling friction: %s, not at rest "
             "(KE < 1e-4 m g H) before about step 65000 with its 1000 spheres, "
             "over the test's CPU budget; fewer spheres roll longer")
EXCLUDED = {
    "oldModels": ("contactModels", "in.oldModels", "LIGGGHTS 2's pair_style "
                  "gran/hertz/history: Debian's 3.8.0 stops with 'Invalid pair style'",
                  "the old wall/gran arguments"),
    "superquadric": ("superquadric", "in.particle_particle", "atom_style superquadric: "
                     "Debian's build stops with 'Invalid atom style'",
                     "rolling_friction epsd2 surface superquadric"),
    # The four monolayer decks: spheres of 1.5 mm on the floor of a 10 cm cylinder,
    # friction 0.05, restitution 0.9 and no rolling friction, so a rolling sphere loses
    # energy only in collisions. As written (1000 spheres, to step 50000) the beds are
    # not at rest in stock LIGGGHTS (KE about 2e-4 m g H, H the box height); hysteresis
    # comes to rest about step 65000, about 0.3 s of CPU per 1000 steps, so the eight
    # runs would take the test's whole budget. With particles_in_region 100 (400
    # spheres) the bed is a rolling gas: KE still 2-6e-4 m g H at step 100000 and,
    # without cohesion, the centres of mass 0.3-0.7 d apart. The cohesive bed (sjkr)
    # creeps at 5-7e-5 m g H from step 50000 to 70000.
    "cohesion": ("cohesion", "in.cohesion", MONOLAYER % "the cohesive bed creeps", None),
    "noCohesion": ("cohesion", "in.noCohesion", MONOLAYER % "the bed rolls", None),
    "hysteresis": ("hysteresis", "in.hysteresis", MONOLAYER % "the bed rolls", None),
    "noHysteresis": ("hysteresis", "in.noHysteresis", MONOLAYER % "the bed rolls", None),
    "ParScale_init": ("ParScale/fluidizedBedTempParScale", "in.liggghts_init",
                      "the packing of a ParScale (couple/pascal) case", None),
    "ParScale_run": ("ParScale/fluidizedBedTempParScale", "in.liggghts_run",
                     "needs couple/pascal and couple/cfd (ParScale, CFDEM)", None),
    "ParScale_bed": ("ParScale/heatTransferBed_paScal", "in.liggghts",
                     "ParScale's particletemplate options: Debian's build stops", None),
}


def migrate(s, name, text):
    path = s.write(name + ".stock.in", text)
    p = subprocess.run([MIGRATE, path], capture_output=True, text=True, timeout=60)
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
    rc, ours, err = migrate(s, name, stock)
    walls = len(re.findall(r"^fix\s+\S+\s+\S+\s+wall/gran", stock, re.M))
    s.ck.check(name + ": the tool translates every wall (exit 0)", rc == 0 and
               "wall/gran" not in ours, "exit %d, %d wall/gran" % (rc, walls), err)
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


def body(s):
    if not s.ck.check("stock tutorials present", os.path.isdir(L.TUTORIALS), L.TUTORIALS):
        return
    only = os.environ.get("RS_MIGRATE_DECKS")
    only = set(only.split(",")) if only else None
    part = os.environ.get("RS_MIGRATE_PART")
    s.ck.check("the parts run every deck once", sorted(sum(PARTS.values(), [])) == sorted(DECKS)
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
    listed = {os.path.join(v[0], v[1]) for t in (DECKS, KEPT, EXCLUDED) for v in t.values()}
    listed |= {os.path.join(f, d) for f, d in MESH_DECKS.values()}
    s.ck.check("every tutorial deck with a fix wall/gran is listed", found <= listed,
               "%d decks" % len(found), "not listed: %s" % sorted(found - listed))
    for name, (folder, deck, want) in KEPT.items():
        rc, out, err = migrate(s, name, open(os.path.join(L.TUTORIALS, folder, deck)).read())
        lines = [l for l in err.splitlines() if l.startswith("LINE ")]
        s.ck.check(name + ": the tool keeps its walls and says why, line by line (exit 3)",
                   rc == 3 and want in err and all(re.match(r"LINE \d+: ", l) for l in lines),
                   "%d report lines" % len(lines), err)
    for name, (folder, deck, why, want) in EXCLUDED.items():
        rc, out, err = migrate(s, name, open(os.path.join(L.TUTORIALS, folder, deck)).read())
        s.ck.check(name + ": excluded (%s); the tool %s" % (
            why, "reports its walls" if want else "translates it"),
            (rc == 3 and want in err) if want else rc == 0, "exit %d" % rc, err)
    rows, cpu = [], 0.0
    for name, spec in DECKS.items():
        if only is None or name in only:
            cpu += compare(s, name, spec, rows)
    print("CPU of the runs: %.0f s" % cpu)
    for name, (folder, deck, want) in KEPT.items():
        rows.append((name, "%s/%s" % (folder, deck), "not run", "", "walls kept: " + want))
    for name, (folder, deck, why, want) in EXCLUDED.items():
        rows.append((name, "%s/%s" % (folder, deck), "excluded: " + why, "", ""))
    table = "\n".join("| %s |" % " | ".join(r) for r in rows)
    print(table)
    # The doc's rows are the decks' rows in table order; a run of some decks
    # (RS_MIGRATE_DECKS, one CTest test per group) checks the rows of its decks.
    doc = open(DOC).read()
    m = re.search(r"<!-- migrate-table -->\n(.*?)\n<!-- /migrate-table -->", doc, re.S)
    have = [l for l in (m.group(1).splitlines() if m else []) if l.startswith("| ")
            and not l.startswith("| deck")]
    names = [n for t in (DECKS, KEPT, EXCLUDED) for n in t]
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
