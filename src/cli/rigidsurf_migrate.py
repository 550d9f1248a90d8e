#!/usr/bin/python3
"""rigidsurf-migrate DECK > DECK.rigid

Rewrites the walls of a LIGGGHTS deck into `fix wall/rigid` (docs/migration.md):

- `fix wall/gran ... primitive type T xplane|yplane|zplane|xcylinder|ycylinder|zcylinder`
  becomes one `fix wall/rigid` with the same ID, acting on both sides (`sides 2`);
- `fix wall/gran ... mesh n_meshes K meshes M1 .. MK` with its `fix mesh/surface` (or
  `mesh/surface/stress`, `mesh/surface/planar`) lines becomes one `fix wall/rigid` per
  mesh, each with the ID of its mesh fix, at the place of the `wall/gran` line; the
  mesh lines go;
- `fix move/mesh` (linear, linear/variable, wiggle, viblin, rotate, rotate/variable,
  riggle, vibrot) and the `unfix` of it become `variable` lines that set the wall's
  rates (`v_rs_MESH_vx` ...; rigidsurf_migrate_motion.py);
- `shear` of a primitive wall along a plane or a cylinder's axis becomes `surface_vel`;
- a wall's `temperature` under `fix heat/gran` gets `conduction liggghts` (LIGGGHTS's wall
  conduction) with the wall/gran's `contact_area`, `store_force yes` becomes `store_force yes` (`store_force into ID` on the
  walls of a wall/gran's meshes), so `f_force_ID[1-3]` read the same vector;
- `dump mesh/gran/VTK` of one migrated mesh becomes the wall's `vtk FILE N`.

Every other line is copied byte for byte, comments included. What the tool cannot
translate it keeps as written and says so on stderr, with the line number. Exit status:
0 when every wall was translated, 3 when some were kept as LIGGGHTS's (or a reference
to a wall could not be kept), 2 on a usage or read error.
"""
import math
import os
import re
import sys

# The motion module lies beside this file (source and build trees) or, installed, in
# share/rigidsurf.
_HERE = os.path.dirname(os.path.realpath(__file__))
sys.path[:0] = [_HERE, os.path.join(_HERE, "..", "share", "rigidsurf")]
import rigidsurf_migrate_motion as motion  # noqa: E402

EXIT_KEPT = 3
LAWS = {"hertz": "hertz", "hooke": "hooke"}
# fix wall/gran's own keywords after the wall style (not contact-model settings)
WALL_KEYWORDS = ("temperature", "shear", "store_force", "store_force_contact",
                 "store_force_contact_every", "store_force_contact_stress",
                 "contact_area", "track_energy", "compute_wall_gran_local",
                 "sum_normal_force", "primitive", "mesh", "type", "n_meshes", "meshes")
MESH_STYLES = ("mesh/surface", "mesh/surface/stress", "mesh/surface/planar",
               "mesh/surface/stress/servo")
# the servo's words and how many values each takes (LIGGGHTS's mesh module servo)
SERVO_WORDS = {"com": 3, "ctrlPV": 1, "axis": 3, "target_val": 1, "vel_max": 1, "kp": 1,
               "ki": 1, "kd": 1, "mode": 1, "ratio": 1}
MESH_FILE_EXT = (".stl", ".obj", ".off", ".ply")
HEAT_FIXES = re.compile(r"^heat/gran")
FLOW = ("jump", "label", "next", "include", "if", "loop")
WRAP = 88


# ---- the deck ------------------------------------------------------------------------

class Cmd:
    """One command: its physical lines (raw, newlines included), first line number,
    words (continuations joined, the comment cut) and the trailing comment."""

    def __init__(self, lineno, raw):
        self.lineno = lineno
        self.raw = raw
        joined = ""
        for phys in raw:
            s = phys.rstrip("\r\n")
            t = s.rstrip()
            joined += (t[:-1] + " ") if t.endswith("&") else s
        self.comment = ""
        cut = _comment_start(joined)
        if cut is not None:
            self.comment = joined[cut:].rstrip()
            joined = joined[:cut]
        self.words = joined.split()

    def word(self, i):
        return self.words[i] if i < len(self.words) else None


