"""Plots the bodies of examples/convex: in the drum (bodies.csv) the height of each
body's centre (y, gravity along -y) and the angle of its body z axis from the drum's
axis against time, into convex.png; down the chute (chute.csv) each body's distance
against time with the closed forms, into chute.png."""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = sys.argv[1]
with open(f"{out}/bodies.csv", newline="") as f:
    rows = list(csv.DictReader(f))
t = [float(r["t"]) for r in rows]
fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(8, 6))
for name in ("tablet", "capsule", "die"):
    ax1.plot(t, [1000 * float(r[f"{name}_y"]) for r in rows], label=name)
    ax2.plot(t, [float(r[f"{name}_tilt"]) for r in rows], label=name)
ax1.axhline(-100, color="k", lw=0.8)
ax1.set_ylabel("height of the centre y (mm)")
ax1.set_title("convex bodies in the drum (radius 100 mm) turning at 3 rad/s")
ax1.legend(loc="upper right")
ax2.set_ylabel("body z axis from the drum axis (deg)")
ax2.set_xlabel("time (s)")
fig.tight_layout()
fig.savefig(f"{out}/convex.png", dpi=100)
print(f"{out}/convex.png")

with open(f"{out}/chute.csv", newline="") as f:
    rows = list(csv.DictReader(f))
t = [float(r["t"]) for r in rows]
g, th, mu = 9.81, math.radians(30.0), 0.3
fig, ax = plt.subplots(figsize=(8, 4))
for name in ("tablet", "die", "capsule"):
    ax.plot(t, [1000 * float(r[name]) for r in rows], label=name)
a = g * (math.sin(th) - mu * math.cos(th))
s0 = float(rows[0]["tablet"])
ax.plot(t, [1000 * (s0 + 0.5 * a * x * x) for x in t], "k:", label="g (sin - mu cos) t^2 / 2")
ax.set_xlabel("time (s)")
ax.set_ylabel("distance down the slope (mm)")
ax.set_title("down a faceted chute at 30 degrees, friction 0.3")
ax.legend()
fig.tight_layout()
fig.savefig(f"{out}/chute.png", dpi=100)
print(f"{out}/chute.png")
