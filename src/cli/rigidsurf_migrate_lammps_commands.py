"""LAMMPS 29Sep2021's grammar of the commands that make walls (part of rigidsurf-migrate):
`fix wall/gran` and `fix wall/gran/region` (FixWallGran's constructor: the model words,
the wall, its options), `region` (each style's arguments and Region::options), and
`lattice`, which scales a region's coordinates; and which engine a deck is written for.

A command is read as LAMMPS reads it; a word LAMMPS would stop at is a Grammar error
naming the word and what LAMMPS expects there.
"""
import re

from rigidsurf_migrate_commands import Grammar

# ---- fix wall/gran, fix wall/gran/region (FixWallGran::FixWallGran) -------------------

STYLES = ("hooke", "hooke/history", "hertz/history", "granular")
WALLS = {"xplane": 2, "yplane": 2, "zplane": 2, "zcylinder": 1, "region": 1}
# the granular model's keywords: the number of values each takes after it (a function
# of its first value where that chooses the rest)
TANGENTIAL = {"linear_nohistory": 2, "linear_history": 3, "mindlin": 3,
              "mindlin_rescale": 3, "mindlin/force": 3, "mindlin_rescale/force": 3}
GRANULAR = {
    "hooke": lambda w, k: 2, "hertz": lambda w, k: 2, "hertz/material": lambda w, k: 3,
    "dmt": lambda w, k: 4, "jkr": lambda w, k: 4,
    "damping": lambda w, k: _choice(w, k, "damping", {"velocity": 0, "mass_velocity": 0,
                                                       "viscoelastic": 0, "tsuji": 0}),
    "tangential": lambda w, k: _choice(w, k, "tangential", TANGENTIAL),
    "rolling": lambda w, k: _choice(w, k, "rolling", {"none": 0, "sds": 3}),
    "twisting": lambda w, k: _choice(w, k, "twisting", {"none": 0, "marshall": 0,
                                                         "sds": 3}),
    "limit_damping": lambda w, k: -1,
}
NORMAL = ("hooke", "hertz", "hertz/material", "dmt", "jkr")
WHAT = ("fix wall/gran: LAMMPS stops with 'Illegal fix wall/gran command'")


def _choice(words, k, key, table):
    if k + 1 >= len(words) or words[k + 1] not in table:
        raise Grammar("fix wall/gran: '%s' expects one of %s, got '%s' (LAMMPS: Illegal "
                      "wall/gran command)" % (key, ", ".join(table), words[k + 1]
                                              if k + 1 < len(words) else "(end of line)"))
    return 1 + table[words[k + 1]]


