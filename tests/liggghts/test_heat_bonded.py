#!/usr/bin/python3
"""Heat through law bonded_interface: spheres bonded to a lumped-capacity wall reach
the capacity-weighted mean temperature; a fixed-temperature wall brings them to its own.

Independent answer: energy conservation. With the wall's heat capacity C and the
spheres' m_i c, T_eq = (C T_w0 + sum m_i c T_i0) / (C + sum m_i c). The law's fluxes
are equal and opposite (fluxMst = -fluxSlv), so the explicit update conserves energy
to round-off, and after ~30 relaxation times the residual is below 1e-9 K.
Tolerance 1e-6 relative.

Spheres (R = 5 mm, 2500 kg/m3, c = 100 J/(kg K)) sit 10 um above our plane, inside the
bond cutoff (1e-4), no gravity and no velocity, so they bond and stay put. fix heat/gran
integrates their temperatures from heatFlux; the spheres do not touch each other.
Conduction per sphere: k A / t with k = 1000, t = 1e-3, A = pi R^2 (area projected):
78.5 W/K, so m c / (k A / t) = 1.7 ms; the run is 60 ms.
"""
import math

import liglib as L

R, RHO, CP, DT, STEPS = 0.005, 2500.0, 100.0, 1.0e-5, 6000
K, THICK, CUTOFF = 1000.0, 1.0e-3, 1.0e-4
T0 = (300.0, 400.0, 500.0)
TW0, CW = 350.0, 0.5
PROPS = "%r 1e7 0.3 1e9 0 %r %r" % (CUTOFF, THICK, K)


def deck(tag, wall_heat):
    extra = ("fix ftco all property/global thermalConductivity peratomtype 10 10\n"
             "fix ftca all property/global thermalCapacity peratomtype %r %r\n" % (CP, CP))
    d = L.header((-0.1, 0.1, -0.1, 0.1, -0.05, 0.1), DT, extra_props=extra)
    for k, t in enumerate(T0):
        d += L.sphere(k + 1, (0.03 * (k - 1), 0, R + 1e-5), R, RHO)
    d += "fix heat all heat/gran initial_temperature 300\n"
    d += "run 0\n"  # LIGGGHTS: 'set' on a new property/atom needs a prior run
    for k, t in enumerate(T0):
        d += "set atom %d property/atom Temp %r\n" % (k + 1, t)
    d += ("fix w all wall/rigid surface plane.inp law bonded_interface props %s type 2 "
          "area projected %s\n" % (PROPS, wall_heat))
    d += "fix integr all nve/sphere\n"
    d += "variable tw equal f_w[13]\n"
    d += 'fix pr all print %d "${tw}" screen no file %s.tw\n' % (STEPS // 4, tag)
    d += L.dump_lines("d", STEPS, tag + ".dump", "id z f_Temp[0]")
    d += "run %d\n" % STEPS
    return d


def body(s):
    s.write("plane.inp", L.plane_z(0.0, 1.0))
    m = RHO * 4.0 / 3.0 * math.pi * R ** 3
    t_eq = (CW * TW0 + m * CP * sum(T0)) / (CW + 3 * m * CP)

    s.run("lumped", deck("lumped", "temperature %r capacity %r" % (TW0, CW)))
    last = L.read_dump(s.path("lumped.dump"))[-1][1]
    tw = L.read_table(s.path("lumped.tw"))
    for i in (1, 2, 3):
        s.ck.check("lumped: sphere %d reaches T_eq = %.6f" % (i, t_eq),
                   L.rel_diff(last[i]["f_Temp[0]"], t_eq, 0) <= 1e-6,
                   "%.9f" % last[i]["f_Temp[0]"])
    s.ck.check("lumped: wall reaches T_eq", L.rel_diff(tw[-1][0], t_eq, 0) <= 1e-6,
               "%.9f" % tw[-1][0])
    s.ck.check("lumped: the wall temperature moved (it is not held fixed)",
               abs(tw[0][0] - TW0) > 1.0, "after %d steps %.6f" % (STEPS // 4, tw[0][0]))
    s.ck.check("lumped: spheres stayed bonded in place",
               all(abs(last[i]["z"] - (R + 1e-5)) < 1e-9 for i in (1, 2, 3)))

    s.run("fixed", deck("fixed", "temperature %r" % TW0))
    last = L.read_dump(s.path("fixed.dump"))[-1][1]
    tw = L.read_table(s.path("fixed.tw"))
    for i in (1, 2, 3):
        s.ck.check("fixed: sphere %d reaches the wall temperature" % i,
                   L.rel_diff(last[i]["f_Temp[0]"], TW0, 0) <= 1e-6,
                   "%.9f" % last[i]["f_Temp[0]"])
    s.ck.check("fixed: wall temperature held", all(r[0] == TW0 for r in tw),
               " ".join("%.9g" % r[0] for r in tw))


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
