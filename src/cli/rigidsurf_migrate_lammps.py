"""rigidsurf-migrate for LAMMPS decks (docs/migration.md, *LAMMPS walls*).

The deck is read and followed as LAMMPS 29Sep2021 runs it (rigidsurf_migrate_deck.py,
engine "lammps"); each `fix wall/gran` and `fix wall/gran/region` becomes `fix
wall/rigid` with `law lammps` (rigidsurf_migrate_lammps_walls.py) on the exact surfaces of
its wall or region (rigidsurf_migrate_lammps_regions.py); `unfix` of such a wall unfixes
what it became, and f_ID[2-4] of its `contacts` array read wall/rigid's stored force.
Every other line is copied byte for byte. Which engine a deck is for: detect_engine.
"""
import os
import re

import rigidsurf_migrate_deck as D
import rigidsurf_migrate_expr as expr
import rigidsurf_migrate_lammps_commands as grammar
import rigidsurf_migrate_lammps_regions as geo
import rigidsurf_migrate_walls as lwalls
from rigidsurf_migrate_commands import Grammar
from rigidsurf_migrate_deck import DeckError
from rigidsurf_migrate_lammps_walls import Wall

REF = re.compile(r"\bf_(\w+)(\[(\d+|\*)\])?")
STYLES = ("wall/gran", "wall/gran/region")
# LAMMPS's contacts array (FixWallGran, `contacts`): its columns
CONTACTS = {1: "1 when in contact", 5: "the contact point's x", 6: "the contact point's y",
            7: "the contact point's z", 8: "the particle's radius"}


def detect_engine(path):
    """The engine the deck at path is written for, from its commands and those of the
    files it includes (as named): 'lammps' or 'liggghts' (also where nothing tells);
    DeckError where both engines' commands appear."""
    commands, todo, seen = [], [(None, path)], set()
    folder = os.path.dirname(os.path.abspath(path))
    while todo:
        name, p = todo.pop()
        if p in seen or not os.path.isfile(p):
            continue
        seen.add(p)
        try:
            with open(p, newline="") as f:
                src = D.Source(name, p, f.read())
        except (OSError, UnicodeDecodeError):
            continue
        commands += src.commands
        for c in src.commands:
            if c.raw_words[:1] == ["include"] and len(c.raw_words) == 2 and \
                    "$" not in c.raw_words[1]:
                todo.append((c.raw_words[1], os.path.join(folder, c.raw_words[1])))
    got = grammar.detect(commands)
    if isinstance(got, tuple):
        raise DeckError(None, "the deck has LIGGGHTS's %s (%s) and LAMMPS's %s (%s): give "
                        "--engine liggghts or --engine lammps" % (
                            got[1], got[0].where(), got[3], got[2].where()))
    return got or "liggghts"