class Wall:
    """The words after 'fix ID group wall/gran[/region]', as FixWallGran reads them:
    model (the model's words, by index into words), wall (its style and values), wiggle
    (dim, A, P), shear (dim, V), contacts; words, the index of each kept."""

    def __init__(self, words, region_fix):
        self.words = words
        what = "fix wall/gran%s" % ("/region" if region_fix else "")
        if not words or words[0] not in STYLES:
            raise Grammar("%s: expects its contact model first: %s, got '%s' (LAMMPS: "
                          "Invalid fix wall/gran interaction style)" % (
                              what, ", ".join(STYLES), words[0] if words else "nothing"))
        self.style = words[0]
        k = self.model_words(what)
        self.model = list(range(k))
        if k >= len(words) or words[k] not in WALLS:
            raise Grammar("%s: expects the wall (%s) after the model words, got '%s'" % (
                what, "region ID" if region_fix else "xplane|yplane|zplane lo hi or "
                "zcylinder R", words[k] if k < len(words) else "the end of the line"))
        self.wall = words[k]
        n = WALLS[self.wall]
        if k + 1 + n > len(words):
            raise Grammar("%s: '%s' expects %d value%s (LAMMPS: Illegal fix wall/gran "
                          "command)" % (what, self.wall, n, "s" if n > 1 else ""))
        self.wall_at = k
        self.values = list(range(k + 1, k + 1 + n))
        if region_fix != (self.wall == "region"):
            raise Grammar("%s: %s" % (what, "expects 'region ID' as its wall" if region_fix
                                      else "'region' is fix wall/gran/region's wall"))
        self.wiggle = self.shear = None
        self.contacts = False
        k += 1 + n
        while k < len(words):
            w = words[k]
            if w in ("wiggle", "shear"):
                n = 3 if w == "wiggle" else 2
                if k + n >= len(words):
                    raise Grammar("%s: '%s' expects %s (LAMMPS: Illegal fix wall/gran "
                                  "command)" % (what, w, "dim A P" if n == 3 else "dim V"))
                if words[k + 1] not in ("x", "y", "z"):
                    raise Grammar("%s: '%s' expects x, y or z, got '%s' (LAMMPS: Illegal "
                                  "fix wall/gran command)" % (what, w, words[k + 1]))
                setattr(self, w, list(range(k + 1, k + 1 + n)))
                k += 1 + n
            elif w == "contacts":
                self.contacts = True
                k += 1
            else:
                raise Grammar("%s: '%s' is not one of its keywords (wiggle, shear, "
                              "contacts) after the wall (LAMMPS: Illegal fix wall/gran "
                              "command)" % (what, w))
        if self.wiggle and self.shear:
            raise Grammar("%s: wiggle and shear together (LAMMPS: Cannot wiggle and shear "
                          "fix wall/gran)" % what)
        if region_fix and (self.wiggle or self.shear):
            raise Grammar("%s: wiggle and shear are fix wall/gran's (LAMMPS: Cannot wiggle "
                          "or shear with fix wall/gran/region)" % what)
        if self.wiggle and self.wall == "zcylinder" and words[self.wiggle[0]] != "z":
            raise Grammar("%s: a zcylinder wiggles along z (LAMMPS: Invalid wiggle "
                          "direction for fix wall/gran)" % what)
        if self.shear and self.wall.endswith("plane") and \
                words[self.shear[0]] == self.wall[0]:
            raise Grammar("%s: %s shears along the plane, not along %s (LAMMPS: Invalid "
                          "shear direction for fix wall/gran)" % (what, self.wall,
                                                                  words[self.shear[0]]))

    def model_words(self, what):
        """The number of model words (FixWallGran's coefficients or granular keywords)."""
        w = self.words
        if self.style != "granular":
            k = 7
            if len(w) < k + 1:
                raise Grammar("%s %s expects kn kt gamma_n gamma_t xmu dampflag and the "
                              "wall (LAMMPS: Illegal fix wall/gran command)" % (what,
                                                                               self.style))
            for j in range(1, 7):
                if j in (2, 4) and w[j] == "NULL":
                    continue
                if not NUMBER.fullmatch(w[j]):
                    raise Grammar("%s %s: '%s' is not a number (its values are kn kt "
                                  "gamma_n gamma_t xmu dampflag)" % (what, self.style, w[j]))
            if w[6] not in ("0", "1"):
                raise Grammar("%s %s: dampflag is 0 or 1, got '%s' (LAMMPS: Illegal fix "
                              "wall/gran command)" % (what, self.style, w[6]))
            return k + 1 if w[k] == "limit_damping" else k
        k, normal = 1, False
        while k < len(w) and w[k] not in WALLS:
            if w[k] not in GRANULAR:
                raise Grammar("%s granular: '%s' is neither a model keyword (%s) nor a wall "
                              "(LAMMPS: Illegal fix wall/gran command)" % (
                                  what, w[k], ", ".join(GRANULAR)))
            normal |= w[k] in NORMAL
            n = GRANULAR[w[k]](w, k)
            if n < 0:
                k += 1
                continue
            if k + n >= len(w):
                raise Grammar("%s granular: '%s' expects %d values, the line ends first "
                              "(LAMMPS: not enough parameters)" % (what, w[k], n))
            k += 1 + n
        if not normal:
            raise Grammar("%s granular: expects a normal model (%s)" % (what,
                                                                       ", ".join(NORMAL)))
        return k


NUMBER = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?")


# ---- region (Region::options and each style) --------------------------------------

# each style's values before its options, and those that may be INF or EDGE
REGION_STYLES = {"block": 6, "cone": 7, "cylinder": 6, "plane": 6, "prism": 9,
                 "sphere": 4}
