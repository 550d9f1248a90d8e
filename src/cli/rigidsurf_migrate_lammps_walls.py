"""LAMMPS's granular walls as `fix wall/rigid` lines (part of rigidsurf-migrate;
docs/migration.md, *LAMMPS walls*).

- `fix wall/gran MODEL xplane|yplane|zplane lo hi`: a plane at each bound not NULL (lo
  facing +axis, hi facing -axis), `sides 2`: LAMMPS pushes a sphere away from a plane on
  whichever side its centre is (FixWallGran::post_force); `zcylinder R`: the cylinder of
  radius R about the z axis, `sides 2`;
- `wiggle dim A P`: LAMMPS's velocity A w sin(w (step - s0) dt), w = 2 pi / P, s0 the
  step the fix was made at, the same formula: along a plane (or a zcylinder's axis),
  which moves the wall's material and not its shape, the rate of `move linear`; along a
  plane's normal the velocity of `move variable`, whose translation is LAMMPS's place of
  the plane, A - A cos(w (step - s0) dt); `shear dim V`: `surface_vel`;
- `fix wall/gran/region MODEL region ID`: the region's surfaces
  (rigidsurf_migrate_lammps_regions.py), one wall/rigid each, the first with the fix's
  ID; a region moved by `move v_x v_y v_z` and turned by `rotate v_theta P A` gets
  `move linear` and `rotate` whose rates are LAMMPS's (Region::set_velocity): the change
  of the variables since the last step over dt, the last step's values kept by a `fix
  ave/time 1 1 1` of them;
- the model: `law lammps` with the model words as written; on curved faces `reff
  region` (cylinders, cones: LAMMPS's region walls take -2 r as the wall's radius of
  curvature) or the exact effective radius (spheres: LAMMPS takes -Rs, which is exact);
- a region's one-sided surfaces `behind none`: LAMMPS's region wall leaves alone a
  particle whose centre lies outside its region (FixWallGranRegion::post_force asks
  Region::match), as wall/rigid's one-sided surface then leaves alone one behind it;
- `contacts`: `store_force`, whose per-atom force_ID stands for LAMMPS's f_ID[2-4].
"""
import math
import os

import rigidsurf_migrate_lammps_commands as grammar
import rigidsurf_migrate_lammps_regions as geo
from rigidsurf_migrate_commands import Grammar
from rigidsurf_migrate_deck import DeckError
from rigidsurf_migrate_motion import par
from rigidsurf_migrate_walls import number, wrap

PLANES = ("xplane", "yplane", "zplane")


def num(v):
    """A computed coordinate, exactly (the shortest text of the double), an integer
    without its point, no negative zero."""
    if isinstance(v, str):
        return v
    if v == 0.0:
        return "0"
    if v == int(v) and abs(v) < 1e15:
        return "%d" % v
    return repr(v)


