"""What else in a deck names a wall or its mesh, kept working when the wall becomes
`fix wall/rigid` (part of rigidsurf-migrate; docs/migration.md):

- f_M[i] of a `mesh/surface/stress` (and /servo) mesh M: the force (1-3), the torque about
  the reference point (4-6) and the point (7-9), the servo's centre (10-12), as wall/rigid's
  force (1-3), moment about the surface origin (4-6) and translation (15-17): an index, or
  a formula where the points differ (in a formula in place, elsewhere a variable
  v_rs_M_i defined after the wall);
- `dump mesh/stl|mesh/vtk|mesh/gran/VTK` of a migrated mesh: the wall's `vtk FILE N` where
  the dump writes the forces on the mesh (stress, stresscomponents, wear), else the mesh
  kept as a LIGGGHTS mesh for the dump alone, without a wall;
- `unfix` of a wall/gran, of a mesh, of a move/mesh; `undump`, `dump_modify` of a dump
  that became a wall's vtk; `fix_modify W energy yes|no` of a mesh wall/gran;
- `compute wall/gran/local`: it reads LIGGGHTS's mesh wall, which stays.
"""
import re

import rigidsurf_migrate_commands as grammar
from rigidsurf_migrate_deck import DeckError
from rigidsurf_migrate_walls import fmt, number

REF = re.compile(r"\bf_(\w+)(\[(\d+)\])?")
TINY = 1e-12


# ---- f_M[i] ------------------------------------------------------------------------------

def rotates(mg, m):
    s = mg.motion_state.get(m.id, {})
    servo = dict(zip(m.servo[::2], m.servo[1::2]))
    return s.get("rot") is not None or s.get("spin") is not None or \
        servo.get("ctrlPV") == "torque"


def ref_point(m):
    """LIGGGHTS's point of the torque f_M[4-6] where the mesh was made: the servo's com,
    else reference_point, else the origin; None when not a number the tool knows."""
    if m.servo:
        k = m.servo.index("com")
        p = [number(x) for x in m.servo[k + 1:k + 4]]
    else:
        p = m.refpoint or [0.0, 0.0, 0.0]
    return None if None in p else p


def mapping(mg, m, i):
    """f_M[i] of mesh m as wall/rigid's output: (True, a text: an f_ reference or a
    formula), (False, why it cannot be), or None for an index out of LIGGGHTS's range
    (left as written)."""
    size = sum(grammar.MODULE_VECTOR[x] for x in m.modules)
    if i is None:
        return False, "f_%s (the whole vector) reads LIGGGHTS's layout of %d values" % (
            m.id, size)
    if not 1 <= i <= size:
        return None          # out of LIGGGHTS's range: left as written
    r = m.rid
    if i <= 6 and m.stress_off:
        return False, "f_%s[%d]: 'stress off' keeps LIGGGHTS's forces at zero" % (m.id, i)
    if i <= 3:
        return True, "f_%s[%d]" % (r, i)
    p, a = ref_point(m), m.origin()
    if p is None:
        return False, "f_%s[%d]: its reference point is not a number the tool knows" % (
            m.id, i)
    d = [x - y for x, y in zip(a, p)]
    turns = rotates(mg, m)
    if i <= 6:
        if all(abs(x) <= TINY for x in d):
            return True, "f_%s[%d]" % (r, i)
        if turns:
            return False, ("f_%s[%d]: the torque about a point the wall turns away from "
                           "its surface origin" % (m.id, i))
        # M_p = M_a + (a - p) x F
        k = i - 4
        j, l = (k + 1) % 3, (k + 2) % 3
        terms = "".join("%s%s*f_%s[%d]" % ("+" if c > 0 else "-", fmt(abs(c)), r, n)
                        for c, n in ((d[j], l + 1), (-d[l], j + 1)) if abs(c) > TINY)
        return True, ("(f_%s[%d]%s)" % (r, i, terms) if terms else "f_%s[%d]" % (r, i))
    k = (i - 7) % 3
    s = mg.motion_state.get(m.id, {})
    if turns and s.get("rot") is not None:
        o = [float(x) for x in s["rot"][0]] if all(_num(x) for x in s["rot"][0]) else None
        if o is None or any(abs(x - y) > TINY for x, y in zip(o, p)) or \
                s.get("spin") is not None:
            return False, "f_%s[%d]: a point the wall turns about another origin" % (m.id, i)
    return True, ("f_%s[%d]" % (r, 15 + k) if abs(p[k]) <= TINY else
                  "(%s+f_%s[%d])" % (fmt(p[k]), r, 15 + k))


