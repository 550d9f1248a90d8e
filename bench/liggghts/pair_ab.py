#!/usr/bin/python3
"""Paired A/B of two liggghts-rigidsurf builds on the wall-cost deck of bench_walls.py.

    pair_ab.py --old EXE_A --new EXE_B [--n N] [--reps R] [--flow | --bounce] [--seed S]

Both builds run the 'ours' deck of section 1 (or 1b with --flow, 1e with --bounce) of
bench_walls.py: N spheres held on the inside of a REVOLUTION cylinder by fix wall/rigid
(--bounce: N defaults to that section's 20000, kicked inward, 1000 steps). Each repetition
runs the two builds back to back, in an order drawn at random, so that a slow period of
the shared host tends to hit both runs of a pair. Reported: the loop time per
particle-step of each build (fastest and median) and the median and mean of the paired
differences new - old, with the number of pairs the new build won. The difference of
loop times is the difference of wall costs: the rest of the deck is the same.
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
    ap.add_argument("--old", required=True)
    ap.add_argument("--new", required=True)
    ap.add_argument("--n", type=int, default=None)
    ap.add_argument("--reps", type=int, default=15)
    ap.add_argument("--flow", action="store_true", help="the flowing deck (section 1b)")
    ap.add_argument("--bounce", action="store_true", help="the bouncing bed (section 1e)")
    ap.add_argument("--seed", type=int, default=1, help="seed of the run order")
    args = ap.parse_args()
    if args.flow and args.bounce:
        ap.error("--flow and --bounce are two decks: give one")
    if args.n is None:
        args.n = bw.N_BOUNCE if args.bounce else 10000
    exes = {"old": os.path.abspath(args.old), "new": os.path.abspath(args.new)}
    n = args.n
    work = tempfile.mkdtemp(prefix="rs_pair_ab_")
    data, height = bw.write_bed(work, n)
    steps = bw.STEPS_BOUNCE if args.bounce else int(min(10000, max(100, 1.0e7 / n)))
    deck = bw.wall_deck("ours", data, steps, height, args.flow,
                        kick=bw.VKICK if args.bounce else 0.0)
    rng = random.Random(args.seed)
    t = {"old": [], "new": []}
    for _ in range(args.reps):
        order = ["old", "new"]
        rng.shuffle(order)
        for k in order:
            r = bw.run_deck(exes[k], work, "ours_" + k, deck)
            if r["atoms"] != n:
                sys.exit("pair_ab: %s lost atoms (%d of %d)" % (k, r["atoms"], n))
            t[k].append(1e6 * r["loop"] / (n * steps))
    d = [b - a for a, b in zip(t["old"], t["new"])]
    print("%s deck, N = %d, %d steps, %d pairs; loop time in us per particle-step"
          % ("flowing" if args.flow else "bouncing" if args.bounce else "static", n, steps,
             args.reps))
    for k in ("old", "new"):
        print("  %s: fastest %.4f, median %.4f  (%s)"
              % (k, min(t[k]), statistics.median(t[k]), exes[k]))
    print("  new - old: median %+.4f, mean %+.4f; new faster in %d of %d pairs"
          % (statistics.median(d), statistics.mean(d), sum(x < 0 for x in d), len(d)))


if __name__ == "__main__":
    main()
