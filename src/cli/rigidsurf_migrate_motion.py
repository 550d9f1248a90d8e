"""The `fix move/mesh` lines of a LIGGGHTS deck as the rates of a `fix wall/rigid`
(part of rigidsurf-migrate; docs/migration.md).

A migrated mesh wall has `move linear v_rs_M_vx v_rs_M_vy v_rs_M_vz` and
`rotate origin O axis A omega v_rs_M_om`; each `fix move/mesh` line and each `unfix` of
one becomes `variable` lines that set those rates, so they change where LIGGGHTS's
motions do. The rates are LIGGGHTS's mesh velocities (src/mesh_mover_linear.cpp,
src/mesh_mover_rotation.cpp), with t = dTAbs, the time since the move fix was made:

- linear V: V; linear/variable: the variables;
- wiggle amplitude A period P: A w cos(w t), w = 2 pi / P;
- viblin axis n order K amplitude a_j phase p_j period P_j: n/|n| s(t) with
  s(t) = -sum_j a_j w_j sin(w_j t + p_j), w_j = 2 pi / P_j (phases in radians);
- rotate ... period P: 2 pi / P; rotate/variable: the variable;
- riggle ... period P amplitude A: A pi/180 w cos(w t) (A in degrees);
- vibrot ... order K amplitude a_j phase p_j period P_j: s(t) (a_j in radians).

LIGGGHTS moves the mesh each step by its velocity at the step's end times dt
(dTAbs += dt, then the displacement), and wall/rigid by its rate evaluated at the step
being integrated, so t = time - t0, with t0 the `time` when the move fix is made (a
`variable rs_F_t0 equal $(time)` at the move fix's line), gives the same velocity and
the same displacement every step. Translations superpose (LIGGGHTS adds each mover's
displacement and velocity): the rate is the sum of the active fixes' rates.

Several movers of one mesh act in the order they were made (FixMesh::move and ::rotate):
each moves the mesh, then carries the reference point (a rotation's origin) of itself and
of the movers made after it; the first mover's point is put back each step
(FixMoveMesh::get_reference_point). A rotation made while translations run therefore
turns about an origin the translations carry, which is wall/rigid's `move` + `rotate`
(its origin moves with the translation); a rotation made while no other mover runs
comes first, and a translation made while it runs leaves its origin in place in space:
`rotate ... centre fixed`. One wall has one of the two. A rotation made while the
mesh's first mover, a rotation, runs turns about an origin that rotation carries, its
axis keeping its direction in space: wall/rigid's `spin`.
"""
import math
import re

TRANSLATIONS = ("linear", "linear/variable", "wiggle", "viblin")
ROTATIONS = ("rotate", "rotate/variable", "riggle", "vibrot")
LIN, ROT, SPIN = ("vx", "vy", "vz"), ("om",), ("om2",)
# The longest run over which the tool sums an oscillating translation's steps.
MAX_SUM_STEPS = 10 ** 7
NUMBER = re.compile(r"(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?")


def par(word):
    """A deck word as a factor of a formula: a number as written, else in parentheses."""
    return word if NUMBER.fullmatch(word) else "(%s)" % word


def is_zero(num, word):
    return num.value(word) == 0.0


def vname(x):
    return x if x.startswith("v_") else "v_" + x


def t_since(fid):
    return "(time-v_rs_%s_t0)" % fid


def harmonics(a, k, n, t):
    """-sum_j a_j w_j sin(w_j t + p_j), w_j = 2 pi / P_j: the rate of LIGGGHTS's viblin and
    vibrot, from the words 'amplitude a_1..a_n phase p_1..p_n period P_1..P_n' at a[k:]."""
    amp, ph, per = a[k + 1:k + 1 + n], a[k + 2 + n:k + 2 + 2 * n], a[k + 3 + 2 * n:]
    terms = ["-%s*2*PI/%s*sin(2*PI/%s*%s+%s)" % (par(amp[j]), par(per[j]), par(per[j]), t,
                                                  par(ph[j])) for j in range(n)]
    return "".join(terms)


def unit(num, words):
    """The axis, normalized as LIGGGHTS does (vectorNormalize3D), as numbers; None when
    its components are not numbers the tool can compute."""
    v = [num.value(x) for x in words]
    if None in v or not any(v):
        return None
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


def order(num, a, k, style, tail):
    """The number of harmonics K of viblin or vibrot ('order K' at a[k:]) when the line
    has the words that K needs (tail: the words before 'order'), else a reason."""
    n = num.value(a[k + 1]) if len(a) > k + 1 and a[k] == "order" else None
    if n is None or n != int(n) or not 1 <= n <= 30:
        return None, "move/mesh %s: its order is not a number from 1 to 30" % style
    n = int(n)
    want = [(k + 2, "amplitude"), (k + 3 + n, "phase"), (k + 4 + 2 * n, "period")]
    if len(a) != k + 5 + 3 * n or any(a[i] != w for i, w in want):
        return None, ("move/mesh %s arguments not understood (%s order K amplitude a_1..a_K "
                      "phase p_1..p_K period P_1..P_K)" % (style, tail))
    return n, None