INF_EDGE = {"block": range(6), "cone": (5, 6), "cylinder": (4, 5), "prism": range(6)}
# the styles' values that may be v_name (the region's shape then changes in time)
VARIABLE_SHAPE = {"cylinder": (1, 2, 3), "sphere": range(4)}


class Region:
    """A `region ID STYLE ...` line as LAMMPS reads it: style, values (as written: words),
    members (union, intersect: the IDs), side ('in'/'out'), units ('box'/'lattice'),
    move (three words, NULL or v_name), rotate (v_name, point, axis: words), open (face
    numbers 1-6)."""

    def __init__(self, words):
        if len(words) < 2:
            raise Grammar("region: expects 'region ID STYLE ...' (LAMMPS: Illegal region "
                          "command)")
        self.id, self.style = words[0], words[1]
        a = words[2:]
        if self.style in ("union", "intersect"):
            if not a or not a[0].isdigit() or int(a[0]) < 2 or len(a) < 1 + int(a[0]):
                raise Grammar("region %s: expects N >= 2 and N region IDs (LAMMPS: Illegal "
                              "region command)" % self.style)
            n = int(a[0])
            self.members, self.values, rest = a[1:1 + n], [], a[1 + n:]
        elif self.style in REGION_STYLES:
            n = REGION_STYLES[self.style]
            if len(a) < n:
                raise Grammar("region %s: expects %d values (LAMMPS: Illegal region "
                              "command)" % (self.style, n))
            self.members, self.values, rest = [], a[:n], a[n:]
            if self.style in ("cone", "cylinder") and a[0] not in ("x", "y", "z"):
                raise Grammar("region %s: expects its axis x, y or z first, got '%s'" % (
                    self.style, a[0]))
            for k, w in enumerate(self.values):
                if self.style in ("cone", "cylinder") and k == 0 or "\x00" in w or \
                        NUMBER.fullmatch(w) or w in ("INF", "EDGE") and \
                        k in INF_EDGE.get(self.style, ()) or w.startswith("v_") and \
                        k in VARIABLE_SHAPE.get(self.style, ()):
                    continue
                raise Grammar("region %s: '%s' is not a number%s (LAMMPS: Expected "
                              "floating point parameter)" % (
                                  self.style, w, ", INF or EDGE" if k in INF_EDGE.get(
                                      self.style, ()) else ""))
        else:
            raise Grammar("region: LAMMPS 29Sep2021 has no region style '%s' (it has %s; "
                          "LAMMPS: Unrecognized region style)" % (
                              self.style, ", ".join(list(REGION_STYLES) + ["union",
                                                                           "intersect"])))
        self.side, self.units, self.move, self.rotate, self.open = "in", "lattice", None, \
            None, []
        k = 0
        while k < len(rest):
            w, n = rest[k], {"units": 1, "side": 1, "move": 3, "rotate": 7,
                             "open": 1}.get(rest[k])
            if n is None:
                raise Grammar("region %s: '%s' is not one of its keywords (units, side, "
                              "move, rotate, open; LAMMPS: Illegal region command)" % (
                                  self.id, w))
            if k + n >= len(rest):
                raise Grammar("region %s: '%s' expects %d value%s (LAMMPS: Illegal region "
                              "command)" % (self.id, w, n, "s" if n > 1 else ""))
            v = rest[k + 1:k + 1 + n]
            if w == "units":
                if v[0] not in ("box", "lattice"):
                    raise Grammar("region %s: units expects box or lattice" % self.id)
                self.units = v[0]
            elif w == "side":
                if v[0] not in ("in", "out"):
                    raise Grammar("region %s: side expects in or out" % self.id)
                self.side = v[0]
            elif w == "move":
                if any(x != "NULL" and not x.startswith("v_") for x in v):
                    raise Grammar("region %s: move expects v_name or NULL for each of x, y, "
                                  "z (LAMMPS: Illegal region command)" % self.id)
                self.move = v
            elif w == "rotate":
                if not v[0].startswith("v_"):
                    raise Grammar("region %s: rotate expects v_name (the angle) first "
                                  "(LAMMPS: Illegal region command)" % self.id)
                self.rotate = v
            else:
                if not v[0].isdigit() or not 1 <= int(v[0]) <= 6:
                    raise Grammar("region %s: open expects a face 1 to 6 (LAMMPS: Illegal "
                                  "region command)" % self.id)
                if self.style in ("cone", "cylinder") and int(v[0]) > 3:
                    raise Grammar("region %s: a %s has faces 1 to 3 (LAMMPS: Invalid region "
                                  "%s open setting)" % (self.id, self.style, self.style))
                self.open.append(int(v[0]))
            k += 1 + n
        if (self.move or self.rotate) and self.members:
            raise Grammar("region %s: a %s moves with its members (LAMMPS: Region union or "
                          "intersect cannot be dynamic)" % (self.id, self.style))

    def variable_shape(self):
        """The values that are v_name (LAMMPS varies the region's shape with them)."""
        return [self.values[k] for k in VARIABLE_SHAPE.get(self.style, ())
                if self.values[k].startswith("v_")]


