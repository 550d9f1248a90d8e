#!/usr/bin/python3
"""The rounded polyhedra in the rotating drum (in.bodies): plot and check.

Reads OUTDIR/bodies.data (the bodies as given: inertia tensor, vertices, faces, rounding),
OUTDIR/post/com.txt (the bed's centre of mass and the drum's speed) and
OUTDIR/post/bodies.dump (each body's mass, centre, velocity, angular momentum and
quaternion). Writes OUTDIR/bodies.png: the dynamic angle of repose against time, the
kinetic energy (translation and rotation) against time, and the last frame seen along the
axis. Prints the numbers and checks three things; exit status 1 if one fails:

- Contained: no body's centre comes nearer the mantle, or an end cap, than the radius of
  the largest ball inside the body (its inner radius: the distance from its centre of mass
  to its nearest face plane, plus the rounding), less a quarter of the rounding radius:
  r_axis <= R - r_in + r/4 and |z| <= H - r_in + r/4, at every dumped frame. A body
  whose centre crossed that line would have pushed its surface more than r/4 into the
  wall (the contacts' overlap is about 1e-5 m).
- Tumbling: the angle from the bed's centre of mass (a flat-topped bed's centre of mass
  lies on the radius normal to its surface: atan2(x_com, -y_com)) in the last 40 % of the
  time at full speed is steady (its two halves differ by at most 4 degrees, while the
  drum turns by more than 50 degrees in that window: a bed carried round rigidly would
  follow it) and its mean lies between 25 and 65 degrees.
- Energy bounded: no body moves faster than a body falling across the whole drum from the
  mantle's speed, sqrt((w R)^2 + 2 g 2R), at any frame; and the mean kinetic energy of the
  bed (translation and rotation) in the second half of the window is within a factor 1.5
  of the first half's.

The rotational energy is 1/2 L . I^-1 L with I the world-frame inertia tensor, I = Q
Q0^T I0 Q0 Q^T: I0 the tensor of the data file (world frame at step 0), Q0 and Q the
rotation of the body's quaternion at step 0 and now (LAMMPS keeps each body in its
principal axes, which it chooses itself).

Lengths in mm, masses in g, times in ms, as in.bodies has them.

With --short (the test suite's run, 200 ms of rotation, too short for a steady angle) the
second check is that the turning wall lifted the bed (its angle reached 25 to 65 degrees),
and the third the speed bound alone (the bed's energy is still changing as it is lifted).

Usage: bodies.py OUTDIR [--short]
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [HERE, os.path.join(HERE, "..", "drum")]
from bodies_vtk import read_custom  # noqa: E402
from angle import read_com  # noqa: E402  (the main job's: time, bed angle, drum speed)

# Units of in.bodies: mm, g, ms (speeds in m/s, energies in mJ)
R_DRUM, HALF = 35.0, 15.0     # drum.inp: radius and half the inner length, mm
G = 9.81e-3                   # mm/ms^2


def read_bodies(path):
    """{id: {"I0": 3x3, "V": [...], "F": [...], "r": rounding}} from the Bodies section."""
    with open(path) as f:
        lines = f.read().split("\n")
    k = next(i for i, l in enumerate(lines) if l.split("#")[0].strip() == "Bodies")
    words = " ".join(lines[k + 1:]).split()
    out, p = {}, 0
    while p < len(words):
        bid, nd = int(words[p]), int(words[p + 2])
        nv, ne, nf = (int(w) for w in words[p + 3:p + 6])
        v = [float(w) for w in words[p + 6:p + 6 + nd]]
        ixx, iyy, izz, ixy, ixz, iyz = v[:6]
        V = [tuple(v[6 + 3 * j:9 + 3 * j]) for j in range(nv)]
        f0 = 6 + 3 * nv + 2 * ne
        F = [[int(c) for c in v[f0 + 4 * j:f0 + 4 * j + 4] if c >= 0] for j in range(nf)]
        out[bid] = {"I0": [[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]], "V": V, "F": F,
                    "r": 0.5 * v[-1]}
        p += 6 + nd
    return out


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def inner_radius(b):
    """Distance from the centre of mass (the origin of V) to the nearest face plane, plus
    the rounding radius."""
    d = []
    for face in b["F"]:
        p0, p1, p2 = (b["V"][c] for c in face[:3])
        n = cross(sub(p1, p0), sub(p2, p0))
        d.append(abs(dot(n, p0)) / math.sqrt(dot(n, n)))
    return min(d) + b["r"]


def quat_mat(q):
    w, x, y, z = q
    return [[w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z]]


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def transpose(a):
    return [[a[j][i] for j in range(3)] for i in range(3)]


def inverse(a):
    c = [[a[(i + 1) % 3][(j + 1) % 3] * a[(i + 2) % 3][(j + 2) % 3]
          - a[(i + 1) % 3][(j + 2) % 3] * a[(i + 2) % 3][(j + 1) % 3] for i in range(3)]
         for j in range(3)]
    det = sum(a[0][k] * c[k][0] for k in range(3))
    return [[c[i][j] / det for j in range(3)] for i in range(3)]


def mean(v):
    return sum(v) / len(v)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "out"
    short = "--short" in sys.argv[2:]
    bodies = read_bodies(os.path.join(out, "bodies.data"))
    frames = read_custom(os.path.join(out, "post", "bodies.dump"))
    t, th, om = read_com(os.path.join(out, "post", "com.txt"))
    steps = sorted(frames)
    dt = t[1] / 250 if len(t) > 1 and t[0] == 0 else None
    if dt is None:
        sys.exit("%s: com.txt does not start at step 0" % out)
    rin = {b: inner_radius(v) for b, v in bodies.items()}
    rnd = min(v["r"] for v in bodies.values())

    # the inverse inertia in each body's LAMMPS frame, from step 0
    first = frames[steps[0]]
    inv_body = {}
    for b, a in first.items():
        q0 = quat_mat([a["c_quat[%d]" % j] for j in (1, 2, 3, 4)])
        inv_body[b] = matmul(transpose(q0), matmul(inverse(bodies[b]["I0"]), q0))

    wmax = max(om)
    vmax_allowed = math.sqrt((wmax * R_DRUM) ** 2 + 2 * G * 2 * R_DRUM)
    tk, ket, ker, worst_r, worst_z, vmax = [], [], [], -1e9, -1e9, 0.0
    for s in steps:
        et = er = 0.0
        for b, a in frames[s].items():
            v2 = a["vx"] ** 2 + a["vy"] ** 2 + a["vz"] ** 2
            et += 0.5 * a["mass"] * v2
            vmax = max(vmax, math.sqrt(v2))
            q = quat_mat([a["c_quat[%d]" % j] for j in (1, 2, 3, 4)])
            L = [a["angmomx"], a["angmomy"], a["angmomz"]]
            Lb = [dot([q[k][i] for k in range(3)], L) for i in range(3)]    # Q^T L
            er += 0.5 * dot(Lb, [dot(inv_body[b][i], Lb) for i in range(3)])
            worst_r = max(worst_r, math.hypot(a["x"], a["y"]) - (R_DRUM - rin[b]))
            worst_z = max(worst_z, abs(a["z"]) - (HALF - rin[b]))
        tk.append(s * dt)
        ket.append(et)
        ker.append(er)

    # the window: the last 40 % of the time at full speed
    full = [ti for ti, w in zip(t, om) if w >= 0.999 * wmax]
    t0, t_end = full[0], t[-1]
    tw = t_end - 0.4 * (t_end - t0)
    win = [a for ti, a in zip(t, th) if ti >= tw]
    half = len(win) // 2
    m, drift = mean(win), abs(mean(win[:half]) - mean(win[half:]))
    s_ = math.sqrt(mean([(a - m) ** 2 for a in win]))
    turned = math.degrees(wmax * (t_end - tw))
    kew = [a + b for ti, a, b in zip(tk, ket, ker) if ti >= tw]
    kh = len(kew) // 2
    k1, k2 = mean(kew[:kh]), mean(kew[kh:])

    fig, (ax, bx, cx) = plt.subplots(1, 3, figsize=(16, 5),
                                     gridspec_kw={"width_ratios": [1.3, 1.3, 1]})
    ts = [ti / 1e3 for ti in t]
    ax.plot(ts, th, "-", color="C0", label="from the bed's centre of mass")
    ax.axhline(m, color="k", ls="--", lw=1,
               label="steady %.1f° ± %.1f° (t ≥ %.2f s)" % (m, s_, tw / 1e3))
    ax.axvspan(tw / 1e3, t_end / 1e3, color="0.9")
    ax.set_xlabel("time (s)")
    ax.set_ylabel("dynamic angle of repose (degrees)")
    ax.set_ylim(-10, max(75, max(th) + 5))
    ax2 = ax.twinx()
    ax2.plot(ts, [1e3 * w for w in om], ":", color="C2")
    ax2.set_ylabel("drum speed (rad/s)", color="C2")
    ax2.set_ylim(0, 2.5e3 * wmax)
    ax.legend(loc="upper left", fontsize=9)
    ax.set_title("%d rounded polyhedra, fix wall/rigid (REVOLUTION)" % len(bodies))

    tks = [ti / 1e3 for ti in tk]
    bx.semilogy(tks, ket, "-", color="C0", label="translation")
    bx.semilogy(tks, ker, "-", color="C1", label="rotation")
    bx.semilogy(tks, [a + b for a, b in zip(ket, ker)], "-", color="k", lw=1, label="total")
    bx.axvspan(tw / 1e3, t_end / 1e3, color="0.9")
    bx.set_xlabel("time (s)")
    bx.set_ylabel("kinetic energy of the bed (mJ)")
    bx.legend(loc="lower right", fontsize=9)
    bx.set_title("kinetic energy")

    last = frames[steps[-1]]
    cx.add_patch(plt.Circle((0, 0), R_DRUM, fill=False, color="k"))
    for b, a in last.items():
        q = quat_mat([a["c_quat[%d]" % j] for j in (1, 2, 3, 4)])
        q0 = quat_mat([first[b]["c_quat[%d]" % j] for j in (1, 2, 3, 4)])
        rot = matmul(q, transpose(q0))        # the turn since step 0
        pts = [[a["x"] + dot(rot[0], p), a["y"] + dot(rot[1], p)] for p in bodies[b]["V"]]
        for face in bodies[b]["F"]:
            cx.add_patch(plt.Polygon([pts[c] for c in face], closed=True, lw=0.3,
                                     ec="0.3", fc="C0" if a["type"] == 1 else "C1",
                                     alpha=0.15))
    ang = math.radians(th[-1])
    cx.plot([-R_DRUM * math.cos(ang), R_DRUM * math.cos(ang)],
            [-R_DRUM * math.sin(ang), R_DRUM * math.sin(ang)], "--", color="C3", lw=1,
            label="free surface from the centre of mass: %.1f°" % th[-1])
    cx.set_aspect("equal")
    cx.set_xlim(-1.1 * R_DRUM, 1.1 * R_DRUM)
    cx.set_ylim(-1.1 * R_DRUM, 1.1 * R_DRUM)
    cx.legend(loc="upper left", fontsize=8)
    cx.set_title("t = %.2f s, along the axis (cubes blue, bricks orange)" % (tk[-1] / 1e3), fontsize=10)
    fig.tight_layout()
    png = os.path.join(out, "bodies.png")
    fig.savefig(png, dpi=110)

    ok_in = worst_r <= rnd / 4 and worst_z <= rnd / 4
    ok_tumble = drift <= 4.0 and 25.0 <= m <= 65.0 and turned > 50.0
    if short:
        ok_tumble = 25.0 <= max(th) <= 65.0
        print("lifted: the bed's angle reached %.1f deg (25 to 65): %s"
              % (max(th), "yes" if ok_tumble else "NO"))
    ok_energy = vmax <= vmax_allowed and (short or (k2 <= 1.5 * k1 and k1 <= 1.5 * k2))
    print("contained: nearest approach of a centre beyond R - r_in: %.3g mm (mantle), "
          "%.3g mm (end caps); allowed r/4 = %.2g mm: %s"
          % (worst_r, worst_z, rnd / 4, "yes" if ok_in else "NO"))
    print("dynamic angle of repose%s, steady (t >= %.2f s, the drum turning %.0f deg): "
          "%.1f deg (std %.1f, halves differ by %.1f): %s"
          % (" (not checked)" if short else "", tw / 1e3, turned, m, s_, drift,
             "" if short else "yes" if ok_tumble else "NO"))
    print("energy: fastest body %.3g m/s (bound %.3g); kinetic energy %.3g then %.3g "
          "(mJ; rotation %.0f %% of it): %s"
          % (vmax, vmax_allowed, k1, k2, 100 * mean([b for ti, b in zip(tk, ker) if ti >= tw])
             / mean(kew), "yes" if ok_energy else "NO"))
    print("plot: %s" % png)
    return 0 if ok_in and ok_tumble and ok_energy else 1


if __name__ == "__main__":
    sys.exit(main())