def wave(num, amp, per, ph, kind):
    """A numeric rate of t from the words of amplitudes, periods and phases: kind 'cos'
    is a w cos(w t) (wiggle), 'sin' is -sum_j a_j w_j sin(w_j t + p_j) (viblin); None
    when a word is not a number the tool can compute."""
    a, p, f = ([num.value(x) for x in ws] for ws in (amp, per, ph))
    if None in a + p + f or 0.0 in p:
        return None
    w = [2 * math.pi / x for x in p]
    if kind == "cos":
        return lambda t: a[0] * w[0] * math.cos(w[0] * t)
    return lambda t: -sum(aj * wj * math.sin(wj * t + fj) for aj, wj, fj in zip(a, w, f))


def parse(style, a, ra, fid, num):
    """One move/mesh line's motion, from its words a (as substituted) and ra (as written,
    where they can be: the rates' text): a dict with kind 'linear' or 'rotate', its rates
    (by name), the constant velocity (vals, for the displacement a later rotation's origin
    needs; None when it varies), for a rotation the origin and axis (words and values),
    and t0 (whether it needs the time origin); or a string, why it cannot be read."""
    t = t_since(fid)
    if style in ("linear", "linear/variable"):
        if len(a) != 3:
            return "move/mesh %s arguments not understood" % style
        if style == "linear":
            vals = [num.value(x) for x in a]
            return dict(kind="linear", rates=dict(zip(LIN, ra)), t0=False, vals=vals,
                        vel=None if None in vals else (lambda tt: vals))
        return dict(kind="linear", rates=dict(zip(LIN, [vname(x) for x in ra])), t0=False,
                    vals=None, vel=None)
    if style == "wiggle":
        if len(a) != 6 or a[0] != "amplitude" or a[4] != "period":
            return "move/mesh wiggle arguments not understood (amplitude AX AY AZ period P)"
        w = "2*PI/%s" % par(ra[5])
        rates = {k: "0" if is_zero(num, x) else "%s*%s*cos(%s*%s)" % (par(r), w, w, t)
                 for k, x, r in zip(LIN, a[1:4], ra[1:4])}
        v = wave(num, ["1"], a[5:6], ["0"], "cos")
        amp = [num.value(x) for x in a[1:4]]
        vel = None if v is None or None in amp else \
            (lambda tt: [c * v(tt) for c in amp])
        return dict(kind="linear", rates=rates, t0=True, vals=None, vel=vel)
    if style == "viblin":
        if len(a) < 5 or a[0] != "axis":
            return "move/mesh viblin arguments not understood (axis AX AY AZ order K ...)"
        n, why = order(num, a, 4, style, "axis AX AY AZ")
        if why:
            return why
        e = unit(num, a[1:4])
        if e is None:
            return "move/mesh viblin: its axis is not a non-zero vector of numbers"
        s = harmonics(ra, 6, n, t)
        rates = {k: "0" if x == 0.0 else "%r*(%s)" % (x, s) for k, x in zip(LIN, e)}
        v = wave(num, a[7:7 + n], a[9 + 2 * n:], a[8 + n:8 + 2 * n], "sin")
        vel = None if v is None else (lambda tt: [c * v(tt) for c in e])
        return dict(kind="linear", rates=rates, t0=True, vals=None, vel=vel)
    if style in ROTATIONS:
        if len(a) < 10 or a[0] != "origin" or a[4] != "axis":
            return "move/mesh %s arguments not understood (origin X Y Z axis AX AY AZ ...)" \
                % style
        rot = dict(kind="rotate", origin=a[1:4], axis=a[5:8], t0=style in ("riggle", "vibrot"),
                   vals=None)
        if style in ("rotate", "rotate/variable"):
            key = "period" if style == "rotate" else "omega"
            if len(a) != 10 or a[8] != key:
                return "move/mesh %s arguments not understood" % style
            om = "2*PI/(%s)" % ra[9] if style == "rotate" else vname(ra[9])
        elif style == "riggle":
            if len(a) != 12 or a[8] != "period" or a[10] != "amplitude":
                return ("move/mesh riggle arguments not understood (origin X Y Z axis AX AY "
                        "AZ period P amplitude A)")
            w = "2*PI/%s" % par(ra[9])
            om = "%s*PI/180*%s*cos(%s*%s)" % (par(ra[11]), w, w, t)
        else:
            n, why = order(num, a, 8, style, "origin X Y Z axis AX AY AZ")
            if why:
                return why
            om = harmonics(ra, 10, n, t)
        rot["rates"] = {"om": om}
        return rot
    return "move/mesh %s has no wall/rigid motion yet" % style