def _comment_start(text):
    quote = None
    for i, ch in enumerate(text):
        if quote:
            if ch == quote:
                quote = None
        elif ch in "\"'":
            quote = ch
        elif ch == "#":
            return i
    return None


def read_deck(text):
    """The deck's commands, in order; the physical lines of all of them are the text."""
    lines = text.splitlines(keepends=True)
    cmds, i = [], 0
    while i < len(lines):
        j = i
        while j < len(lines) - 1 and lines[j].rstrip().endswith("&") \
                and _comment_start(lines[j]) is None:
            j += 1
        cmds.append(Cmd(i + 1, lines[i:j + 1]))
        i = j + 1
    return cmds


# ---- numbers the deck computes -------------------------------------------------------

class Numbers:
    """Values of the deck's numeric variables as LIGGGHTS sets them (equal, index,
    internal, constant forms), in deck order; None where it cannot know them."""

    def __init__(self):
        self.vars = {}

    def define(self, words):
        if len(words) >= 4 and words[2] in ("equal", "index", "internal"):
            self.vars[words[1]] = self.value(" ".join(words[3:]).strip("\"'"))
        elif len(words) >= 2:
            self.vars[words[1]] = None

    def value(self, text):
        """A number from a word or formula of numbers, ${x}, $(...), v_x, PI, + - * / ^."""
        if text is None:
            return None
        t = re.sub(r"\$\{(\w+)\}|\bv_(\w+)|\$(\w)",
                   lambda m: self._sub(m.group(1) or m.group(2) or m.group(3)), text)
        if "?" in t:
            return None
        t = t.replace("$(", "(").replace("PI", "(%r)" % math.pi).replace("^", "**")
        if not re.fullmatch(r"[0-9eE+\-*/(). ]+", t):
            return None
        try:
            v = float(eval(t, {"__builtins__": {}}, {}))
        except Exception:
            return None
        return v if math.isfinite(v) else None

    def _sub(self, name):
        v = self.vars.get(name)
        return "?" if v is None else "(%r)" % v


def fmt(v):
    """A computed coordinate, to 12 significant digits, without a negative zero."""
    if abs(v) < 1e-12:
        return "0"
    s = "%.12g" % v
    return s


# ---- placement -----------------------------------------------------------------------

def rot(axis, deg):
    ax = math.sqrt(sum(c * c for c in axis))
    x, y, z = (c / ax for c in axis)
    a = math.radians(deg)
    c, s, C = math.cos(a), math.sin(a), 1 - math.cos(a)
    return [[c + x * x * C, x * y * C - z * s, x * z * C + y * s],
            [y * x * C + z * s, c + y * y * C, y * z * C - x * s],
            [z * x * C - y * s, z * y * C + x * s, c + z * z * C]]


def matvec(m, v):
    return [sum(m[i][k] * v[k] for k in range(3)) for i in range(3)]


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def compose_placement(ops):
    """LIGGGHTS's `scale s`, `move m`, `rotate axis A angle θ` applied in the order given
    (each about the global origin), as wall/rigid's scale s and place a b c:
    x = a + s (X ex + Y ey + Z ez), a the image of the file's origin, b = a + ex,
    c = a + ey. ops: ("scale", s) | ("move", (x, y, z)) | ("rotate", (ax, ay, az), θ)."""
    s, R, t = 1.0, [[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]], [0.0, 0.0, 0.0]
    for op in ops:
        if op[0] == "scale":
            s *= op[1]
            t = [op[1] * c for c in t]
        elif op[0] == "move":
            t = [c + m for c, m in zip(t, op[1])]
        else:
            r = rot(op[1], op[2])
            R, t = matmul(r, R), matvec(r, t)
    ex = [R[i][0] for i in range(3)]
    ey = [R[i][1] for i in range(3)]
    return s, t, [a + e for a, e in zip(t, ex)], [a + e for a, e in zip(t, ey)]


# ---- primitive walls ------------------------------------------------------------------

