#!/usr/bin/python3
"""rigidsurf-migrate: a LIGGGHTS or LAMMPS deck's walls as `fix wall/rigid`
(docs/migration.md).

The deck is read and followed as LIGGGHTS runs it (rigidsurf_migrate_deck.py); each
`fix wall/gran` becomes wall/rigid (rigidsurf_migrate_walls.py), its mesh's `fix
move/mesh` lines the wall's rates (rigidsurf_migrate_motion.py), and every command that
names the wall or its mesh is kept working (rigidsurf_migrate_refs.py). Every other line
is copied byte for byte. A LAMMPS deck (detected, or --engine lammps) goes through
rigidsurf_migrate_lammps.py.
"""
import os
import sys

# The modules lie beside this file (source and build trees) or, installed, in
# share/rigidsurf.
_HERE = os.path.dirname(os.path.realpath(__file__))
sys.path[:0] = [_HERE, os.path.join(_HERE, "..", "share", "rigidsurf")]
import rigidsurf_migrate_commands as grammar  # noqa: E402
import rigidsurf_migrate_folds as folds  # noqa: E402
import rigidsurf_migrate_lammps as lammps  # noqa: E402
import rigidsurf_migrate_motion as motion  # noqa: E402
import rigidsurf_migrate_refs as refs  # noqa: E402
import rigidsurf_migrate_walls as walls  # noqa: E402
from rigidsurf_migrate_deck import Deck, DeckError, split_words  # noqa: E402

USAGE = """usage: rigidsurf-migrate DECK [--engine liggghts|lammps] [-var NAME VALUE ...]
           > DECK.rigid

Writes the LIGGGHTS deck DECK with its walls as `fix wall/rigid` (liggghts-rigidsurf):
each `fix wall/gran` primitive or mesh wall, its meshes, their `fix move/mesh` motion,
and what names them (f_ID[i] values, dumps of meshes, unfix, fix_modify). Every other
line is copied byte for byte. The deck is read as LIGGGHTS runs it: its variables
(`-var` as on LIGGGHTS's command line), formulas, `include` (a file with walls is
written into the deck in place of its include line), `jump`, `label`, `next` and `if`.
Reports go to stderr, one per line, each with its line number.

A LAMMPS deck (lmp-rigidsurf) likewise: each `fix wall/gran` plane or zcylinder and each
`fix wall/gran/region` becomes `fix wall/rigid` with `law lammps` and the same model
words on the exact surfaces of its wall or region, moving as LAMMPS moves it. The engine
is told by the deck's commands (LAMMPS's wall/gran/region, wall/gran hooke ... or
granular, pair_style granular; LIGGGHTS's wall/gran model, mesh/surface,
property/global, atom_style granular), or by --engine.

Exit status:
  0  every wall was migrated: the deck runs with liggghts-rigidsurf (lmp-rigidsurf) and
     reads the same quantities as with LIGGGHTS (LAMMPS) (NOTE lines name what differs
     in what it writes and where the walls' physics differs from the engine's:
     docs/migration.md)
  3  some walls are kept as the engine's, each listed with its line and the reason; the
     deck still runs with liggghts-rigidsurf (lmp-rigidsurf) as it runs with LIGGGHTS
     (LAMMPS)
  1  an error, named with its line (a deck the engine would stop at, control flow the
     tool cannot follow to a wall, a missing file, a usage error); nothing is written
"""
NUM = type("Num", (), {"value": staticmethod(walls.number)})()
MISSING = object()


def wall_related(words, ids):
    """Whether a command's words (as written) make, move, write or remove a wall or mesh."""
    if len(words) >= 4 and words[0] == "fix" and (
            words[3] in ("wall/gran", "move/mesh") or words[3].startswith("mesh/surface")):
        return True
    if len(words) >= 4 and words[0] == "dump" and words[3] in grammar.DUMP_MESH_STYLES:
        return True
    if len(words) >= 4 and words[0] == "compute" and words[3] == "wall/gran/local":
        return True
    if words[:1] and words[0] in ("unfix", "undump", "fix_modify") and len(words) > 1:
        return words[1] in ids or "$" in words[1]
    if words[:1] == ["if"]:
        return any(wall_related(split_words(c, None, strict=False), ids) for c in words[2:]
                   if c not in ("then", "elif", "else"))
    return False