def total(active, kind, key):
    """The rate KEY of a mesh: the sum of its active fixes' of that kind."""
    terms = [mo["rates"][key] for mo in active.values() if mo["kind"] == kind]
    terms = [x for x in terms if x != "0"]
    if not terms:
        return "0"
    return terms[0] if len(terms) == 1 else "+".join("(%s)" % x for x in terms)


def rate_lines(mid, active, kind):
    keys = keys_of(kind)
    return ["variable rs_%s_%s equal %s" % (mid, k, total(active, kind, k)) for k in keys]


def follow(mg, num, fmt):
    """Follows every fix move/mesh of mg's meshes over the deck's trace (the commands in
    the order they ran): the lines that set each mesh's rates (state 'lines': Exec ->
    text), the rates set before the wall exists, the rotation axis, and the displacement
    a later rotation's origin needs. num.value(word) is a word's number or None."""
    dt, restart = None, None
    st = {}
    mg.motion_state = st
    for ex in mg.deck.trace:
        w = ex.words
        if w[0] == "timestep" and len(w) > 1:
            dt = num.value(w[1])
        elif w[0] == "read_restart":
            restart = ex.cmd.where()
        elif w[0] == "run" and len(w) > 1:
            nsteps = ex.nsteps
            for mid, s in st.items():
                if not s["active"]:
                    continue
                if not s["wall"]:
                    mg.meshes[mid].reasons.append("%s runs while it moves and before "
                                                  "its wall exists" % ex.cmd.where())
                for mo in s["active"].values():
                    if mo["kind"] == "linear" and s["D"] is not None:
                        s["D"] = advance(s["D"], mo, nsteps, dt)
                    mo["k"] = None if nsteps is None or mo["k"] is None else mo["k"] + nsteps
        elif w[0] == "unfix" and len(w) > 1:
            for mid, s in st.items():
                if w[1] in s["active"]:
                    kind = s["active"].pop(w[1])["kind"]
                    s["lines"][ex] = rate_lines(mid, s["active"], kind)
        elif w[0] == "fix" and len(w) >= 4 and w[3] == "wall/gran" and "mesh" in w:
            for mid in w[w.index("mesh"):]:
                if mid in st:
                    st[mid]["wall"] = True
                    st[mid]["pre_wall"] = set(st[mid]["assigned"])
        elif w[0] == "fix" and len(w) >= 4 and w[3].startswith("mesh/surface") and \
                w[1] in mg.meshes:
            st[w[1]] = blank()
        elif w[0] == "fix" and len(w) >= 7 and w[3] == "move/mesh" and w[4] == "mesh" \
                and w[5] in st:
            move(ex, num, st[w[5]], mg.meshes[w[5]], restart, fmt)


def blank():
    """A mesh's motion state before any move/mesh."""
    return dict(active={}, wall=False, D=[0.0, 0.0, 0.0], D_rot=None, rot=None,
                lin_used=False, lin_since_rot=False, assigned=set(), pre_wall=set(),
                lines={}, centre=None, spin=None)


def advance(D, mo, nsteps, dt):
    """The displacement D after nsteps more of a translating fix, as LIGGGHTS sums it:
    v(k dt) dt at its k-th step since it was made; None where the tool cannot know it."""
    if nsteps is None or dt is None or mo["vel"] is None or mo["k"] is None:
        return None
    if mo["vals"] is not None:
        return [d + v * nsteps * dt for d, v in zip(D, mo["vals"])]
    if nsteps > MAX_SUM_STEPS:
        return None
    k0 = int(mo["k"])
    acc = [0.0, 0.0, 0.0]
    for k in range(k0 + 1, k0 + int(nsteps) + 1):
        acc = [x + v for x, v in zip(acc, mo["vel"](k * dt))]
    return [d + x * dt for d, x in zip(D, acc)]


