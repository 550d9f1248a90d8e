#!/usr/bin/python3
"""The bonded-interface cases in LIGGGHTS against their closed forms.

Six spheres (R = 5 mm, area projected: A = pi R^2) bonded through a layer of thickness
th to a moving master; the spheres are not integrated, so the layer strain is the wall
motion over th. Props: E = 2e8, nu = 0.3 (G = E / 2.6), yield 1e6, hardening H = 2e7,
th = 1e-3. The wall moves with the velocity of each step (decks); its displacement is
exact, so the closed forms below hold to round-off (1e-9 of the largest value).

- normal:  F_y = -N A E d / th with d = v min(t, T1) - v max(0, t - T1); ALLSE = N A th
           s^2 / (2E); no plastic work. The bond carries tension after 8 ms.
- shear:   plane sliding at u: F_x = -N A G u t / th, ALLSE = N A th tau^2 / (2G).
           shell turning at w: hoop slip w rho t at the contact point radius
           rho = 0.05 - gap / 2, moment M_z = -N A G w rho^2 t / th.
- plastic: loading s = E e up to the yield strain, then s = sy + E H/(E + H) (e - sy/E);
           unloading s = s_max - E (e_max - e); plastic strain e_p = (s - sy) / H while
           loading, plastic work ALLPD = N A th (sy e_p + H e_p^2 / 2).
- thermal: spheres (N m c) and lumped wall (C = N m c) through the layer, conductance
           k A / th per sphere: T_wall - T = 100 exp(-2 k A t / (th m c)), the mean 350 K;
           the heat C (T_wall - 400) is what the spheres gained. Tolerances: energy
           conservation 1e-9 of C 100 K; temperatures 0.02 K (the explicit update's
           error is about 0.003 K here).
Usage: check.py OUTDIR. Prints PASS/FAIL per case with the numbers.
"""
import math
import os
import sys

N, R, RHO = 6, 0.005, 2500.0
A = math.pi * R * R
E, NU, SY, H, TH, GAP = 2.0e8, 0.3, 1.0e6, 2.0e7, 1.0e-3, 1.0e-5
G = E / (2.0 * (1.0 + NU))
TOL = 1e-9


def table(out, name):
    rows = []
    with open(os.path.join(out, "post", name + ".txt")) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            rows.append([float(v) for v in line.split()])
    return rows


def worst(rows, col, fn):
    """Largest |sim - closed form| over the rows, relative to the largest |closed form|."""
    big = max(abs(fn(r[0])) for r in rows) or 1.0
    err = max(abs(r[col] - fn(r[0])) for r in rows)
    return err / big, big


def report(name, checks):
    ok = all(c[1] <= c[2] for c in checks)
    print("%s %s" % ("PASS" if ok else "FAIL", name))
    for what, err, tol, detail in checks:
        print("     %-34s rel. error %.2e (tol %.0e) %s" % (what, err, tol, detail))
    return ok


def normal(out):
    v, t1 = 1.0e-3, 0.004
    rows = table(out, "normal")

    def d(t):
        return v * min(t, t1) - v * max(0.0, t - t1)

    def fy(t):
        return -N * A * E * d(t) / TH

    def se(t):
        s = E * d(t) / TH
        return N * A * TH * s * s / (2.0 * E)

    e_f, big = worst(rows, 2, fy)
    e_se, _ = worst(rows, 3, se)
    pd = max(abs(r[4]) for r in rows)
    last = rows[-1]
    return report("normal (compression, unloading, tension)", [
        ("F_y = -N A E d / th", e_f, TOL,
         "| max %.2f N; at %.0f ms %.4f N (closed form %.4f)"
         % (big, 1e3 * last[0], last[2], fy(last[0]))),
        ("ALLSE = N A th s^2 / (2E)", e_se, TOL, ""),
        ("ALLPD = 0 (elastic)", pd, TOL, "| %.3g J" % pd),
    ])