def _num(x):
    try:
        float(x)
        return True
    except ValueError:
        return False


def references(mg, commands):
    """Every f_M[i] of a migrated mesh in commands (not rewritten otherwise): adds to the
    mesh's reasons those that cannot be kept."""
    wall_ids = {w.id for w in mg.walls if w.kind == "mesh"}
    for cmd in commands:
        for mt in REF.finditer(cmd.body):
            if mt.group(1) in wall_ids:
                raise DeckError(cmd, "%s: fix wall/gran computes no value a deck can read "
                                "(LIGGGHTS stops here)" % mt.group(0))
            m = mg.meshes.get(mt.group(1))
            if m is None or not m.modules:
                continue
            i = int(mt.group(3)) if mt.group(3) else None
            got = mapping(mg, m, i)
            if got is not None and not got[0]:
                m.reasons.append("%s reads %s; wall/rigid has no such value" % (
                    cmd.where(), got[1]))


def in_formula(cmd, pos):
    """Whether the text at pos of cmd.body lies in a formula: the formula of a `variable
    ... equal|atom` or an immediate $(...)."""
    w = cmd.raw_words
    if w[:1] == ["variable"] and len(w) > 3 and w[2] in ("equal", "atom"):
        start = cmd.body.find(w[3], cmd.body.find(w[2]) + len(w[2]))
        if 0 <= start <= pos:
            return True
    depth, i = 0, 0
    while i < pos:
        if cmd.body.startswith("$(", i):
            depth += 1
            i += 2
            continue
        if cmd.body[i] == ")" and depth:
            depth -= 1
        i += 1
    return depth > 0


def rewrite_references(mg, commands):
    """The text of each command of commands whose f_M[i] change: {cmd: its physical
    lines}; the variables that argument contexts need go to mg.after (after the wall)."""
    out = {}
    for cmd in commands:
        def sub(mt, cmd=cmd):
            m = mg.meshes.get(mt.group(1))
            if m is None or not m.ok or not m.modules or not mt.group(3):
                return mt.group(0)
            i = int(mt.group(3))
            got = mapping(mg, m, i)
            if got is None or not got[0] or got[1] == mt.group(0):
                return mt.group(0)
            got = got[1]
            if got.startswith("f_") or in_formula(cmd, mt.start()):
                return got
            name = "rs_%s_%d" % (m.id, i)
            mg.after.setdefault(m.wall.cmd, {})[name] = "variable %s equal %s" % (name, got)
            return "v_" + name
        lines = [REF.sub(sub, phys) if "f_" in phys else phys for phys in cmd.raw]
        if lines != cmd.raw:
            out[cmd] = lines
    return out


# ---- dumps, computes, fix_modify, unfix --------------------------------------------------

class Dump:
    """A mesh dump as it ran: its meshes (named, or every mesh made before it) and
    fields."""

    def __init__(self, ex, alive_meshes):
        w = ex.words
        if len(w) < 6:
            raise DeckError(ex.cmd, "Illegal dump %s command" % w[3])
        self.ex, self.id, self.style, self.every, self.file = ex, w[1], w[3], w[4], w[5]
        try:
            named, self.fields = grammar.parse_mesh_dump(w[3:], lambda x: x in alive_meshes)
        except grammar.Grammar as e:
            raise DeckError(ex.cmd, str(e))
        self.meshes = named if named is not None else list(alive_meshes)
        self.forces = any(f in grammar.DUMP_FORCE_FIELDS for f in self.fields)


def dumps(mg):
    """Decides each mesh dump: the migrated meshes of a dump of forces get the wall's
    vtk (one per dump; a mesh in two such dumps keeps its wall), those of a dump of the
    geometry stay LIGGGHTS meshes for it."""
    for d in mg.dumps:
        mine = [mg.meshes[x] for x in d.meshes if x in mg.meshes and mg.meshes[x].ok]
        if not mine:
            continue
        if not d.forces:
            for m in mine:
                m.display = True
                m.rid = "rs_" + m.id
            continue
        for m in mine:
            if m.vtk:
                m.reasons.append("two dumps write its stress (%s and %s): wall/rigid writes "
                                 "one vtk" % (m.vtk_dump.ex.cmd.where(), d.ex.cmd.where()))
            name = d.file if len(mine) == len(d.meshes) == 1 else \
                d.file.replace("*", m.id + "_*", 1) if "*" in d.file else \
                d.file + "." + m.id
            m.vtk, m.vtk_dump = [name, d.every], d