def shear(shape, dim, v):
    """wall/gran's `shear DIM V` of a primitive wall as wall/rigid's surface_vel, or why
    not. LIGGGHTS (fix_wall_gran.cpp) gives every contact the wall velocity V along DIM
    when DIM is the cylinder's axis or the wall is a plane (the wall does not move, its
    material slides); along a plane's tangent, or a cylinder's axis, that is surface_vel
    V e_DIM. Along a plane's normal it is a velocity into the wall, and for a cylinder
    with DIM across its axis LIGGGHTS turns it into (V e_axis) x r of the particle's
    centre: neither has a wall/rigid counterpart."""
    if dim not in ("x", "y", "z") or shape is None:
        return ("wall/gran keyword 'shear %s' has no wall/rigid counterpart (it needs a "
                "primitive wall and x, y or z)" % dim)
    if shape.endswith("plane") and shape[0] == dim:
        return ("shear %s of %s is a velocity along the plane's normal: wall/rigid's "
                "surface_vel slides in the tangent plane only" % (dim, shape))
    if shape.endswith("cylinder") and shape[0] != dim:
        return ("shear %s of %s is LIGGGHTS's spin (%s e_%s) x r about the axis, at the "
                "particle's centre: wall/rigid has no counterpart" % (dim, shape, v, shape[0]))
    return [v if d == dim else "0" for d in "xyz"]


# ---- the tool ------------------------------------------------------------------------