class Migration:
    """A LIGGGHTS deck's migration (rigidsurf_migrate_lammps.py: a LAMMPS deck's)."""
    ENGINE, FIXES = "LIGGGHTS", "wall/gran fixes"
    wall_related = staticmethod(wall_related)

    def __init__(self, path, cli_vars=(), engine="liggghts"):
        self.deck = Deck(path, cli_vars, engine)
        self.reports, self.out, self.after = [], {}, {}
        self.meshes, self.walls, self.dumps = {}, [], []
        self.wall_execs, self.motion_lines, self.motion_state = {}, {}, {}
        self.heat, self.box_half = False, None

    # -- reports ------------------------------------------------------------------
    def report(self, cmd, text):
        """A line of stderr, sorted by file (in the order read) and line."""
        order = list(self.deck.sources).index(cmd.source.path)
        self.reports.append(((order, cmd.lineno), "%s: %s" % (cmd.where(), text)))

    def note(self, cmd, text):
        if text:
            self.report(cmd, "NOTE: " + text)

    @staticmethod
    def refuse_if(ex):
        raise DeckError(ex.via, "an if runs '%s': the tool rewrites a wall's commands where "
                        "they stand; write it as a line of its own" % " ".join(ex.words[:4]))

    def commit(self, ex, lines):
        """The text of ex's command: lines (None: as written); one text per command."""
        if ex.via is not None:
            self.refuse_if(ex)
        prev = self.out.get(ex.cmd, MISSING)
        if prev is not MISSING and prev != lines:
            raise DeckError(ex.cmd, "it runs more than once and would be written "
                            "differently each time (%s / %s)" % (
                                " | ".join(prev or ["as written"]),
                                " | ".join(x or "as written" for x in lines or [None])))
        self.out[ex.cmd] = lines

    def mesh_wall(self, fid):
        """The migrated mesh wall/gran of that ID, or None."""
        for w in self.walls:
            if w.id == fid and w.ok and w.kind == "mesh":
                return w
        return None

    # -- the deck -------------------------------------------------------------------
    def ids(self):
        out = set()
        for ex in self.deck.trace:
            w = ex.words
            if len(w) >= 4 and w[0] in ("fix", "dump", "compute") and \
                    self.wall_related(w, ()):
                out.add(w[1])
        return out

    def check_flow(self):
        """Control flow the tool does not follow must not decide a wall's commands."""
        ids = self.ids()
        for ex in self.deck.trace:
            if ex.via is not None and self.wall_related(ex.words, ids):
                self.refuse_if(ex)
        for cmd, reason, branches in self.deck.blind:
            for _, cmds in branches:
                for c in cmds:
                    if self.wall_related(split_words(c, cmd, strict=False), ids):
                        raise DeckError(cmd, "the tool cannot follow this if: its condition "
                                        "depends on the run (%s), and it decides whether "
                                        "'%s' runs" % (reason, c))
        if self.deck.stopped is None:
            return
        cmd, reason, stack, targets = self.deck.stopped
        starts = list(stack)
        for t in targets:
            starts += self.target(stack[-1][0], t, cmd)
        for c in self.reachable(starts, cmd):
            if self.wall_related(c.raw_words, ids):
                raise DeckError(cmd, "the tool cannot follow the deck past this line (%s), "
                                "and %s ('%s') may run after it" % (
                                    reason, c.where(), " ".join(c.raw_words[:4])))
        self.note(cmd, "the tool follows the deck up to this line (%s); no wall command "
                  "runs after it" % reason)

    def target(self, src, words, cmd):
        """Where a jump (its words after 'jump') may go on: [(source, command index)]; for
        a target the tool does not know, every file it has read."""
        if not words or any("$" in w for w in words):
            return [(s, 0) for s in list(self.deck.sources.values())]
        if words[0] != "SELF":
            path = self.deck.resolve(words[0])
            if path is None:
                return []
            src = self.deck.source(words[0], path, cmd)
        for c in src.commands:
            if len(words) > 1 and c.raw_words[:2] == ["label", words[1]]:
                return [(src, c.index)]
        return [(src, 0)]

    def reachable(self, starts, cmd):
        """The commands LIGGGHTS may run from the places starts, through includes and
        jumps, read as written."""
        seen, out, work = set(), [], list(starts)
        while work:
            src, pos = work.pop()
            for c in src.commands[pos:]:
                if c in seen:
                    break
                seen.add(c)
                out.append(c)
                w = c.raw_words
                if w[:1] == ["include"] and len(w) == 2:
                    work += self.target(src, w[1:], cmd)
                elif w[:1] == ["jump"] and len(w) > 1:
                    work += self.target(src, w[1:], cmd)
        return out

    def scan(self):
        alive, regions, self.cwl = {}, {}, set()
        for ex in self.deck.trace:
            w = ex.words
            c = w[0]
            if c == "fix" and len(w) >= 4:
                fid, style = w[1], w[3]
                self.heat |= style.startswith("heat/gran")
                if style.startswith("mesh/surface"):
                    m = walls.Mesh(ex, self.deck)
                    if fid in self.meshes and self.meshes[fid].cmd is not ex.cmd:
                        raise DeckError(ex.cmd, "mesh %s was made by %s before: the tool "
                                        "follows one definition of each mesh" % (
                                            fid, self.meshes[fid].cmd.where()))
                    self.meshes[fid] = alive[fid] = m
                elif style == "wall/gran":
                    self.wall(ex, alive)
                else:
                    if style == "move/mesh" and not (len(w) > 5 and isinstance(
                            alive.get(w[5]), walls.Mesh)):
                        raise DeckError(ex.cmd, "fix move/mesh expects 'mesh ID' of a fix "
                                        "mesh/surface made before it")
                    if style != "move/mesh":
                        self.uses(ex, alive)
                    alive[fid] = style
            elif c == "unfix" and len(w) > 1:
                alive.pop(w[1], None)
            elif c == "region" and len(w) >= 9 and w[2] == "block":
                regions[w[1]] = [walls.number(x) for x in w[3:9]]
            elif c == "create_box" and len(w) >= 3 and self.box_half is None:
                b = regions.get(w[2])
                if b and None not in b:
                    self.box_half = max(abs(x) for x in b)
            elif c == "dump" and len(w) >= 4 and w[3] in grammar.DUMP_MESH_STYLES:
                self.dumps.append(refs.Dump(ex, [k for k, v in alive.items()
                                                 if isinstance(v, walls.Mesh)]))
            elif c == "compute" and len(w) >= 4 and w[3] == "wall/gran/local":
                refs.cwl(self, ex, alive)
                self.cwl.add(w[1])
            elif c == "uncompute" and len(w) > 1:
                self.cwl.discard(w[1])
            elif c == "fix_modify" and len(w) > 2:
                m = alive.get(w[1])
                if isinstance(m, walls.Mesh) and w[2] != "energy":
                    m.reasons.append("%s: fix_modify %s has no wall/rigid counterpart" % (
                        ex.cmd.where(), " ".join(w[2:])))
            elif c == "clear" and self.walls:
                raise DeckError(ex.cmd, "the tool does not follow a deck past 'clear'")
            elif c not in ("unfix", "undump", "dump_modify", "uncompute"):
                self.uses(ex, alive)

    def wall(self, ex, alive):
        wall = walls.Wall(ex)
        if wall.kind == "mesh":
            for mid in wall.meshes:
                m = alive.get(mid)
                if not isinstance(m, walls.Mesh):
                    raise DeckError(ex.cmd, "fix %s: mesh %s is not a fix mesh/surface made "
                                    "before it (LIGGGHTS: could not find fix mesh id you "
                                    "provided)" % (wall.id, mid))
                m.walls.append(wall)
                wall.mesh_objs.append(m)
            if self.cwl:
                wall.reasons.append("compute %s (wall/gran/local) reads the contacts of the "
                                    "mesh walls made while it exists" % " ".join(self.cwl))
        elif wall.kind is None:
            raise DeckError(ex.cmd, "fix %s: expects 'primitive' or 'mesh' (LIGGGHTS: Need to "
                            "use define style 'mesh' or 'primitive')" % wall.id)
        self.walls.append(wall)
        self.wall_execs[ex] = wall
        alive[wall.id] = wall

    def uses(self, ex, alive):
        for word in ex.words[1:]:
            m = alive.get(word)
            if isinstance(m, walls.Mesh) and ex not in m.users:
                m.users.append(ex)

    # -- decisions ------------------------------------------------------------------
    def decide(self):
        for m in self.meshes.values():
            if len({w.cmd for w in m.walls}) > 1:
                m.reasons.append("%d wall/gran fixes use it" % len({w.cmd for w in m.walls}))
            if m.group != "all" and any(m.group != w.group for w in m.walls):
                m.reasons.append("its group %s is not its wall's" % m.group)
        self.settle()
        refs.dumps(self)
        self.settle()
        for m in self.meshes.values():
            if m.ok and m.users:
                m.display, m.rid = True, "rs_" + m.id

    def settle(self):
        for wall in self.walls:
            reasons = list(wall.reasons)
            for m in wall.mesh_objs:
                reasons += ["mesh %s (%s): %s" % (m.id, m.cmd.where(), r) for r in m.reasons]
            wall.ok = not reasons
            wall.why = reasons
        for m in self.meshes.values():
            m.ok = bool(m.walls) and all(w.ok for w in m.walls)
            m.wall = m.walls[0] if m.walls else None

    # -- output -------------------------------------------------------------------
    def emit(self):
        L, with_L = walls.half_length(self.box_half), None
        for wall in self.walls:
            if not wall.ok:
                for r in wall.why:
                    self.report(wall.cmd, "fix %s: %s" % (wall.id, r))
                self.report(wall.cmd, "fix %s: the wall is kept as %s's" % (wall.id,
                                                                          self.ENGINE))
                continue
            for n in wall.notes:
                self.note(wall.cmd, "fix %s: %s" % (wall.id, n))
            if wall.kind == "primitive":
                lines = []
                if L is None and with_L in (None, wall.cmd):
                    # the box's size where create_box's region is not known, before the
                    # first such wall
                    lines.append("variable rs_L equal 10*(abs(xlo)+abs(xhi)+abs(ylo)+"
                                 "abs(yhi)+abs(zlo)+abs(zhi))")
                    with_L = wall.cmd
                lines.append(walls.primitive(wall, L or "${rs_L}", self.heat))
            else:
                lines = []
                for m in wall.mesh_objs:
                    lines += walls.mesh_wall(wall, m, self.motion_state[m.id], self.heat)
                    self.mesh(m)
            self.commit(wall.ex, lines)
        refs.unfixes(self)
        for ex, lines in self.motion_lines.items():
            self.commit(ex, lines)
        removed = set()
        for d in self.dumps:
            lines = refs.dump_lines(self, d)
            if lines is not None:
                self.commit(d.ex, lines)
                if not lines:
                    removed.add(d.id)
        for ex in self.deck.trace:
            if ex.words[0] in ("undump", "dump_modify") and len(ex.words) > 1 and \
                    ex.words[1] in removed:
                self.commit(ex, [])
                if ex.words[0] == "undump":
                    self.note(ex.cmd, "undump %s: the walls that write its meshes' vtk go on "
                              "writing it" % ex.words[1])
        refs.notes_for_dumps(self)

    def mesh(self, m):
        """A migrated mesh's lines: gone, or kept as a LIGGGHTS mesh for the commands that
        use it; its move/mesh lines become the wall's rates."""
        if not m.display:
            self.commit(m.ex, [])
        elif m.users:
            self.note(m.cmd, "mesh %s stays a LIGGGHTS mesh, without a wall, for %s; its wall "
                      "is wall/rigid %s" % (m.id, ", ".join(sorted({
                          "%s (%s)" % (u.cmd.where(), " ".join(u.words[:4]))
                          for u in m.users})), m.rid))
        for n in m.notes:
            self.note(m.cmd, "fix %s: %s" % (m.id, n))
        if m.path:
            text = folds.note(m.path)
            if text:
                self.note(m.cmd, "mesh %s (%s): %s" % (m.id, m.file, text))
        for ex, lines in self.motion_state[m.id]["lines"].items():
            self.motion_lines[ex] = ([None] if m.display else []) + lines

    def render(self, cmd, lines):
        """The text of a rewritten command: its lines, its comment on the last of them (or
        on a line of its own), its line ending."""
        lines = ["".join(cmd.raw).rstrip("\r\n") if x is None else x for x in lines]
        lines += list(self.after.get(cmd, {}).values())
        if cmd.comment:
            if lines and lines[-1] is not None:
                lines[-1] += " " + cmd.comment
            else:
                lines = [cmd.comment]
        nl = "\n" if cmd.raw[-1].endswith("\n") else ""
        return "\n".join(lines) + (nl if lines else "")

    def changed(self, src, seen=()):
        if src.path in seen:
            return False
        seen = seen + (src.path,)
        incl = getattr(src, "includes", {})
        return any(c in self.out or c in self.refs_out for c in src.commands) or any(
            self.changed(self.deck.sources[p], seen) for p in incl.values())

    def text_of(self, src):
        parts = []
        incl = getattr(src, "includes", {})
        for p in getattr(src, "jumps", ()):
            if p != src.path and self.changed(self.deck.sources[p]):
                raise DeckError(None, "%s jumps to %s, whose walls the tool would rewrite: "
                                "migrate it on its own" % (src.name or "the deck",
                                                           self.deck.sources[p].name))
        for cmd in src.commands:
            if cmd in self.out:
                parts.append(self.render(cmd, self.out[cmd]))
            elif cmd.index in incl and self.changed(self.deck.sources[incl[cmd.index]]):
                inc = self.deck.sources[incl[cmd.index]]
                if any(c.raw_words[:1] in (["jump"], ["label"]) for c in inc.commands):
                    raise DeckError(cmd, "the included %s holds walls and jump or label: "
                                    "the tool writes an included file into the deck, where "
                                    "its jumps would mean the deck" % inc.name)
                body = self.text_of(inc)
                parts.append("# rigidsurf-migrate: %s, migrated\n%s%s"
                             "# rigidsurf-migrate: end of %s\n" % (
                                 cmd.text.strip(), body, "" if body.endswith("\n") or
                                 not body else "\n", inc.name))
                self.note(cmd, "%s holds walls or their names: its commands, migrated, "
                          "stand in the deck in place of this line" % inc.name)
            elif cmd in self.refs_out:
                parts.append("".join(self.refs_out[cmd]))
            else:
                parts.append("".join(cmd.raw))
        return "".join(parts)

    def run(self):
        self.deck.follow()
        self.check_flow()
        self.scan()
        motion.follow(self, NUM, walls.fmt)
        for m in self.meshes.values():
            self.motion_state.setdefault(m.id, motion.blank())
        commands = [c for s in self.deck.sources.values() for c in s.commands]
        refs.references(self, commands)
        self.decide()
        self.emit()
        self.refs_out = refs.rewrite_references(self, [c for c in commands
                                                       if c not in self.out])
        return self.text_of(self.deck.main)


