"""LIGGGHTS 3.8's grammar of the commands that make, move, write and read walls (part of
rigidsurf-migrate): their keywords in the order LIGGGHTS parses them, with the number of
values each takes, and the contact models with their settings.

A command is parsed as LIGGGHTS parses it: groups of keywords, each group read while its
words come, one group after the other (FixMesh, then FixMeshSurface, then each mesh
module for `fix mesh/surface...`; the wall keywords, then the model's settings for `fix
wall/gran`). A word left over is LIGGGHTS's "unknown keyword or wrong keyword order",
which the tool reports as an error naming the word.
"""


class Grammar(Exception):
    """A word LIGGGHTS would refuse; the message says which and what was expected."""


def parse_groups(words, groups, what):
    """words read by groups of {keyword: number of values}; returns [(keyword, values)] in
    order. Raises Grammar for a word left over or a keyword without its values."""
    out, k = [], 0
    for group in groups:
        while k < len(words) and words[k] in group:
            n = group[words[k]]
            if callable(n):
                n = n(words, k)
            if k + 1 + n > len(words):
                raise Grammar("%s: '%s' expects %d value%s, the line ends after %d" % (
                    what, words[k], n, "" if n == 1 else "s", len(words) - k - 1))
            out.append((words[k], words[k + 1:k + 1 + n]))
            k += 1 + n
    if k < len(words):
        raise Grammar("%s: '%s' is not one of its keywords, or comes after the keywords it "
                      "must precede (LIGGGHTS: unknown keyword or wrong keyword order); it "
                      "takes %s" % (what, words[k], ", ".join(
                          "%s" % key for g in groups for key in g)))
    return out


# ---- fix mesh/surface[/MODULE...] (FixMesh, FixMeshSurface, the mesh modules) ---------

def _exclusion(words, k):
    return 2


MESH_GROUPS = [
    # FixMesh, after 'file F': the mesh's reading
    {"type": 1, "verbose": 1, "region": 1, "heal": 1, "precision": 1,
     "min_feature_length": 1, "element_exclusion_list": _exclusion},
    # FixMesh: its placement and temperature
    {"move": 3, "rotate": 6, "scale": 1, "temperature": 1, "mass_temperature": 1},
    # FixMeshSurface
    {"surface_vel": 3, "surface_ang_vel": 10, "curvature": 1, "curvature_tolerant": 1,
     "extrude_planar": 1},
]
MESH_MODULES = {
    "stress": {"reference_point": 3, "stress": 1, "wear": 1},
    "servo": {"com": 3, "ctrlPV": 1, "vel_max": 1, "target_val": 1, "axis": 3, "kp": 1,
              "ki": 1, "kd": 1, "mode": 1, "ratio": 1},
}
# the values of each module's global vector (f_ID[i]), in module order
MODULE_VECTOR = {"stress": 9, "servo": 3}


def mesh_modules(style):
    """The modules of a mesh style ('mesh/surface/stress/servo': stress, servo), or
    Grammar."""
    mods, parts = [], style.split("/")
    if parts[:2] != ["mesh", "surface"]:
        raise Grammar("fix %s is not a mesh/surface style" % style)
    for p in parts[2:]:
        if p == "planar" and len(parts) == 3:
            continue
        if p not in MESH_MODULES:
            raise Grammar("fix %s: LIGGGHTS knows no mesh module '%s' (unknown keyword in "
                          "style definition)" % (style, p))
        mods.append(p)
    return mods


def parse_mesh(words):
    """The words after 'fix ID group STYLE' of a mesh fix: (file, [(keyword, values)])."""
    style = words[0]
    what = "fix %s" % style
    mods = mesh_modules(style)
    if len(words) < 3 or words[1] not in ("file", "fix"):
        raise Grammar("%s: expects 'file FILE' first" % what)
    groups = MESH_GROUPS + [MESH_MODULES[m] for m in mods]
    kws = parse_groups(words[3:], groups, what)
    if not any(k == "type" for k, _ in kws):
        raise Grammar("%s: expects 'type T' among the keywords before its placement "
                      "(LIGGGHTS: expecting keyword 'type')" % what)
    return words[2], kws


# ---- fix wall/gran (FixWallGran) and its contact model ---------------------------------

PRIMITIVES = {"xplane": 1, "yplane": 1, "zplane": 1, "xcylinder": 3, "ycylinder": 3,
              "zcylinder": 3}