class Wall:
    """A `fix wall/gran` or `fix wall/gran/region` line as it ran (observed: what the
    deck held where it ran, for a region wall: the region and the values of its motion's
    variables)."""

    def __init__(self, ex, observed):
        w = ex.words
        self.ex, self.cmd, self.id, self.group = ex, ex.cmd, w[1], w[2]
        self.id_raw, self.group_raw = ex.rawword(1, w[1]), ex.rawword(2, w[2])
        self.style = w[3]
        self.reasons, self.notes, self.pre, self.pieces = [], [], [], []
        self.ok, self.why, self.prev, self.modifies = False, [], None, []
        try:
            self.g = grammar.Wall(w[4:], self.style == "wall/gran/region")
        except Grammar as e:
            raise DeckError(ex.via or ex.cmd, "fix %s: %s" % (self.id, e))
        self.raw = lambda k: ex.rawword(4 + k, w[4 + k])
        self.word = lambda k: w[4 + k]
        self.model = [self.raw(k) for k in self.g.model]
        self.observed = observed
        self.contacts = self.g.contacts

    # -- the surfaces --------------------------------------------------------------
    def build(self, ctx, number_of):
        """The wall's surfaces and motion: self.pieces [(fix ID, Surf)], self.pre (the
        lines before the wall: its rates), self.motion (wall/rigid's words); reasons where
        no exact surface reproduces LAMMPS's."""
        self.motion, self.vel = [], None
        try:
            surfs = self.primitive(ctx) if self.style == "wall/gran" else \
                self.region_surfaces(ctx, number_of)
        except geo.Unmigratable as e:
            self.reasons.append(str(e))
            return
        ids = [self.id_raw] + ["rs_%s_%d" % (self.id, k + 2) for k in range(len(surfs) - 1)]
        self.pieces = list(zip(ids, surfs))

    def primitive(self, ctx):
        g, L = self.g, ctx.L
        if g.wall == "zcylinder":
            R = self.raw(g.values[0])
            if number(self.word(g.values[0])) is None or number(
                    self.word(g.values[0])) <= 0.0:
                raise geo.Unmigratable("zcylinder: its radius '%s' is not a positive number "
                                       "the tool knows" % self.word(g.values[0]))
            s = geo.Surf("revolution", origin=[0.0, 0.0, 0.0], axis=[0.0, 0.0, 1.0],
                         items=[("START", R, -L), ("LINE", R, L)], two_sided=True,
                         curvature={"cyl"})
            surfs = [s]
        else:
            k = "xyz".index(g.wall[0])
            surfs = []
            for j, sign in ((0, 1.0), (1, -1.0)):
                word = self.word(g.values[j])
                if word == "NULL":
                    continue
                if number(word) is None:
                    raise geo.Unmigratable("%s: '%s' is not a number the tool knows" % (
                        g.wall, word))
                p = [0.0, 0.0, 0.0]
                p[k] = self.raw(g.values[j])
                n = [0.0, 0.0, 0.0]
                n[k] = sign
                surfs.append(geo.Surf("plane", point=p, normal=n, two_sided=True))
            if not surfs:
                raise geo.Unmigratable("%s NULL NULL: no wall" % g.wall)
        if g.wiggle:
            self.wiggle(ctx)
        if g.shear:
            self.shear()
        return surfs

    def wiggle(self, ctx):
        g = self.g
        dim, A, P = (self.word(k) for k in g.wiggle)
        rA, rP = (self.raw(k) for k in g.wiggle[1:])
        a, p = number(A), number(P)
        if a is None or p is None or p == 0.0:
            raise geo.Unmigratable("wiggle: its amplitude and period are not numbers the "
                                   "tool knows")
        if abs(a) > ctx.L / 4:
            raise geo.Unmigratable("wiggle: its amplitude reaches past the wall's ends")
        s0 = self.ex.step
        w = "(2*PI/%s)" % par(rP)
        arg = "%s*(step-%s)*dt" % (w, s0 if s0 is not None else "v_rs_%s_s0" % self.id)
        if s0 is None:
            self.pre.append("variable rs_%s_s0 equal $(step)" % self.id)
        self.pre.append("variable rs_%s_w equal %s*%s*sin(%s)" % (self.id, par(rA), w, arg))
        rate = ["v_rs_%s_w" % self.id if d == dim else "0" for d in "xyz"]
        if g.wall.endswith("plane") and g.wall[0] == dim:
            # along the normal: LAMMPS places the plane at lo + A - A cos(arg) and gives
            # it the velocity A w sin(arg), each a formula of the step
            self.pre.append("variable rs_%s_d equal %s-%s*cos(%s)" % (self.id, par(rA),
                                                                      par(rA), arg))
            self.motion = ["move", "variable"] + [
                "v_rs_%s_d" % self.id if d == dim else "0" for d in "xyz"] + rate
        else:
            # along the plane or the cylinder's axis: the wall's material moves, its
            # shape stays where it is
            self.motion = ["move", "linear"] + rate

    def shear(self):
        g = self.g
        dim, V = self.word(g.shear[0]), self.raw(g.shear[1])
        if g.wall == "zcylinder" and dim != "z":
            raise geo.Unmigratable(
                "shear %s of zcylinder: LAMMPS adds V (y/r, -x/r, 0) of each touching "
                "particle to one wall velocity that it does not reset between particles "
                "(FixWallGran::post_force): no wall has that velocity" % dim)
        self.motion = ["surface_vel"] + [V if d == dim else "0" for d in "xyz"]

    def region_surfaces(self, ctx, number_of):
        reg, regions, vals = self.observed
        surfs = geo.surfaces(reg, regions, ctx, number_of)
        if reg.members and not all(regions[m].open for m in reg.members):
            self.notes.append(
                "region %s is %s: LAMMPS gives a particle the faces of the members its "
                "centre lies in, wall/rigid the faces of the %s's outline; where a sphere "
                "reaches across the join of two members' faces, wall/rigid gives it both "
                "(their shares summing to one: docs/conventions.md), LAMMPS one of them" % (
                    reg.id, "a union" if reg.style == "union" else "an intersection",
                    "union" if reg.style == "union" else "intersection"))
        if not (reg.move or reg.rotate):
            return surfs
        names = []
        D0 = [0.0, 0.0, 0.0]
        for d, word in enumerate(reg.move or ()):
            if word != "NULL":
                names.append(word)
                D0[d] = self.value(vals, word)
        theta0, P, axis = 0.0, None, None
        if reg.rotate:
            names.append(reg.rotate[0])
            theta0 = self.value(vals, reg.rotate[0])
            nums = [number(x) for x in reg.rotate[1:]]
            if None in nums:
                raise geo.Unmigratable("region %s: rotate's point and axis are not numbers "
                                       "the tool knows" % reg.id)
            sc = ctx.lattice if reg.units == "lattice" else (1.0, 1.0, 1.0)
            if isinstance(sc, str):
                raise geo.Unmigratable("region %s is in lattice units, and %s" % (reg.id,
                                                                                   sc))
            P = [x * s for x, s in zip(nums[:3], sc)]
            a = nums[3:]
            length = math.sqrt(sum(x * x for x in a))
            if length == 0.0:
                raise DeckError(self.cmd, "region %s: Region cannot have 0 length rotation "
                                "vector" % reg.id)
            if abs(length - 1.0) > 1e-12:
                raise geo.Unmigratable(
                    "region %s: its rotation axis has length %g: LAMMPS turns the region "
                    "about the unit axis but gives the wall the angular velocity theta' "
                    "times the axis as written (Region::set_velocity), which no turning "
                    "wall has; write the axis as a unit vector" % (reg.id, length))
            axis = [x / length for x in a]
        if theta0 != 0.0 or any(D0):
            geo.place(surfs, P or [0.0, 0.0, 0.0], theta0, axis or [0.0, 0.0, 1.0], D0)
        self.prev = "rs_%s_prev" % self.id
        slot = (lambda i: "f_%s[%d]" % (self.prev, i + 1)) if len(names) > 1 else \
            (lambda i: "f_%s" % self.prev)
        self.pre.append("fix %s all ave/time 1 1 1 %s" % (self.prev, " ".join(names)))
        rates, i = [], 0
        for d, word in enumerate(reg.move or ("NULL",) * 3):
            if word == "NULL":
                rates.append("0")
                continue
            name = "rs_%s_v%s" % (self.id, "xyz"[d])
            self.pre.append("variable %s equal (%s-%s)/dt" % (name, word, slot(i)))
            rates.append("v_" + name)
            i += 1
        if reg.move:
            self.motion += ["move", "linear"] + rates
        if reg.rotate:
            name = "rs_%s_om" % self.id
            self.pre.append("variable %s equal (%s-%s)/dt" % (name, reg.rotate[0], slot(i)))
            origin = [p + d for p, d in zip(P, D0)]
            self.motion += ["rotate", "origin"] + [num(x) for x in origin] + ["axis"] + [
                num(x) for x in axis] + ["omega", "v_" + name]
        return surfs

    def value(self, vals, word):
        v = vals.get(word)
        if not isinstance(v, float):
            raise geo.Unmigratable("%s where the wall is made: %s" % (
                word, v or "not known to the tool"))
        return v

    # -- the lines ---------------------------------------------------------------------
    def law_words(self, surf):
        words = ["law", "lammps"]
        curved = surf.curvature
        if self.g.style in ("hertz/history", "granular") and curved:
            if curved & {"cyl", "cone"}:
                words += ["reff", "region"]
        return words + self.model

    def lines(self, L, deck_path, files):
        """The wall/rigid lines of the wall (after its pre lines); files: {path: text} the
        meshes to write beside the deck at deck_path."""
        out = list(self.pre)
        many = len(self.pieces) > 1
        for k, (fid, s) in enumerate(self.pieces):
            words = ["fix", fid, self.group_raw, "wall/rigid", "surface", "inline"]
            words += surface_words(s, L, fid, os.path.dirname(os.path.abspath(deck_path)),
                                   os.path.basename(deck_path), files)
            if self.style == "wall/gran/region" and not s.two_sided:
                # LAMMPS's region wall touches the particles on its region's side only
                words += ["behind", "none"]
            words += self.law_words(s)
            if self.contacts:
                words += ["store_force", "into", self.id] if many else ["store_force", "yes"]
            words += self.motion
            out.append(wrap(words))
        return out

    def unfix_lines(self):
        out = ["unfix %s" % fid for fid, _ in reversed(self.pieces)]
        if self.prev:
            out.append("unfix %s" % self.prev)
        return out

    def curvature_notes(self):
        """What the law's curvature differs by from LAMMPS's, per kind of face."""
        notes = []
        if self.g.style not in ("hertz/history", "granular"):
            return notes
        for fid, s in self.pieces:
            who = "its wall %s: " % fid if len(self.pieces) > 1 else ""
            if "cone" in s.curvature:
                notes.append(
                    "%sa cone face (half-angle up to %.4g degrees): LAMMPS's region "
                    "takes -2 r as the wall's radius of curvature (r the cone's radius at "
                    "the contact), law lammps reff region -2 r / cos(beta), %.4g times it "
                    "(docs/lammps.md)" % (who, s.beta, 1.0 / math.cos(math.radians(s.beta))))
            if self.style == "wall/gran/region" and s.two_sided and \
                    s.curvature & {"cyl", "cone"}:
                notes.append(
                    "%san open region's outer side: LAMMPS takes it flat there "
                    "(RegCylinder::surface_exterior's open branch), law lammps reff "
                    "region +2 r" % who)
        return notes