def main(argv):
    args = argv[1:]
    if args[:1] in (["-h"], ["--help"]):
        sys.stdout.write(USAGE)
        return 0
    if not args:
        sys.stderr.write(USAGE)
        return 1
    path, cli_vars, k, engine = args[0], [], 1, None
    while k < len(args):
        if args[k] == "--engine":
            if k + 1 >= len(args) or args[k + 1] not in ("liggghts", "lammps"):
                sys.stderr.write("rigidsurf-migrate: --engine expects liggghts or lammps, "
                                 "got '%s'\n" % (args[k + 1] if k + 1 < len(args) else ""))
                return 1
            engine = args[k + 1]
            k += 2
        elif args[k] in ("-var", "-v") and k + 1 < len(args):
            j = k + 2
            while j < len(args) and not args[j].startswith("-"):
                j += 1
            cli_vars.append((args[k + 1], args[k + 2:j]))
            k = j
        else:
            sys.stderr.write("rigidsurf-migrate: unknown argument '%s'\n%s" % (args[k], USAGE))
            return 1
    if not os.path.isfile(path):
        sys.stderr.write("rigidsurf-migrate: %s: no such file\n" % path)
        return 1
    try:
        engine = engine or lammps.detect_engine(path)
        mg = (LammpsMigration if engine == "lammps" else Migration)(path, cli_vars)
        out = mg.run()
    except DeckError as e:
        where = e.where.where() if e.where is not None else os.path.basename(path)
        sys.stderr.write("rigidsurf-migrate: %s: ERROR: %s\nrigidsurf-migrate: nothing "
                         "written\n" % (where, e))
        return 1
    for name, text in sorted(getattr(mg, "files", {}).items()):
        with open(name, "w") as f:
            f.write(text)
    sys.stdout.write(out)
    done = set()
    for _, text in sorted(mg.reports, key=lambda r: r[0]):
        if text not in done:
            sys.stderr.write(text + "\n")
        done.add(text)
    lines = {w.cmd for w in mg.walls}
    ok = lines - {w.cmd for w in mg.walls if not w.ok}
    kept = len(lines) - len(ok)
    sys.stderr.write("rigidsurf-migrate: %d of %d %s translated%s\n" % (
        len(ok), len(lines), mg.FIXES, "; %d kept as %s's (above)" % (kept, mg.ENGINE)
        if kept else ""))
    return 3 if kept else 0


class LammpsMigration(lammps.LammpsMigration, Migration):
    """A LAMMPS deck's migration."""


if __name__ == "__main__":
    sys.exit(main(sys.argv))
