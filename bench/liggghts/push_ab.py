#!/usr/bin/python3
"""The bouncing bed (section 1e of bench_walls.py) under its two pushes, interleaved.

    push_ab.py --exe liggghts-rigidsurf [--reps R] [--seed S]

bench_walls.py presses the beds that move only radially with a push stored once per
sphere (fix store/state 0, then copied each step). Before, the push was the atom-style
variable v_f0*x/sqrt(x*x+y*y) evaluated for every sphere at every step, which costs
about twice the walls. The trajectories are the same; what differs is the rest of the
step around the walls. Each repetition runs none, prim and ours under both pushes, six
runs in an order drawn at random, and prints each wall's cost (loop time minus that
push's 'none', µs per particle-step) and ours / prim. At the end: per push, the median
and mean of the repetitions' ratios and the ratio of the mean costs.
"""
import argparse
import os
import random
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench_walls as bw  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", required=True)
    ap.add_argument("--reps", type=int, default=10)
    ap.add_argument("--seed", type=int, default=3, help="seed of the run order")
    args = ap.parse_args()
    exe = os.path.abspath(args.exe)
    work = tempfile.mkdtemp(prefix="rs_push_ab_")
    n = bw.N_BOUNCE
    data, height = bw.write_bed(work, n)
    pushes = ("stored", "per-step")
    decks = {}
    for v in ("none", "prim", "ours"):
        for p in pushes:
            decks[(p, v)] = bw.wall_deck(v, data, bw.STEPS_BOUNCE, height, kick=bw.VKICK,
                                         push_every_step=p == "per-step")
    rng = random.Random(args.seed)
    cost = {(p, w): [] for p in pushes for w in ("prim", "ours")}
    ratios = {p: [] for p in pushes}
    print("bouncing bed, N = %d, %d steps, %d repetitions; wall cost in us per "
          "particle-step" % (n, bw.STEPS_BOUNCE, args.reps))
    for rep in range(args.reps):
        keys = list(decks)
        rng.shuffle(keys)
        t = {}
        for k in keys:
            r = bw.run_deck(exe, work, "%s_%s" % (k[0].replace("-", ""), k[1]), decks[k])
            t[k] = r["loop"] / (r["steps"] * r["atoms"]) * 1e6
        for p in pushes:
            prim = t[(p, "prim")] - t[(p, "none")]
            ours = t[(p, "ours")] - t[(p, "none")]
            cost[(p, "prim")].append(prim)
            cost[(p, "ours")].append(ours)
            ratios[p].append(ours / prim)
            print("  rep %2d  %-8s  none %.4f  prim %.4f  ours %.4f  ours/prim %.3f"
                  % (rep, p, t[(p, "none")], prim, ours, ours / prim), flush=True)
    for p in pushes:
        print("%-8s push: ours/prim median %.3f, mean %.3f, ratio of the mean costs %.3f "
              "(%d of %d repetitions at most 1.2)"
              % (p, statistics.median(ratios[p]), statistics.mean(ratios[p]),
                 statistics.mean(cost[(p, "ours")]) / statistics.mean(cost[(p, "prim")]),
                 sum(x <= 1.2 for x in ratios[p]), len(ratios[p])))


if __name__ == "__main__":
    main()
