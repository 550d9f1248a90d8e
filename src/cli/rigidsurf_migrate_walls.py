"""LIGGGHTS's walls and meshes as `fix wall/rigid` lines (part of rigidsurf-migrate;
docs/migration.md).

- `fix wall/gran MODEL primitive type T xplane|... ARGS`: one wall/rigid with the same ID,
  a CYLINDER (plane) or REVOLUTION (cylinder) of one LINE, `sides 2`;
- `fix wall/gran MODEL mesh n_meshes K meshes M1 .. MK` with its `fix mesh/surface...`
  lines: one wall/rigid per mesh, `surface inline mesh FILE scale s place a b c`, the
  mesh's own placement (scale, move, rotate applied in the order written) composed;
- the model: `law hertz` or `law hooke` for LIGGGHTS's plain Hertz or Hooke with
  tangential history, else `law liggghts` with the model words and settings.

A wall or mesh the tool cannot express keeps its reasons (Wall.reasons, Mesh.reasons);
the caller keeps it as LIGGGHTS's.
"""
import math

import rigidsurf_migrate_commands as grammar
from rigidsurf_migrate_deck import DeckError, known

LAWS = {"hertz": "hertz", "hooke": "hooke"}
MESH_FILE_EXT = (".stl", ".obj", ".off", ".ply")
WRAP = 88
# mesh/surface keywords that describe how LIGGGHTS reads or treats its mesh: wall/rigid
# finds each contact from the geometry, welds and checks the mesh itself
READING_ONLY = ("verbose", "heal", "precision", "min_feature_length", "curvature",
                "curvature_tolerant")


def fmt(v):
    """A computed coordinate, to 12 significant digits, without a negative zero."""
    return "0" if abs(v) < 1e-12 else "%.12g" % v


def number(word):
    """A word's value, or None when it is not a number the tool knows."""
    if word is None or not known(word):
        return None
    try:
        v = float(word)
    except ValueError:
        return None
    return v if math.isfinite(v) else None


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


# ---- the deck's meshes and walls -------------------------------------------------------

class Mesh:
    """A `fix mesh/surface...` line as it ran."""

    def __init__(self, ex, deck):
        w = ex.words
        self.ex, self.cmd, self.id, self.group, self.style = ex, ex.cmd, w[1], w[2], w[3]
        self.reasons, self.notes, self.walls, self.users = [], [], [], []
        self.type, self.opts, self.wear, self.refpoint, self.servo = "1", {}, None, None, []
        self.stress_off, self.display, self.rid = False, False, self.id
        self.ok, self.wall = False, None   # set by the caller once all walls are read
        self.vtk = self.vtk_dump = None   # the vtk FILE N a dump of its stress gives
        try:
            self.modules = grammar.mesh_modules(self.style)
            self.file, kws = grammar.parse_mesh(w[3:])
        except grammar.Grammar as e:
            raise DeckError(ex.via or ex.cmd, "fix %s: %s" % (self.id, e))
        ops = []
        for key, vals in kws:
            if key == "type":
                self.type = vals[0]
            elif key == "scale":
                ops.append(("scale", number(vals[0])))
            elif key == "move":
                ops.append(("move", [number(x) for x in vals]))
            elif key == "rotate":
                if vals[0] != "axis" or vals[4] != "angle":
                    raise DeckError(ex.cmd, "fix %s: rotate expects 'axis AX AY AZ angle A'"
                                    % self.id)
                ops.append(("rotate", [number(x) for x in vals[1:4]], number(vals[5])))
            elif key == "temperature":
                self.opts["temperature"] = vals
            elif key == "surface_vel":
                if any(v.startswith("v_") for v in vals):
                    self.reasons.append("surface_vel with variables has no wall/rigid "
                                        "counterpart")
                self.opts["surface_vel"] = vals
            elif key in READING_ONLY:
                self.notes.append("mesh/surface's %s %s is not needed: wall/rigid finds a "
                                  "face's, edge's or vertex's contact from the geometry and "
                                  "welds and checks the mesh itself; left out"
                                  % (key, " ".join(vals)))
            elif key == "reference_point":
                self.refpoint = [number(x) for x in vals]
            elif key == "stress":
                self.stress_off = vals[0] == "off"
            elif key == "wear":
                if vals[0] not in ("finnie", "off"):
                    raise DeckError(ex.cmd, "fix %s: wear expects finnie or off" % self.id)
                self.wear = vals[0]
            elif key in grammar.MESH_MODULES["servo"]:
                self.servo += [key] + vals
            else:
                self.reasons.append("mesh/surface keyword '%s' has no wall/rigid counterpart"
                                    % key)
        vals = [x for op in ops for x in (op[1:2] if op[0] == "scale" else
                                          op[1] + ([op[2]] if op[0] == "rotate" else []))]
        self.placement = None
        if None in vals:
            self.reasons.append("its scale, move or rotate uses values the tool cannot "
                                "compute")
        else:
            self.placement = compose_placement(ops)
        if not self.file.lower().endswith(MESH_FILE_EXT):
            self.reasons.append("wall/rigid reads STL, OBJ, OFF or PLY meshes, not '%s'"
                                % self.file)
        self.path = deck.resolve(self.file) if w[4] == "file" else None
        if w[4] == "file" and self.path is None and known(self.file):
            raise DeckError(ex.cmd, "fix %s: cannot open mesh file %s (looked for in the "
                            "deck's folder and the working folder)" % (self.id, self.file))

    def origin(self):
        """The image of the file's origin (wall/rigid's surface origin a)."""
        return list(self.placement[1]) if self.placement else [0.0, 0.0, 0.0]