def _primitive(words, k):
    # primitive type T STYLE args
    if k + 3 >= len(words) or words[k + 1] != "type":
        raise Grammar("fix wall/gran: 'primitive' expects 'type T' and a wall style")
    style = words[k + 3]
    if style not in PRIMITIVES:
        raise Grammar("fix wall/gran: '%s' is not a primitive wall of LIGGGHTS (it takes %s)"
                      % (style, ", ".join(PRIMITIVES)))
    return 3 + PRIMITIVES[style]


def _meshes(words, k):
    for j in range(k - 1, -1, -1):
        if words[j] == "n_meshes" and j + 1 < len(words):
            try:
                return int(words[j + 1])
            except ValueError:
                break
    raise Grammar("fix wall/gran: 'meshes' needs 'n_meshes N' before it")


def _contact_area(words, k):
    return 2 if k + 1 < len(words) and words[k + 1] == "constant" else 1


WALL_KEYWORDS = {"primitive": _primitive, "mesh": 0, "track_energy": 0, "store_force": 1,
                 "store_force_contact": 1, "store_force_contact_every": 1,
                 "allow_special_domain_periodic": 1, "store_force_contact_stress": 1,
                 "n_meshes": 1, "meshes": _meshes, "shear": 2, "temperature": 1,
                 "contact_area": _contact_area}

# The models LIGGGHTS 3.8 offers (liggghts -h), in the order its selector reads their
# keywords, and the settings each registers (on/off unless named yes/no or a number).
MODEL_KEYWORDS = ("model", "tangential", "cohesion", "rolling_friction", "surface")
_HOOKE = ("viscous", "tangential_damping", "limitForce", "ktToKnUser",
          "heating_normal_hooke", "heating_tracking", "computeElasticPotential",
          "computeDissipatedEnergy", "disableNormalWhenBonded")
MODELS = {
    "model": {
        "hertz": ("tangential_damping", "limitForce", "heating_normal_hertz",
                  "heating_tracking", "computeElasticPotential",
                  "computeDissipatedEnergy", "disableNormalWhenBonded"),
        "hertz/stiffness": ("tangential_damping", "limitForce"),
        "hooke": _HOOKE,
        "hooke/hysteresis": _HOOKE,
        "hooke/stiffness": ("tangential_damping", "absolute_damping", "limitForce",
                            "computeElasticPotential", "computeDissipatedEnergy"),
        "luding": ("tangential_damping", "limitForce"),
        "edinburgh": ("tangential_damping", "limitForce", "fixKc"),
        "edinburgh/stiffness": ("tangential_damping", "limitForce", "fixKc"),
        "thornton_ning": ("tangential_damping", "limitForce"),
    },
    "tangential": {
        "history": ("heating_tangential_history", "heating_tracking",
                    "computeElasticPotential", "computeDissipatedEnergy"),
        "no_history": ("disableTangentialWhenBonded", "computeDissipatedEnergy"),
        "tan_luding": ("heating_tangential_history", "heating_tracking"),
    },
    "cohesion": {
        "off": (), "sjkr": ("tangential_reduce",), "sjkr2": ("tangential_reduce",),
        "easo/capillary/viscous": ("tangential_reduce",),
        "washino/capillary/viscous": ("limitLiquidContent", "modifyLbVolume",
                                      "tangential_reduce"),
    },
    "rolling_friction": {
        "off": (), "cdt": ("torsionTorque",), "epsd": ("torsionTorque",),
        "epsd2": ("torsionTorque",), "epsd3": ("torsionTorque",), "luding": ("torsion",),
    },
    "surface": {
        "default": ("computeElasticPotential", "computeDissipatedEnergy"),
        "multicontact": (),
        "superquadric": ("curvatureLimitFactor", "meanCurvature", "gaussianCurvature"),
    },
}
SETTING_VALUES = {"curvatureLimitFactor": None, "meanCurvature": ("yes", "no"),
                  "gaussianCurvature": ("yes", "no")}