class Migration:
    def __init__(self, text):
        self.cmds = read_deck(text)
        self.reports = []          # (lineno, text, kept)
        self.out = {}              # cmd index -> replacement text ("" removes)
        self.num = Numbers()

    def report(self, cmd, fid, text, kept=True):
        self.reports.append((cmd.lineno, "LINE %d: %s%s" % (
            cmd.lineno, ("fix %s: " % fid) if fid else "", text), kept))

    # -- pass 1: what the deck holds ---------------------------------------------------
    def scan(self):
        self.meshes, self.walls, self.heat = {}, [], False
        self.box_half = None
        regions = {}
        for i, c in enumerate(self.cmds):
            w = c.words
            if not w:
                continue
            if w[0] == "variable":
                self.num.define(w)
            elif w[0] == "region" and len(w) >= 9 and w[2] == "block":
                regions[w[1]] = [self.num.value(x) for x in w[3:9]]
            elif w[0] == "create_box" and len(w) >= 3 and self.box_half is None:
                b = regions.get(w[2])
                if b and None not in b:
                    self.box_half = max(abs(x) for x in b)
            elif w[0] == "fix" and len(w) >= 4:
                style = w[3]
                if HEAT_FIXES.match(style):
                    self.heat = True
                if style.startswith("mesh/surface"):
                    self.meshes[w[1]] = self.parse_mesh(i, c)
                elif style == "wall/gran":
                    self.walls.append(self.parse_wall(i, c))

    def parse_mesh(self, i, c):
        w, m = c.words, dict(index=i, cmd=c, id=c.words[1], ops=[], opts={}, reasons=[],
                             notes=[], type="1", stress=c.words[3] != "mesh/surface",
                             wear=None, refpoint=None, used=[])
        if w[3] not in MESH_STYLES:
            m["reasons"].append("%s has no wall/rigid counterpart yet" % w[3])
        k = 4
        try:
            while k < len(w):
                key = w[k]
                if key == "file":
                    m["file"] = w[k + 1]
                    k += 2
                elif key == "type":
                    m["type"] = w[k + 1]
                    k += 2
                elif key == "scale":
                    m["ops"].append(("scale", w[k + 1]))
                    k += 2
                elif key == "move":
                    m["ops"].append(("move", w[k + 1:k + 4]))
                    k += 4
                elif key == "rotate" and w[k + 1] == "axis" and w[k + 5] == "angle":
                    m["ops"].append(("rotate", w[k + 2:k + 5], w[k + 6]))
                    k += 7
                elif key == "temperature":
                    m["opts"]["temperature"] = [w[k + 1]]
                    k += 2
                elif key == "surface_vel":
                    m["opts"]["surface_vel"] = w[k + 1:k + 4]
                    k += 4
                elif key in ("curvature", "curvature_tolerant", "precision", "heal",
                             "verbose", "min_feature_length"):
                    m["notes"].append("mesh/surface's %s %s is not needed: wall/rigid finds "
                                      "a face's, edge's or vertex's contact from the geometry "
                                      "and welds and checks the mesh itself; left out"
                                      % (key, w[k + 1]))
                    k += 2
                elif key == "wear" and m["stress"]:
                    if w[k + 1] not in ("finnie", "off"):
                        m["reasons"].append("wear %s has no wall/rigid counterpart" % w[k + 1])
                    m["wear"] = w[k + 1]
                    k += 2
                elif key == "stress" and m["stress"]:
                    k += 2
                elif key == "reference_point" and m["stress"]:
                    m["refpoint"] = w[k + 1:k + 4]
                    k += 4
                elif key in SERVO_WORDS and w[3] == "mesh/surface/stress/servo":
                    n = SERVO_WORDS[key]
                    if len(w) < k + 1 + n:
                        raise IndexError
                    m.setdefault("servo", []).extend(w[k:k + 1 + n])
                    k += 1 + n
                else:
                    m["reasons"].append("mesh/surface keyword '%s' has no wall/rigid "
                                        "counterpart yet" % key)
                    break
        except IndexError:
            m["reasons"].append("its line ends inside a keyword")
        ops, vals = [], []
        for op in m["ops"]:
            if op[0] == "scale":
                ops.append(("scale", self.num.value(op[1])))
                vals.append(ops[-1][1])
            elif op[0] == "move":
                ops.append(("move", [self.num.value(x) for x in op[1]]))
                vals += ops[-1][1]
            else:
                ops.append(("rotate", [self.num.value(x) for x in op[1]],
                            self.num.value(op[2])))
                vals += ops[-1][1] + [ops[-1][2]]
        if None in vals:
            m["reasons"].append("its scale, move or rotate uses values the tool cannot "
                                "compute")
        else:
            m["placement"] = compose_placement(ops)
        f = m.get("file")
        if f is None:
            m["reasons"].append("a mesh not read from a file has no wall/rigid counterpart")
        elif not f.lower().endswith(MESH_FILE_EXT):
            m["reasons"].append("wall/rigid reads STL, OBJ, OFF or PLY meshes, not '%s'" % f)
        return m

    def parse_wall(self, i, c):
        w = c.words
        wall = dict(index=i, cmd=c, id=w[1], group=w[2], reasons=[], law=None, vtk=None)
        k, model = 4, []
        while k + 1 < len(w) and w[k] in ("model", "tangential", "cohesion",
                                          "rolling_friction", "surface"):
            model += w[k:k + 2]
            k += 2
        words = dict(zip(model[::2], model[1::2]))
        law = None
        if not model and k < len(w) and w[k] not in ("primitive", "mesh"):
            wall["reasons"].append("the old wall/gran arguments ('%s ...') have no wall/rigid "
                                   "law yet" % " ".join(w[4:8]))
        else:
            plain = words.get("tangential", "history") == "history" and \
                words.get("cohesion", "off") == "off" and \
                words.get("rolling_friction", "off") == "off" and \
                words.get("surface", "default") == "default"
            law = LAWS.get(words.get("model", "hertz")) if plain else None
            surface = words.get("surface", "default")
            if surface != "default":
                wall["reasons"].append(
                    "model words '%s': surface %s needs LIGGGHTS's own wall (%s); law "
                    "liggghts takes the default surface model only" % (
                        " ".join(model), surface,
                        "the expanded radii of fix multicontact/halfspace"
                        if surface == "multicontact" else "superquadric particles"))
            elif law is None:
                # any other combination: LIGGGHTS's own model through law liggghts
                law = " ".join(["liggghts"] + (model if "model" in words
                                                else ["model", "hertz"] + model))
        wall["law"] = law
        rest = w[k:]
        if rest[:1] == ["primitive"]:
            wall["kind"] = "primitive"
            self.parse_primitive(wall, rest[1:])
        elif rest[:1] == ["mesh"]:
            wall["kind"] = "mesh"
            self.parse_wall_meshes(wall, rest[1:])
        elif not wall["reasons"]:
            wall["kind"] = None
            wall["reasons"].append("no 'primitive' or 'mesh' wall style")
        return wall

    def general(self, wall, rest):
        """The general and model keywords after the wall style's own arguments."""
        k, opts = 0, {}
        while k < len(rest):
            key = rest[k]
            if key == "temperature" and k + 1 < len(rest):
                opts["temperature"] = [rest[k + 1]]
                k += 2
            elif key == "contact_area" and rest[k + 1:k + 2] in (["overlap"], ["projection"]):
                opts["contact_area"] = [rest[k + 1]]
                k += 2
            elif key == "contact_area" and rest[k + 1:k + 2] == ["constant"] and \
                    k + 2 < len(rest):
                opts["contact_area"] = rest[k + 1:k + 3]
                k += 3
            elif key == "store_force" and k + 1 < len(rest) and rest[k + 1] == "yes":
                opts["store_force"] = ["yes"]
                k += 2
            elif key == "shear" and k + 2 < len(rest):
                vel = shear(wall.get("shape"), rest[k + 1], rest[k + 2])
                if isinstance(vel, str):
                    wall["reasons"].append(vel)
                else:
                    opts["surface_vel"] = vel
                k += 3
            elif key in ("store_force", "store_force_contact", "store_force_contact_stress") \
                    and k + 1 < len(rest) and rest[k + 1] == "no":
                k += 2
            elif k + 1 < len(rest) and wall["law"] and rest[k] not in WALL_KEYWORDS:
                # a setting of the contact model (tangential_damping off, limitForce on,
                # ...): LIGGGHTS's model takes it through law liggghts
                law = wall["law"]
                if not law.startswith("liggghts"):
                    law = "liggghts model %s tangential history" % law
                wall["law"] = law + " " + " ".join(rest[k:k + 2])
                k += 2
            else:
                wall["reasons"].append("wall/gran keyword '%s' has no wall/rigid counterpart "
                                       "yet" % " ".join(rest[k:k + 2]))
                break
        return opts

    def parse_primitive(self, wall, r):
        shapes = {"xplane": 1, "yplane": 1, "zplane": 1,
                  "xcylinder": 3, "ycylinder": 3, "zcylinder": 3}
        if len(r) < 4 or r[0] != "type" or r[2] not in shapes or \
                len(r) < 3 + shapes[r[2]]:
            wall["reasons"].append("primitive arguments '%s' not understood" % " ".join(r))
            return
        wall["type"], wall["shape"] = r[1], r[2]
        n = shapes[r[2]]
        wall["args"] = r[3:3 + n]
        wall["opts"] = self.general(wall, r[3 + n:])

    def parse_wall_meshes(self, wall, r):
        try:
            assert r[0] == "n_meshes" and r[2] == "meshes"
            n = int(r[1])
            wall["meshes"] = r[3:3 + n]
            assert len(wall["meshes"]) == n
        except (AssertionError, IndexError, ValueError):
            wall["reasons"].append("mesh arguments '%s' not understood" % " ".join(r))
            wall["meshes"] = []
            return
        wall["opts"] = self.general(wall, r[3 + n:])
        for mid in wall["meshes"]:
            m = self.meshes.get(mid)
            if m is None:
                wall["reasons"].append("mesh %s is not a fix mesh/surface defined before it"
                                       % mid)
            else:
                m["used"].append(wall)

    # -- pass 2: motion, in deck order -------------------------------------------------
    def motion(self):
        """Every fix move/mesh of the meshes, in deck order (rigidsurf_migrate_motion)."""
        motion.follow(self, Numbers, FLOW, fmt)

    # -- pass 3: who else names a mesh or a wall ----------------------------------------
    def uses(self):
        """Commands other than the wall's own that name a mesh (they need LIGGGHTS's mesh:
        the wall stays), and dumps of meshes."""
        self.dumps = []
        own = {m["index"] for m in self.meshes.values()} | {w["index"] for w in self.walls}
        for i, c in enumerate(self.cmds):
            w = c.words
            if i in own or not w or w[0] == "unfix":
                continue
            if w[0] == "fix" and len(w) > 5 and w[3] == "move/mesh":
                continue
            if w[0] == "dump" and len(w) > 5 and w[3] in ("mesh/gran/VTK", "mesh/vtk"):
                self.dumps.append((i, c))
                continue
            for word in w[1:]:
                m = self.meshes.get(word)
                if m is not None and m["used"]:
                    m["reasons"].append("LINE %d (%s) uses it as a LIGGGHTS mesh"
                                        % (c.lineno, " ".join(w[:4])))

    def decide(self):
        for m in self.meshes.values():
            if len(m["used"]) > 1:
                m["reasons"].append("%d wall/gran fixes use it" % len(m["used"]))
            if m["cmd"].words[2] not in ("all", ) and m["used"] and \
                    m["cmd"].words[2] != m["used"][0]["group"]:
                m["reasons"].append("its group %s is not its wall's" % m["cmd"].words[2])
        for wall in self.walls:
            reasons = list(wall["reasons"])
            if wall.get("kind") == "mesh":
                for mid in wall["meshes"]:
                    m = self.meshes.get(mid)
                    for r in (m["reasons"] if m else []):
                        reasons.append("mesh %s (LINE %d): %s" % (mid, m["cmd"].lineno, r))
            wall["ok"] = not reasons
            if not wall["ok"]:
                for r in reasons:
                    self.report(wall["cmd"], wall["id"], r)
                self.report(wall["cmd"], wall["id"], "the wall is kept as LIGGGHTS's")
        self.done = {mid for wall in self.walls if wall["ok"] and wall["kind"] == "mesh"
                     for mid in wall["meshes"]}

    # -- output --------------------------------------------------------------------------
    def half_length(self, lines):
        """L, the half-length of a plane's LINE and a cylinder's: past the box."""
        if self.box_half is not None and self.box_half > 0:
            return fmt(10.0 ** math.ceil(math.log10(4 * self.box_half)))
        if not self.defined_L:
            lines.append("variable rs_L equal 10*(abs(xlo)+abs(xhi)+abs(ylo)+abs(yhi)"
                         "+abs(zlo)+abs(zhi))")
            self.defined_L = True
        return "${rs_L}"

    def primitive(self, wall):
        lines = []
        L = self.half_length(lines)
        mL = L[1:] if L.startswith("-") else "-" + L
        shape, args = wall["shape"], wall["args"]
        if shape.endswith("plane"):
            X = args[0]
            a, b, c = {"x": ([X, 0, 0], [X, 1, 0], [X, 0, -1]),
                       "y": ([0, X, 0], [0, X, 1], [-1, X, 0]),
                       "z": ([0, 0, X], [1, 0, X], [0, -1, X])}[shape[0]]
            surf = (["cylinder", "a"] + a + ["b"] + b + ["c"] + c +
                    ["sides", "2", "profile", "START", mL, "0", "LINE", L, "0", "end"])
        else:
            R, c1, c2 = args
            origin, axis = {"x": ([0, c1, c2], [1, 0, 0]), "y": ([c2, 0, c1], [0, 1, 0]),
                            "z": ([c1, c2, 0], [0, 0, 1])}[shape[0]]
            surf = (["revolution", "origin"] + origin + ["axis"] + axis +
                    ["sides", "2", "profile", "START", R, mL, "LINE", R, L, "end"])
        words = ["fix", wall["id"], wall["group"], "wall/rigid", "surface", "inline"] + \
            surf + ["law"] + wall["law"].split() + ["type", wall["type"]]
        for key, vals in wall["opts"].items():
            if key != "contact_area":
                words += [key] + vals
        words += self.conduction(wall["opts"], wall["opts"])
        return lines + [wrap(words)]

    def conduction(self, opts, wall_opts):
        """A wall's temperature under fix heat/gran conducts heat into the particles that
        touch it (fix_wall_gran.cpp, addHeatFlux): wall/rigid's conduction liggghts, with
        the wall/gran's contact_area (which sets that conduction's area only)."""
        if "temperature" not in opts or not self.heat:
            return []
        area = wall_opts.get("contact_area")
        return ["conduction", "liggghts"] + (["contact_area"] + area if area else [])

    def mesh_wall(self, wall, m):
        s = self.motion_state[m["id"]]
        scale, a, b, c = m["placement"] if m.get("placement") else (1.0, None, None, None)
        words = ["fix", m["id"], wall["group"], "wall/rigid", "surface", "inline", "mesh",
                 m["file"]]
        if scale != 1.0:
            words += ["scale", fmt(scale)]
        if a is not None and [fmt(x) for x in a + b + c] != \
                ["0", "0", "0", "1", "0", "0", "0", "1", "0"]:
            words += ["place"] + [fmt(x) for x in a + b + c]
        words += ["law"] + wall["law"].split() + ["type", m["type"]]
        for key, vals in m["opts"].items():
            words += [key] + vals
        words += self.conduction(m["opts"], wall["opts"])
        if wall["opts"].get("store_force"):
            # wall/gran keeps one force_ID for all its meshes: each mesh's wall adds to it
            words += ["store_force", "into", wall["id"]]
        if m["wear"] == "finnie":
            words += ["wear", "finnie"]
        if m.get("vtk"):
            words += ["vtk"] + m["vtk"]
        if m.get("servo"):
            words += ["servo"] + m["servo"]
        pre = []
        if s["lin_used"]:
            words += ["move", "linear"] + ["v_rs_%s_%s" % (m["id"], k) for k in ("vx", "vy",
                                                                              "vz")]
        if s["rot"] is not None and s["centre"] == "fixed":
            # the origin where LIGGGHTS's first mover keeps it, in space
            words += ["rotate", "origin"] + list(s["rot"][4]) + ["axis"] + list(s["rot"][1]) \
                + ["omega", "v_rs_%s_om" % m["id"], "centre", "fixed"]
        elif s["rot"] is not None:
            words += ["rotate", "origin"] + list(s["rot"][0]) + ["axis"] + list(s["rot"][1]) \
                + ["omega", "v_rs_%s_om" % m["id"]]
        if s["spin"] is not None:
            words += ["spin", "origin"] + list(s["spin"][0]) + ["axis"] + list(s["spin"][1]) \
                + ["omega", "v_rs_%s_om2" % m["id"]]
        used = (["vx", "vy", "vz"] if s["lin_used"] else []) + (["om"] if s["rot"] else []) \
            + (["om2"] if s["spin"] is not None else [])
        for k in used:
            if k not in s["pre_wall"]:
                pre.append("variable rs_%s_%s equal 0" % (m["id"], k))
        return pre + [wrap(words)]

    def emit(self):
        self.defined_L = False
        self.out = {}
        for m in self.meshes.values():
            for n in m["notes"]:
                if m["id"] in self.done:
                    self.report(m["cmd"], m["id"], n, kept=False)
        self.dump_refs()
        for wall in self.walls:
            if not wall["ok"]:
                continue
            if wall["kind"] == "primitive":
                self.out[wall["index"]] = self.primitive(wall)
                continue
            lines = []
            for mid in wall["meshes"]:
                m = self.meshes[mid]
                self.out[m["index"]] = []
                lines += self.mesh_wall(wall, m)
                self.out.update(self.motion_state[mid]["lines"])
            self.out[wall["index"]] = lines
            # last made, first unfixed: the wall that made force_ID (store_force) deletes
            # it when it goes, after the others
            for i, c in enumerate(self.cmds):
                if c.words[:2] == ["unfix", wall["id"]]:
                    self.out[i] = ["unfix %s" % mid for mid in reversed(wall["meshes"])]
        self.references()

    def dump_refs(self):
        self.gone_dumps = set()
        for i, c in self.dumps:
            w = c.words
            named = [x for x in w[6:] if x in self.meshes]
            mine = [x for x in named if x in self.done]
            if not named:
                if self.done:
                    self.report(c, None, "dump %s writes the meshes LIGGGHTS still has; the "
                                "migrated walls are not among them (wall/rigid's vtk FILE N "
                                "writes a wall)" % w[1], kept=False)
                continue
            if len(named) == 1 and mine:
                m = self.meshes[mine[0]]
                m["vtk"] = [w[5], w[4]]
                self.out[i] = []
                self.gone_dumps.add(w[1])
                self.report(c, None, "dump %s is now the vtk of wall %s (cell data sigma_n, "
                            "sigma_t, wear)" % (w[1], mine[0]), kept=False)
            elif mine:
                self.report(c, None, "dump %s names migrated meshes %s beside others: it is "
                            "kept and fails; give each wall/rigid its vtk FILE N"
                            % (w[1], " ".join(mine)))
        for i, c in enumerate(self.cmds):
            if c.words[:1] == ["undump"] and c.words[1:2] and c.words[1] in self.gone_dumps:
                self.out[i] = []

    def references(self):
        """f_ID of a migrated mesh or of a migrated mesh wall, in the lines that stay."""
        walls = {w["id"]: w for w in self.walls if w["ok"] and w["kind"] == "mesh"}
        pat = re.compile(r"\bf_(\w+)(\[(\d+)\])?")
        for i, c in enumerate(self.cmds):
            if i in self.out:
                continue
            for word in c.words:
                for mt in pat.finditer(word):
                    fid, idx = mt.group(1), mt.group(3)
                    if fid in walls:
                        self.report(c, None, "%s: wall/gran %s is now the wall/rigid fixes "
                                    "%s; this reference is not kept" % (
                                        mt.group(0), fid, " ".join(walls[fid]["meshes"])))
                    elif fid in self.done:
                        m = self.meshes[fid]
                        ref0 = m["refpoint"] is None or \
                            all(self.num.value(x) == 0 for x in m["refpoint"])
                        n = int(idx) if idx else 0
                        if m.get("servo"):
                            sv = m["servo"]
                            com = sv[sv.index("com") + 1:sv.index("com") + 4]
                            a = (m.get("placement") or (1.0, [0, 0, 0]))[1] or [0, 0, 0]
                            # LIGGGHTS's servo gives the torque about com, which moves
                            # with the wall: the same moment where com is the origin
                            ref0 = all(self.num.value(x) == float(y)
                                       for x, y in zip(com, a))
                        if m.get("servo") and 7 <= n <= 9:
                            self.report(c, None, "%s: the servo's centre; wall/rigid %s "
                                        "offers its translation as f_%s[%d] (add com)"
                                        % (mt.group(0), fid, fid, n + 8))
                        elif not (1 <= n <= 3 or (4 <= n <= 6 and ref0)):
                            self.report(c, None, "%s: wall/rigid %s offers the force "
                                        "(f_%s[1-3]) and the moment about the mesh's placed "
                                        "origin (f_%s[4-6]) of mesh/surface/stress; this "
                                        "reference is not kept" % (mt.group(0), fid, fid,
                                                                   fid))

    def text(self):
        parts = []
        for i, c in enumerate(self.cmds):
            if i not in self.out:
                parts.append("".join(c.raw))
                continue
            lines = list(self.out[i])
            if c.comment:
                if lines:
                    lines[-1] += " " + c.comment
                else:
                    lines = [c.comment]
            nl = "\n" if c.raw[-1].endswith("\n") else ""
            parts.append("\n".join(lines) + (nl if lines else ""))
        return "".join(parts)

    def run(self):
        self.scan()
        self.motion()
        self.uses()
        self.decide()
        self.emit()
        return self.text()