class Wall:
    """A `fix wall/gran` line as it ran."""

    def __init__(self, ex):
        w = ex.words
        self.ex, self.cmd, self.id, self.group = ex, ex.cmd, w[1], w[2]
        # as written, for the line that stands where this one does
        self.id_raw, self.group_raw = ex.rawword(1, w[1]), ex.rawword(2, w[2])
        self.reasons, self.notes, self.meshes, self.opts = [], [], [], {}
        self.kind, self.shear = None, None
        # set by the caller: its Mesh objects, whether it is migrated and why not
        self.mesh_objs, self.ok, self.why = [], False, []
        try:
            model, kws, settings = grammar.parse_wall(w[4:])
        except grammar.Grammar as e:
            raise DeckError(ex.via or ex.cmd, "fix %s: %s" % (self.id, e))
        self.law = law(model, settings, self.reasons)
        for key, vals in kws:
            if key == "primitive":
                self.kind, self.shape = "primitive", vals[2]
                pos = self.positions(vals[1:])
                self.type = ex.rawword(*pos[0])
                self.args = [ex.rawword(k, x) for k, x in pos[2:]]
            elif key == "mesh":
                self.kind = "mesh"
            elif key == "meshes":
                self.meshes = vals
            elif key == "temperature":
                self.opts["temperature"] = vals
            elif key == "contact_area":
                self.opts["contact_area"] = vals
            elif key == "store_force":
                if vals[0] == "yes":
                    self.opts["store_force"] = ["yes"]
            elif key == "shear":
                if self.kind != "primitive":
                    raise DeckError(ex.cmd, "fix %s: shear needs the primitive wall before it "
                                    "(LIGGGHTS: have to define primitive wall before "
                                    "'shear')" % self.id)
                self.shear = vals
            elif key == "track_energy":
                self.notes.append("track_energy is set and read nowhere by LIGGGHTS 3.8; "
                                  "left out")
            elif key in ("store_force_contact", "store_force_contact_every",
                         "store_force_contact_stress"):
                if key != "store_force_contact" or vals[0] == "yes":
                    self.reasons.append("wall/gran keyword '%s' has no wall/rigid counterpart"
                                        % " ".join([key] + vals))
        if self.kind == "primitive" and self.shear:
            if self.shear[0] not in ("x", "y", "z"):
                raise DeckError(ex.cmd, "fix %s: shear expects x, y or z, got '%s' (LIGGGHTS: "
                                "illegal 'shear' dim)" % (self.id, self.shear[0]))
            vel = shear(self.shape, *self.shear)
            if isinstance(vel, str):
                self.reasons.append(vel)
            else:
                self.opts["surface_vel"] = vel

    def positions(self, vals):
        """(index in the Exec's words, word) of the primitive's arguments."""
        w = self.ex.words
        k = w.index("primitive") + 2
        return [(k + i, x) for i, x in enumerate(vals)]


def law(model, settings, reasons):
    """wall/rigid's law for LIGGGHTS's model words and settings. Without `tangential`
    LIGGGHTS's selector takes no tangential model (TANGENTIAL_OFF): no friction, which
    only law liggghts with the same words gives."""
    plain = model.get("tangential") == "history" and \
        model.get("cohesion", "off") == "off" and \
        model.get("rolling_friction", "off") == "off" and not settings
    surface = model.get("surface", "default")
    if surface != "default":
        reasons.append("model words '%s': surface %s needs LIGGGHTS's own wall (%s); law "
                       "liggghts takes the default surface model only" % (
                           " ".join("%s %s" % kv for kv in model.items()), surface,
                           "the expanded radii of fix multicontact/halfspace"
                           if surface == "multicontact" else "superquadric particles"))
    for s, v in settings:
        if s in ("computeElasticPotential", "computeDissipatedEnergy") and v == "on":
            reasons.append("setting '%s on': LIGGGHTS computes it for its mesh walls' own "
                           "bookkeeping, which wall/rigid has not" % s)
    if plain and model["model"] in LAWS:
        return LAWS[model["model"]]
    words = ["liggghts"]
    for key in grammar.MODEL_KEYWORDS:
        if key in model:
            words += [key, model[key]]
    for s, v in settings:
        words += [s, v]
    return " ".join(words)