def dump_lines(mg, d):
    """The text of dump d once its migrated meshes write their own vtk: None (as written),
    or the lines that replace it."""
    mine = [x for x in d.meshes if x in mg.meshes and mg.meshes[x].ok]
    if not mine or not d.forces:
        return None
    rest = [x for x in d.meshes if x not in mine]
    return [" ".join(d.ex.words[:6] + d.fields + rest)] if rest else []


def notes_for_dumps(mg):
    for d in mg.dumps:
        mine = [mg.meshes[x] for x in d.meshes if x in mg.meshes and mg.meshes[x].ok]
        if not mine:
            continue
        ids = " ".join(m.id for m in mine)
        if d.forces:
            written = [f for f in d.fields if f in ("stress", "wear")]
            lost = [f for f in d.fields if f not in ("stress", "wear")]
            mg.note(d.ex.cmd, "dump %s of %s: wall/rigid's vtk %s every %s steps (cell data "
                    "sigma_n and sigma_t for LIGGGHTS's stress, wear with wear finnie)%s" % (
                        d.id, ids, " ".join(m.vtk[0] for m in mine), d.every,
                        "; not written: " + " ".join(lost) if lost else "")
                    if written or lost else "")
        else:
            one = len(mine) == 1
            mg.note(d.ex.cmd, "dump %s writes %s %s, kept as %s for it alone (without a "
                    "wall); the wall%s wall/rigid %s" % (
                        d.id, "mesh" if one else "meshes", ids,
                        "a LIGGGHTS mesh" if one else "LIGGGHTS meshes",
                        " is" if one else "s are", " ".join(m.rid for m in mine)))


def cwl(mg, ex, alive):
    """compute wall/gran/local reads the contacts of the last mesh wall/gran made before
    it (ComputePairGranLocal::init_cpgl): that wall stays LIGGGHTS's."""
    walls = [w for w in alive.values() if getattr(w, "kind", None) == "mesh"]
    if not walls:
        raise DeckError(ex.cmd, "compute wall/gran/local requires a fix of type wall/gran "
                        "using one or more mesh walls, defined before it")
    walls[-1].reasons.append("compute %s (%s) reads its contacts: wall/rigid has no "
                             "per-contact output" % (ex.words[1], ex.cmd.where()))


def unfixes(mg):
    """unfix of a migrated wall/gran, mesh or move/mesh: each wall/rigid unfixed once,
    at the first unfix that removes it in LIGGGHTS (the wall/gran's or its mesh's), the
    last made first."""
    alive = set()
    for ex in mg.deck.trace:
        w = ex.words
        if ex in mg.wall_execs:
            alive |= {m.rid for m in mg.wall_execs[ex].mesh_objs}
            continue
        if w[0] == "fix_modify" and len(w) > 1:
            wall = mg.mesh_wall(w[1])
            if wall is not None:
                if any(x not in ("energy", "yes", "no") for x in w[2:]) or len(w) != 4:
                    raise DeckError(ex.cmd, "fix_modify %s: fix wall/gran takes no keyword "
                                    "but 'energy yes|no' (LIGGGHTS: Illegal fix_modify "
                                    "command)" % w[1])
                mg.commit(ex, ["fix_modify %s energy %s" % (m.rid, w[3])
                               for m in wall.mesh_objs])
            continue
        if w[0] != "unfix" or len(w) < 2:
            continue
        wall, m = mg.mesh_wall(w[1]), mg.meshes.get(w[1])
        lines = None
        if wall is not None:
            lines = ["unfix %s" % x.rid for x in reversed(wall.mesh_objs) if x.rid in alive]
            alive -= {x.rid for x in wall.mesh_objs}
        elif m is not None and m.ok:
            lines = ["unfix %s" % m.id] if m.display else []
            if m.rid in alive:
                lines.append("unfix %s" % m.rid)
                alive.discard(m.rid)
        if ex in mg.motion_lines:
            lines = (lines or []) + mg.motion_lines.pop(ex)
        if lines is not None:
            mg.commit(ex, lines)