def parse_model(words):
    """The model words at the start of words (LIGGGHTS's selector: each keyword at most
    once, in MODEL_KEYWORDS order): ({keyword: name}, the number of words read)."""
    model, k = {}, 0
    for key in MODEL_KEYWORDS:
        if k + 1 < len(words) and words[k] == key:
            if words[k + 1] not in MODELS[key]:
                raise Grammar("fix wall/gran: %s '%s' is not one of LIGGGHTS's (it has %s): "
                              "LIGGGHTS stops with 'Invalid model specified'" % (
                                  key, words[k + 1], ", ".join(MODELS[key])))
            model[key] = words[k + 1]
            k += 2
    if "model" not in model:
        raise Grammar("fix wall/gran: expects 'model NORMAL [tangential T] [cohesion C] "
                      "[rolling_friction R] [surface S]' first (LIGGGHTS 2's numeric "
                      "arguments are not LIGGGHTS 3.8's: it stops with 'Invalid model "
                      "specified')")
    return model, k


def parse_settings(model, words):
    """The model's settings [(name, value)] (LIGGGHTS's Settings::parseArguments)."""
    allowed = {}
    for key in MODEL_KEYWORDS:
        # a keyword not given: its model off (no settings), the surface's default
        name = model.get(key, "default" if key == "surface" else None)
        if name is not None:
            for s in MODELS[key][name]:
                allowed[s] = SETTING_VALUES.get(s, ("on", "off"))
    out, k = [], 0
    while k < len(words):
        s = words[k]
        if s not in allowed:
            raise Grammar("fix wall/gran: '%s' is neither a keyword of the wall nor a setting "
                          "of %s (LIGGGHTS: unknown argument or wrong keyword order; the wall "
                          "takes %s before the settings, the model's settings are %s)" % (
                              s, " ".join("%s %s" % kv for kv in model.items()),
                              ", ".join(WALL_KEYWORDS), ", ".join(allowed) or "none"))
        if k + 1 >= len(words):
            raise Grammar("fix wall/gran: setting '%s' expects a value" % s)
        v = words[k + 1]
        if allowed[s] is not None and v not in allowed[s]:
            raise Grammar("fix wall/gran: setting '%s' expects %s, got '%s'" % (
                s, " or ".join(allowed[s]), v))
        out.append((s, v))
        k += 2
    return out


def parse_wall(words):
    """The words after 'fix ID group wall/gran': (model, [(keyword, values)] of the wall,
    [(setting, value)])."""
    model, k = parse_model(words)
    rest = words[k:]
    kw, j = [], 0
    while j < len(rest) and rest[j] in WALL_KEYWORDS:
        n = WALL_KEYWORDS[rest[j]]
        if callable(n):
            n = n(rest, j)
        if j + 1 + n > len(rest):
            raise Grammar("fix wall/gran: '%s' expects %d value%s" % (rest[j], n,
                                                                      "" if n == 1 else "s"))
        kw.append((rest[j], rest[j + 1:j + 1 + n]))
        j += 1 + n
    return model, kw, parse_settings(model, rest[j:])


# ---- dumps of meshes (DumpMeshSTL, DumpMeshVTK) -----------------------------------------

DUMP_MESH_STYLES = ("mesh/stl", "mesh/vtk", "mesh/gran/VTK", "mesh/vtm")
DUMP_STL_KEYWORDS = {"binary": 0, "region": 1, "all": 0, "local": 0, "ghost": 0}
# the fields of mesh/vtk that come from forces on the mesh (its wall's), and those that
# the mesh's geometry and motion give
DUMP_FORCE_FIELDS = ("stress", "stresscomponents", "wear")
DUMP_VTK_FIELDS = DUMP_FORCE_FIELDS + ("id", "vel", "temp", "owner", "area", "aedges",
                                       "acorners", "index", "nneighs", "liquid", "distaa")


def parse_mesh_dump(words, is_mesh):
    """The words after 'dump ID group STYLE N FILE' of a mesh dump: (the meshes named, or
    None for every mesh, [fields])."""
    style, rest = words[0], words[3:]
    meshes, fields, k = [], [], 0
    while k < len(rest):
        w = rest[k]
        if style == "mesh/stl" and w in DUMP_STL_KEYWORDS:
            k += 1 + DUMP_STL_KEYWORDS[w]
            continue
        if style != "mesh/stl" and w == "output":
            k += 2
            continue
        if is_mesh(w):
            meshes.append(w)
        elif style == "mesh/stl":
            raise Grammar("dump mesh/stl: '%s' is neither a keyword nor a mesh (LIGGGHTS: "
                          "unknown keyword or mesh)" % w)
        else:
            fields.append(w)
        k += 1
    return (meshes or None), fields