def surface_words(s, L, fid, deck_dir, deck_name, files):
    """The words after 'surface inline' of a Surf; a mesh's file, DECK_NAME.FID.stl in
    the deck's folder, goes to files."""
    sides = ["sides", "2"] if s.two_sided else []
    if s.kind == "plane":
        a, b, c = plane_points(s.point, s.normal)
        return (["cylinder", "a"] + a + ["b"] + b + ["c"] + c + sides +
                ["profile", "START", num(-L), "0", "LINE", num(L), "0", "end"])
    if s.kind == "revolution":
        return (["revolution", "origin"] + [num(x) for x in s.origin] + ["axis"] +
                [num(x) for x in s.axis] + sides + ["profile"] + items_words(s.items) +
                ["end"])
    if s.kind == "extrusion":
        return (["cylinder", "a"] + [num(x) for x in s.a] + ["b"] + [num(x) for x in s.b] +
                ["c"] + [num(x) for x in s.c] + sides + ["profile"] +
                items_words(s.items) + ["end"])
    name = "%s.%s.stl" % (deck_name, fid)
    files[os.path.join(deck_dir, name)] = stl(s.triangles, fid)
    return ["mesh", name, "sides", "2" if s.two_sided else "1"]


def items_words(items):
    out = []
    for it in items:
        out += [it[0]] + [num(x) for x in it[1:]]
    return out