def move(ex, num, s, m, restart, fmt):
    c = ex.cmd
    fid, style, mid = ex.words[1], ex.words[6], ex.words[5]
    mo = parse(style, ex.words[7:], [ex.rawword(k, x) for k, x in enumerate(ex.words)][7:],
               fid, num)
    if isinstance(mo, str):
        m.reasons.append("%s: %s" % (c.where(), mo))
        return
    mo["k"] = 0
    kinds = {x["kind"] for x in s["active"].values()}
    if mo["t0"] and restart is not None:
        m.reasons.append("%s: move/mesh %s after read_restart (%s): LIGGGHTS "
                            "takes the time since the fix was made from the restart file"
                            % (c.where(), style, restart))
    if mo["kind"] == "linear":
        if "spin" in kinds:
            # a mover carries the origins of the movers made after it only: this
            # translation leaves the spin's origin where the first rotation puts it,
            # where wall/rigid's move carries the spin's point
            m.reasons.append("%s moves it while two rotations turn it: LIGGGHTS's "
                                "translation, made after them, does not carry the second "
                                "one's origin, which wall/rigid's would" % c.where())
        if "rotate" in kinds:
            rid = [f for f, x in s["active"].items() if x["kind"] == "rotate"][0]
            # the rotation came first: its origin stays in space; else a translation
            # that ran when it was made carries its origin, and so does this one
            centre(c, s, m, "fixed" if s["active"][rid]["first"] else "moving", rid)
        s["lin_used"] = True
        if s["rot"] is not None:
            s["lin_since_rot"] = True
    elif "rotate" in kinds:
        spin(c, s, m, mo)
    else:
        if "spin" in kinds:
            m.reasons.append("%s turns it while a second rotation turns it: "
                                "wall/rigid has a rotation and a spin" % c.where())
        # a rotation made while translations run: they come first among the mesh's movers
        # and carry its origin (FixMesh::move), as wall/rigid's translation carries the
        # rotation's origin; made alone, it is the first mover
        mo["first"] = not s["active"]
        if "linear" in kinds:
            centre(c, s, m, "moving", None)
        rotation(c, num, s, m, mo, fmt)
    s["active"][fid] = mo
    pre = ["variable rs_%s_t0 equal $(time)" % fid] if mo["t0"] else []
    s["lines"][ex] = pre + rate_lines(mid, s["active"], mo["kind"])
    s["assigned"] |= set(keys_of(mo["kind"]))


def keys_of(kind):
    return LIN if kind == "linear" else SPIN if kind == "spin" else ROT


def spin(c, s, m, mo):
    """A rotation made while another runs: LIGGGHTS's second mover, whose origin the
    first carries (FixMesh::rotate) and whose axis keeps its direction in space, is
    wall/rigid's spin. The first must be the mesh's first mover (its origin fixed in
    space), the wall not yet turned nor translated, so the origin as given is the spin's
    point in the wall's reference configuration."""
    first = [x for x in s["active"].values() if x["kind"] == "rotate"][0]
    if s["spin"] is not None or len(s["active"]) != 1 or not first["first"] or \
            first["k"] != 0 or s["lin_used"]:
        m.reasons.append(
            "%s turns it while another move/mesh turns it, where wall/rigid's spin "
            "needs the other to be the mesh's only mover, made at the same point of the "
            "deck, and the mesh not translated before" % c.where())
        return
    mo["kind"] = "spin"
    mo["rates"] = {"om2": mo["rates"]["om"]}
    s["spin"] = (mo["origin"], mo["axis"])


def centre(c, s, m, mode, rid):
    """The wall's rotation centre, 'moving' with its translation or 'fixed' in space, as
    the movers running together at LINE c ask; one wall has one."""
    if s["centre"] not in (None, mode):
        m.reasons.append(
            "%s makes a translation and a rotation run together with the rotation's "
            "origin %s, where before it was %s: one wall/rigid turns about an origin "
            "that is fixed in space or moves with the wall, not both" % (
                c.where(), "carried by the translation" if mode == "moving"
                else "fixed in space (move/mesh %s came first)" % rid,
                "carried by the translation" if s["centre"] == "moving"
                else "fixed in space"))
        return
    s["centre"] = mode


def rotation(c, num, s, m, mo, fmt):
    """The wall's one rotation: origin (in the wall's reference configuration: LIGGGHTS's
    fixed point less the translation so far) and axis, from the first rotating fix; a
    later one must turn about the same axis, with no translation since the first (D_rot,
    the translation then, which a translation made before it and still running moves
    on)."""
    origin, axis = [num.value(x) for x in mo["origin"]], [num.value(x) for x in mo["axis"]]
    if s["rot"] is None:
        if s["lin_used"]:
            if s["D"] is None or None in origin:
                m.reasons.append(
                    "%s turns it about a point after a translation the tool cannot "
                    "compute (it needs the steps run and constant rates)" % c.where())
                return
            o = [fmt(p - d) for p, d in zip(origin, s["D"])]
        else:
            o = mo["origin"]
        s["rot"] = (o, mo["axis"], origin, axis, mo["origin"])
        s["D_rot"] = list(s["D"]) if s["D"] is not None else None
    elif s["lin_since_rot"] or s["D"] != s["D_rot"] or origin != s["rot"][2] \
            or axis != s["rot"][3] or None in origin + axis:
        m.reasons.append("%s turns it about another axis, or after it moved on since "
                            "its first rotation: one wall/rigid has one rotation axis fixed "
                            "in it" % c.where())