def shear(shape, dim, v):
    """wall/gran's `shear DIM V` of a primitive wall as wall/rigid's surface_vel, or why
    not. LIGGGHTS (fix_wall_gran.cpp) gives every contact the wall velocity V along DIM
    when DIM is the cylinder's axis or the wall is a plane (the wall does not move, its
    material slides); along a plane's tangent, or a cylinder's axis, that is surface_vel
    V e_DIM. Along a plane's normal it is a velocity into the wall, and for a cylinder
    with DIM across its axis LIGGGHTS turns it into (V e_axis) x r of the particle's
    centre: neither has a wall/rigid counterpart."""
    if shape.endswith("plane") and shape[0] == dim:
        return ("shear %s of %s is a velocity along the plane's normal: wall/rigid's "
                "surface_vel slides in the tangent plane only" % (dim, shape))
    if shape.endswith("cylinder") and shape[0] != dim:
        return ("shear %s of %s is LIGGGHTS's spin (%s e_%s) x r about the axis, at the "
                "particle's centre: wall/rigid has no counterpart" % (dim, shape, v, shape[0]))
    return [v if d == dim else "0" for d in "xyz"]


# ---- wall/rigid lines ----------------------------------------------------------------

def conduction(opts, wall_opts, heat):
    """A wall's temperature under fix heat/gran conducts heat into the particles that
    touch it (fix_wall_gran.cpp, addHeatFlux): wall/rigid's conduction liggghts, with
    the wall/gran's contact_area (which sets that conduction's area only)."""
    if "temperature" not in opts or not heat:
        return []
    area = wall_opts.get("contact_area")
    return ["conduction", "liggghts"] + (["contact_area"] + area if area else [])


def primitive(wall, L, heat):
    """The wall/rigid line of a primitive wall (L: the LINE's half-length)."""
    mL = L[1:] if L.startswith("-") else "-" + L
    shape, args = wall.shape, wall.args
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
    words = ["fix", wall.id_raw, wall.group_raw, "wall/rigid", "surface", "inline"] + \
        surf + ["law"] + wall.law.split() + ["type", wall.type]
    for key, vals in wall.opts.items():
        if key != "contact_area":
            words += [key] + vals
    words += conduction(wall.opts, wall.opts, heat)
    return wrap(words)


def mesh_wall(wall, m, motion, heat):
    """The wall/rigid line of mesh m of wall (motion: its state from the motion module),
    and the rate variables it needs defined before it."""
    scale, a, b, c = m.placement if m.placement else (1.0, None, None, None)
    words = ["fix", m.rid, wall.group, "wall/rigid", "surface", "inline", "mesh", m.file]
    if scale != 1.0:
        words += ["scale", fmt(scale)]
    if a is not None and [fmt(x) for x in a + b + c] != \
            ["0", "0", "0", "1", "0", "0", "0", "1", "0"]:
        words += ["place"] + [fmt(x) for x in a + b + c]
    words += ["law"] + wall.law.split() + ["type", m.type]
    for key, vals in m.opts.items():
        words += [key] + vals
    words += conduction(m.opts, wall.opts, heat)
    if wall.opts.get("store_force"):
        # wall/gran keeps one force_ID for all its meshes: each mesh's wall adds to it
        words += ["store_force", "into", wall.id]
    if m.wear == "finnie":
        words += ["wear", "finnie"]
    if m.vtk:
        words += ["vtk"] + m.vtk
    if m.servo:
        words += ["servo"] + m.servo
    s, pre = motion, []
    rate = lambda k: "v_rs_%s_%s" % (m.id, k)  # noqa: E731
    if s["lin_used"]:
        words += ["move", "linear"] + [rate(k) for k in ("vx", "vy", "vz")]
    if s["rot"] is not None:
        o = s["rot"][4] if s["centre"] == "fixed" else s["rot"][0]
        words += ["rotate", "origin"] + list(o) + ["axis"] + list(s["rot"][1]) + \
            ["omega", rate("om")] + (["centre", "fixed"] if s["centre"] == "fixed" else [])
    if s["spin"] is not None:
        words += ["spin", "origin"] + list(s["spin"][0]) + ["axis"] + list(s["spin"][1]) \
            + ["omega", rate("om2")]
    used = (["vx", "vy", "vz"] if s["lin_used"] else []) + (["om"] if s["rot"] else []) \
        + (["om2"] if s["spin"] is not None else [])
    for k in used:
        if k not in s["pre_wall"]:
            pre.append("variable rs_%s_%s equal 0" % (m.id, k))
    return pre + [wrap(words)]


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


def half_length(box_half):
    """L, the half-length of a plane's LINE and a cylinder's: a power of ten past four
    times the box; None where the box is not known."""
    if box_half is not None and box_half > 0:
        return fmt(10.0 ** math.ceil(math.log10(4 * box_half)))
    return None