def plane_points(p, n):
    """a, b, c of a CYLINDER whose LINE along local x has the normal n: a = p, b = p +
    x (x the next axis after n's largest component, made normal to n), c = p + x cross n,
    so local y = n. p's components may be words (kept where b and c do not move them)."""
    k = max(range(3), key=lambda i: abs(n[i]))
    t = [0.0, 0.0, 0.0]
    t[(k + 1) % 3] = 1.0
    tn = sum(x * y for x, y in zip(t, n))
    x = [ti - tn * ni for ti, ni in zip(t, n)]
    ln = math.sqrt(sum(v * v for v in x))
    x = [v / ln for v in x]
    z = geo.cross(x, n)

    def shift(off):
        out = []
        for pi, o in zip(p, off):
            if o == 0.0:
                out.append(num(pi))
            else:
                base = number(pi) if isinstance(pi, str) else pi
                out.append(num(base + o))
        return out
    return [num(v) for v in p], shift(x), shift(z)


def stl(tris, name):
    out = ["solid %s" % name]
    for t in tris:
        out.append("facet normal 0 0 0\n outer loop")
        out += [" vertex %s %s %s" % tuple(repr(float(v)) for v in p) for p in t]
        out.append(" endloop\nendfacet")
    out.append("endsolid %s" % name)
    return "\n".join(out) + "\n"