def wrap(words, width=WRAP):
    """One command, continued with ' &' and four spaces where it grows past width, before
    a keyword (so a keyword stays with its values)."""
    groups = []
    for word in (str(x) for x in words):
        keyword = word[0].isalpha() and not word.startswith("v_")
        if groups and (not keyword or " " not in groups[-1] and groups[-1] != "end"):
            groups[-1] += " " + word
        else:
            groups.append(word)
    lines, cur = [], ""
    for word in groups:
        if cur and len(cur) + 1 + len(word) > width - 2:
            lines.append(cur + " &")
            cur = "    " + word
        else:
            cur = (cur + " " + word) if cur else word
    return "\n".join(lines + [cur])


def migrate(text):
    """(the migrated deck, the report lines in line order, whether a wall was kept)."""
    mg = Migration(text)
    out = mg.run()
    reps = sorted(mg.reports, key=lambda r: r[0])
    return out, [r[1] for r in reps], any(r[2] for r in reps), mg


def main(argv):
    if len(argv) != 2 or argv[1] in ("-h", "--help"):
        sys.stderr.write("usage: rigidsurf-migrate DECK > DECK.rigid\n")
        return 2
    try:
        with open(argv[1], newline="") as f:
            text = f.read()
    except OSError as e:
        sys.stderr.write("rigidsurf-migrate: %s\n" % e)
        return 2
    out, reps, kept, mg = migrate(text)
    sys.stdout.write(out)
    for r in reps:
        sys.stderr.write(r + "\n")
    n_ok = sum(1 for w in mg.walls if w["ok"])
    sys.stderr.write("rigidsurf-migrate: %d of %d wall/gran fixes translated%s\n" % (
        n_ok, len(mg.walls), "; some kept as LIGGGHTS's or a reference not kept (above)"
        if kept else ""))
    return EXIT_KEPT if kept else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