# ---- lattice (Lattice::Lattice): the scale of a region's `units lattice` -------------

CUBIC = {"sc": 1, "bcc": 2, "fcc": 4, "diamond": 8}


def lattice_scale(words, units, dimension):
    """The spacings (x, y, z) of `lattice STYLE SCALE ...` for regions in lattice units,
    or a reason the tool does not compute them."""
    if len(words) < 2 or not NUMBER.fullmatch(words[1]):
        return "lattice %s: its scale is not a number the tool knows" % " ".join(words)
    s = float(words[1])
    if words[0] == "none":
        return (s, s, s)
    rest = words[2:]
    if "spacing" in rest:
        k = rest.index("spacing")
        v = rest[k + 1:k + 4]
        if len(v) == 3 and all(NUMBER.fullmatch(x) for x in v):
            if units == "lj":
                return "lattice with spacing in lj units"
            return tuple(float(x) * s for x in v)
    if words[0] in CUBIC and not rest and dimension == 3:
        if units == "lj":
            s = (CUBIC[words[0]] / s) ** (1.0 / 3.0)
        return (s, s, s)
    return ("lattice %s: the tool computes the spacings of lattice none, of sc, bcc, fcc "
            "and diamond as given, and of 'spacing'" % " ".join(words))


# ---- the engine of a deck --------------------------------------------------------

LAMMPS_SIGNS = [
    (re.compile(r"^\s*fix\s+\S+\s+\S+\s+wall/gran/region\b"), "fix wall/gran/region"),
    (re.compile(r"^\s*fix\s+\S+\s+\S+\s+wall/gran\s+(hooke|hooke/history|hertz/history|"
                r"granular)\b"), "fix wall/gran hooke|hooke/history|hertz/history|granular"),
    # (pair_style gran/hooke... is LIGGGHTS 2's too)
    (re.compile(r"^\s*pair_style\s+granular\b"), "pair_style granular"),
]
LIGGGHTS_SIGNS = [
    (re.compile(r"^\s*fix\s+\S+\s+\S+\s+wall/gran\s+model\b"), "fix wall/gran model"),
    (re.compile(r"^\s*fix\s+\S+\s+\S+\s+mesh/surface"), "fix mesh/surface"),
    (re.compile(r"^\s*fix\s+\S+\s+\S+\s+property/global\b"), "fix property/global"),
    (re.compile(r"^\s*pair_style\s+gran\s+model\b"), "pair_style gran model"),
    (re.compile(r"^\s*atom_style\s+granular\b"), "atom_style granular"),
]


def detect(commands):
    """The engine a deck's commands (Command objects, as written) are for: 'lammps',
    'liggghts', None when nothing tells, or a (where, what, where, what) pair of the
    first sign of each engine when both appear."""
    first = {}
    for cmd in commands:
        for engine, signs in (("lammps", LAMMPS_SIGNS), ("liggghts", LIGGGHTS_SIGNS)):
            if engine in first:
                continue
            for rx, what in signs:
                if rx.search(cmd.body):
                    first[engine] = (cmd, what)
                    break
    if len(first) == 2:
        return first["liggghts"] + first["lammps"]
    return next(iter(first), None)