class LammpsMigration:
    """A LAMMPS deck's migration: what differs from a LIGGGHTS deck's, before the
    Migration class of rigidsurf-migrate (which gives the reports, the commits, the
    control-flow checks and the text) in the migration's classes."""
    ENGINE, FIXES = "LAMMPS", "wall/gran and wall/gran/region fixes"

    def __init__(self, path, cli_vars=()):
        super().__init__(path, cli_vars, "lammps")
        self.deck.observer = self.observe
        self.regions, self.observed, self.files = {}, {}, {}
        # the region walls that exist (fix ID: its Exec and regions as made), and those
        # that run with a region defined again since (Exec: the run and the region)
        self.live, self.redefined = {}, {}
        self.units, self.dimension, self.periodic = "lj", 3, [True, True, True]
        self.lattice, self.box = (1.0, 1.0, 1.0), None

    # -- what the deck holds where a wall is made ------------------------------------
    def observe(self, ex):
        w = ex.words
        if w[0] == "unfix" and len(w) > 1:
            self.live.pop(w[1], None)
        elif w[0] == "run":
            for fex, made in self.live.values():
                for rid, reg in made.items():
                    if self.regions.get(rid) is not reg and fex not in self.redefined:
                        self.redefined[fex] = (ex.cmd, rid)
        elif w[0] == "region" and len(w) >= 3:
            if w[2] == "delete":
                for rid in w[1:2]:
                    if rid not in self.regions:
                        raise DeckError(ex.via or ex.cmd, "Delete region %s does not exist"
                                        % rid)
                    del self.regions[rid]
                return
            try:
                reg = grammar.Region(w[1:])
            except Grammar as e:
                raise DeckError(ex.via or ex.cmd, str(e))
            if reg.id in self.regions:
                raise DeckError(ex.via or ex.cmd, "Reuse of region ID %s" % reg.id)
            for m in reg.members:
                if m not in self.regions:
                    raise DeckError(ex.via or ex.cmd, "Region %s region ID %s does not "
                                    "exist" % (reg.style, m))
            reg.cmd = ex.cmd
            self.regions[reg.id] = reg
        elif w[0] == "fix" and len(w) >= 4 and w[3] == "wall/gran/region":
            try:
                g = grammar.Wall(w[4:], True)
            except Grammar:
                return          # the scan reports it
            rid = w[4 + g.values[0]]
            reg = self.regions.get(rid)
            if reg is None:
                raise DeckError(ex.via or ex.cmd, "fix %s: region %s does not exist (LAMMPS: "
                                "Region ID for fix wall/gran/region does not exist)" % (
                                    w[1], rid))
            vals = {}
            for name in [x for x in (reg.move or ()) if x != "NULL"] + \
                    ([reg.rotate[0]] if reg.rotate else []):
                try:
                    vals[name] = float(self.deck.formula(name, ex.cmd))
                except expr.Unknown as e:
                    vals[name] = str(e)
                except DeckError as e:   # LAMMPS needs it only when the run begins
                    vals[name] = str(e)
            self.observed[ex] = (reg, dict(self.regions), vals)
            made, todo = {}, [reg]
            while todo:
                r = todo.pop()
                made[r.id] = r
                todo += [self.regions[m] for m in r.members]
            self.live[w[1]] = (ex, made)

    # -- the deck ------------------------------------------------------------------
    def wall_related(self, words, ids):
        if len(words) >= 4 and words[0] == "fix" and words[3] in STYLES:
            return True
        if words[:1] == ["region"] and len(words) > 1:
            return words[1] in ids
        if words[:1] and words[0] in ("unfix", "fix_modify") and len(words) > 1:
            return words[1] in ids or "$" in words[1]
        if words[:1] == ["if"]:
            return any(self.wall_related(D.split_words(c, None, strict=False, triple=True),
                                         ids) for c in words[2:]
                       if c not in ("then", "elif", "else"))
        return False

    def ids(self):
        out = set()
        for ex in self.deck.trace:
            w = ex.words
            if len(w) >= 4 and w[0] == "fix" and w[3] in STYLES:
                out.add(w[1])
        for reg, regions, _ in self.observed.values():
            todo = [reg]
            while todo:
                r = todo.pop()
                out.add(r.id)
                todo += [regions[m] for m in r.members if m in regions]
        return out

    def scan(self):
        alive, restart = {}, None
        for ex in self.deck.trace:
            w = ex.words
            c = w[0]
            if c == "read_restart":
                restart = ex.cmd
            elif c == "units" and len(w) > 1:
                self.units = w[1]
            elif c == "dimension" and len(w) > 1:
                self.dimension = int(w[1]) if w[1].isdigit() else 3
            elif c == "boundary" and len(w) > 3:
                self.periodic = [x == "p" for x in w[1:4]]
            elif c == "change_box" and "boundary" in w[2:]:
                k = w.index("boundary", 2)
                if len(w) > k + 3:
                    self.periodic = [x == "p" for x in w[k + 1:k + 4]]
            elif c == "lattice" and len(w) > 1:
                self.lattice = grammar.lattice_scale(w[1:], self.units, self.dimension)
            elif c == "create_box" and len(w) > 2 and self.box is None:
                self.box = self.box_of(w[2], ex)
            elif c == "fix" and len(w) >= 4 and w[3] in STYLES:
                wall = Wall(ex, self.observed.get(ex))
                if wall.g.wall in ("xplane", "yplane", "zplane", "zcylinder") and any(
                        self.periodic[k] for k in ({"xplane": [0], "yplane": [1],
                                                    "zplane": [2]}.get(wall.g.wall, [0, 1]))):
                    raise DeckError(ex.via or ex.cmd, "fix %s: %s in a periodic dimension "
                                    "(LAMMPS: Cannot use wall in periodic dimension)" % (
                                        wall.id, wall.g.wall))
                if ex in self.redefined:
                    cmd, rid = self.redefined[ex]
                    wall.reasons.append(
                        "%s runs it with region %s defined again since the wall was made "
                        "(LAMMPS's wall takes the region of its ID as it stands at each "
                        "run): the tool migrates a wall whose region stays as it was" % (
                            cmd.where(), rid))
                if restart is not None:
                    wall.notes.append(
                        "read_restart (%s): a restart file of stock lmp holds fix %s's "
                        "contact history, which wall/rigid does not read (its contacts "
                        "start anew); one that lmp-rigidsurf wrote holds wall/rigid's" % (
                            restart.where(), wall.style))
                self.walls.append(wall)
                self.wall_execs[ex] = wall
                alive[wall.id] = wall
            elif c == "unfix" and len(w) > 1:
                alive.pop(w[1], None)
            elif c == "fix_modify" and len(w) > 1 and isinstance(alive.get(w[1]), Wall):
                self.fix_modify(ex, alive[w[1]])

    def fix_modify(self, ex, wall):
        """fix_modify of a wall: FixWallGran takes Fix::modify_params's words and acts on
        none (it has no energy, virial or respa levels to give); wall/rigid likewise
        takes them on each of its walls."""
        w, k, pairs = ex.words, 2, []
        while k < len(w):
            if w[k] in ("energy", "virial", "dynamic/dof") and k + 1 < len(w) and \
                    w[k + 1] in ("yes", "no") and not (w[k] != "dynamic/dof" and
                                                       w[k + 1] == "yes"):
                pairs.append(w[k:k + 2])
                k += 2
                continue
            raise DeckError(ex.via or ex.cmd, "fix_modify %s: fix %s takes %s (LAMMPS: "
                            "Illegal fix_modify command)" % (
                                wall.id, wall.style, "'energy no', 'virial no' and "
                                "'dynamic/dof yes|no' only" if k < len(w) else
                                "a keyword and its value"))
        if len(w) < 3:
            raise DeckError(ex.via or ex.cmd, "Illegal fix_modify command")
        wall.modifies.append((ex, w[2:]))

    def box_of(self, rid, ex):
        """The box (lo, hi per axis) of create_box's block region, where the tool knows
        it."""
        reg = self.regions.get(rid)
        if reg is None or reg.style != "block":
            return None
        ctx = geo.Context(self.lattice, None, geo.BIG)
        try:
            v = geo.values(reg, ctx, lwalls.number)
        except geo.Unmigratable:
            return None
        return [(v[0], v[1]), (v[2], v[3]), (v[4], v[5])]

    def context(self):
        half = None
        if self.box is not None:
            half = max(abs(x) for b in self.box for x in b)
        L = lwalls.half_length(half)
        return geo.Context(self.lattice, self.box, float(L) if L is not None else None)

    # -- decisions -------------------------------------------------------------------
    def references(self, commands):
        """Every f_ID of a wall in commands: LAMMPS reads its contacts array; wall/rigid
        keeps its force (2-4) in store_force's array."""
        by_id = {}
        for w in self.walls:
            by_id.setdefault(w.id, []).append(w)
        for cmd in commands:
            for mt in REF.finditer(cmd.body):
                walls = by_id.get(mt.group(1))
                if not walls:
                    continue
                for w in walls:
                    if not w.contacts:
                        raise DeckError(cmd, "%s: fix %s keeps no per-atom array without "
                                        "'contacts' (LAMMPS stops here)" % (mt.group(0), w.id))
                    i = mt.group(3)
                    if i is None or i == "*" or int(i) not in (2, 3, 4):
                        w.reasons.append("%s reads %s, LAMMPS's contacts %s, which "
                                         "wall/rigid does not keep (it keeps the force, "
                                         "f_%s[2-4])" % (cmd.where(), mt.group(0),
                                                         "array" if i in (None, "*") else
                                                         "column %s (%s)" % (i, CONTACTS.get(
                                                             int(i), "out of its 8")), w.id))

    def decide(self):
        ctx = self.context()
        for wall in self.walls:
            if ctx.L is None:
                wall.reasons.append("the box's size is not known to the tool (create_box of "
                                    "a block region it can read)")
            else:
                wall.build(ctx, lwalls.number)
            wall.ok = not wall.reasons
            wall.why = list(wall.reasons)

    # -- output ------------------------------------------------------------------
    def emit(self):
        ctx = self.context()
        for wall in self.walls:
            if not wall.ok:
                for r in wall.why:
                    self.report(wall.cmd, "fix %s: %s" % (wall.id, r))
                self.report(wall.cmd, "fix %s: the wall is kept as LAMMPS's" % wall.id)
                continue
            for n in wall.notes + wall.curvature_notes():
                self.note(wall.cmd, "fix %s: %s" % (wall.id, n))
            meshes = [fid for fid, s in wall.pieces if s.kind == "mesh"]
            if meshes:
                self.note(wall.cmd, "fix %s: region %s's faces are written to %s beside the "
                          "deck" % (wall.id, wall.observed[0].id, " ".join(
                              "%s.%s.stl" % (os.path.basename(self.deck.main.path), m)
                              for m in meshes)))
            if wall.contacts:
                self.note(wall.cmd, "fix %s: contacts: f_%s[2-4] (the force) read "
                          "wall/rigid's store_force f_force_%s[1-3]" % (wall.id, wall.id,
                                                                       wall.id))
        replaced = self.replacements()
        for wall in self.walls:
            lines = wall.lines(ctx.L, self.deck.main.path, self.files) if wall.ok else \
                [None]
            if replaced.get(wall.ex) or wall.ok:
                self.commit(wall.ex, replaced.get(wall.ex, []) + lines)
        for wall in self.walls:
            for ex, words in wall.modifies if wall.ok else ():
                self.commit(ex, ["fix_modify %s %s" % (fid, " ".join(words))
                                 for fid, _ in wall.pieces])
        alive = {}
        for ex in self.deck.trace:
            w = ex.words
            if ex in self.wall_execs:
                alive[self.wall_execs[ex].id] = self.wall_execs[ex]
            elif w[0] == "unfix" and len(w) > 1 and w[1] in alive:
                wall = alive.pop(w[1])
                if wall.ok:
                    self.commit(ex, wall.unfix_lines())

    def replacements(self):
        """A wall made with the ID of a wall that is still there: LAMMPS replaces a fix by
        one of its style (Modify::add_fix). What goes first, {Exec: lines}: the old
        wall's fixes that the new one does not replace, all of them where one of the two
        stays LAMMPS's and the other is wall/rigid (LAMMPS refuses to replace a fix by
        one of another style)."""
        alive, out = {}, {}
        for ex in self.deck.trace:
            w = ex.words
            new = self.wall_execs.get(ex)
            if new is not None:
                old = alive.get(new.id)
                if old is not None and old.ok:
                    keep = {fid for fid, _ in new.pieces} if new.ok else set()
                    if new.ok and new.prev:
                        keep.add(new.prev)
                    out[ex] = [x for x in old.unfix_lines() if x.split()[1] not in keep]
                elif old is not None and new.ok:
                    out[ex] = ["unfix %s" % old.id]
                alive[new.id] = new
            elif w[0] == "unfix" and len(w) > 1:
                alive.pop(w[1], None)
        return out

    def rewrite_refs(self, commands):
        ok = {w.id for w in self.walls if w.ok and w.contacts}
        out = {}
        for cmd in commands:
            def sub(mt):
                if mt.group(1) in ok and mt.group(3) in ("2", "3", "4"):
                    return "f_force_%s[%d]" % (mt.group(1), int(mt.group(3)) - 1)
                return mt.group(0)
            lines = [REF.sub(sub, phys) if "f_" in phys else phys for phys in cmd.raw]
            if lines != cmd.raw:
                out[cmd] = lines
        return out

    def run(self):
        self.deck.follow()
        self.check_flow()
        self.scan()
        commands = [c for s in self.deck.sources.values() for c in s.commands]
        self.references(commands)
        self.decide()
        self.emit()
        self.refs_out = self.rewrite_refs([c for c in commands if c not in self.out])
        return self.text_of(self.deck.main)