def shear(out):
    u, w = 1.0e-3, 0.02
    rho = 0.05 - GAP / 2.0
    rows = table(out, "shear")

    def fx(t):
        return -N * A * G * u * t / TH

    def mz(t):
        return -N * A * G * w * rho * rho * t / TH

    def se_p(t):
        tau = G * u * t / TH
        return N * A * TH * tau * tau / (2.0 * G)

    def se_s(t):
        tau = G * w * rho * t / TH
        return N * A * TH * tau * tau / (2.0 * G)

    e_fx, bfx = worst(rows, 1, fx)
    e_fy = max(abs(r[2]) for r in rows) / bfx
    e_sp, _ = worst(rows, 3, se_p)
    e_mz, bmz = worst(rows, 4, mz)
    e_ss, _ = worst(rows, 5, se_s)
    return report("shear (plane sliding along t2; shell turning: hoop slip)", [
        ("plane F_x = -N A G u t / th", e_fx, TOL, "| max %.3f N" % bfx),
        ("plane F_y = 0", e_fy, TOL, ""),
        ("plane ALLSE = N A th tau^2 / (2G)", e_sp, TOL, ""),
        ("shell M_z = -N A G w rho^2 t / th", e_mz, TOL, "| max %.5f N m" % bmz),
        ("shell ALLSE", e_ss, TOL, ""),
    ])


def plastic(out):
    v, t1 = 1.0e-3, 0.02
    rows = table(out, "plastic")
    et = E * H / (E + H)
    e_max = v * t1 / TH

    def load(e):
        return E * e if E * e <= SY else SY + et * (e - SY / E)

    s_max = load(e_max)

    def stress(t):
        if t <= t1:
            return load(v * t / TH)
        return s_max - E * v * (t - t1) / TH

    def ep(t):
        s = load(v * min(t, t1) / TH)
        return max(0.0, (s - SY) / H)

    def fy(t):
        return -N * A * stress(t)

    def se(t):
        s = stress(t)
        return N * A * TH * s * s / (2.0 * E)

    def pd(t):
        p = ep(t)
        return N * A * TH * (SY * p + 0.5 * H * p * p)

    e_f, big = worst(rows, 1, fy)
    e_se, _ = worst(rows, 2, se)
    e_pd, bpd = worst(rows, 3, pd)
    last = rows[-1]
    return report("plastic (linear hardening, elastic unloading into tension)", [
        ("F_y = -N A s(e)", e_f, TOL,
         "| peak %.2f N (yield at %.2f N); end %.3f N (closed form %.3f)"
         % (big, N * A * SY, last[1], fy(last[0]))),
        ("ALLSE = N A th s^2 / (2E)", e_se, TOL, ""),
        ("ALLPD = N A th (sy e_p + H e_p^2/2)", e_pd, TOL,
         "| %.6e J (closed form %.6e)" % (last[3], pd(last[0]))),
    ])


def thermal(out):
    k, c = 10.0, 100.0
    m = RHO * 4.0 / 3.0 * math.pi * R ** 3
    cap = N * m * c
    lam = 2.0 * k * A / (TH * m * c)
    rows = table(out, "thermal")
    e_tp = max(abs(r[1] - (350.0 - 50.0 * math.exp(-lam * r[0]))) for r in rows)
    e_tw = max(abs(r[2] - (350.0 + 50.0 * math.exp(-lam * r[0]))) for r in rows)
    e_cons = max(abs(cap * (r[2] - 400.0) + N * m * c * (r[1] - 300.0)) for r in rows)
    e_q = max(abs(r[3] - cap * (r[2] - 400.0)) for r in rows)
    last = rows[-1]
    tol_t = 0.02
    ok = report("thermal (conduction through the layer, lumped wall)", [
        ("sphere T = 350 - 50 exp(-lam t)", e_tp / 100.0, tol_t / 100.0,
         "| max %.4f K; at %.1f s %.4f K (closed form %.4f), lam = %.2f 1/s"
         % (e_tp, last[0], last[1], 350.0 - 50.0 * math.exp(-lam * last[0]), lam)),
        ("wall T = 350 + 50 exp(-lam t)", e_tw / 100.0, tol_t / 100.0, "| max %.4f K" % e_tw),
        ("heat conserved", e_cons / (cap * 100.0), TOL, "| max %.3g J" % e_cons),
        ("heat into wall = C (T_wall - 400)", e_q / (cap * 100.0), TOL,
         "| %.4f J at the end" % last[3]),
    ])
    return ok


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "out"
    results = [f(out) for f in (normal, shear, plastic, thermal)]
    print("bonded_interface in LIGGGHTS: %d of %d cases PASS" % (sum(results), len(results)))
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main())
