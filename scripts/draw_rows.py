#!/usr/bin/python3
"""Draw random hold-out rows for scripts/sweep.sh and scripts/peer_sweep.sh.

    /usr/bin/python3 scripts/draw_rows.py SEED COUNT [--outliers] > ROWS.txt

Each row is one of the six generated scenes in turn (cube, room, staircase, facade, industrial,
boxes), in a random layout (31-999), at 0.3-2 times the scene's default size and 0.5-1.5 times its
default noise, isotropic or not, turned or not, and with --outliers none / 5 / 10 / 20 % uniform
outliers (the facade keeps its own 15 % when none is drawn). The same SEED gives the same rows, so a
list drawn once can be drawn again; choose a new SEED for a set that no default was chosen on.
"""
import argparse
import random

# The scenes' default sizes and noise (include/pcl_rspd/synthetic_scenes.h, sceneNames' brief).
SCENES = [("cube", 100000, 0.01), ("room", 200000, 0.005), ("staircase", 100000, 0.002),
          ("facade", 200000, 0.03), ("industrial", 300000, 0.005), ("boxes", 300000, 0.002)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("seed", type=int)
    parser.add_argument("count", type=int)
    parser.add_argument("--outliers", action="store_true", help="draw outlier shares too")
    args = parser.parse_args()
    rng = random.Random(args.seed)
    print("# Drawn by: /usr/bin/python3 scripts/draw_rows.py %d %d%s" %
          (args.seed, args.count, " --outliers" if args.outliers else ""))
    for i in range(args.count):
        name, points, sigma = SCENES[i % len(SCENES)]
        layout = rng.randint(31, 999)
        n = int(round(points * rng.uniform(0.3, 2.0), -3))
        noise = float("%.2g" % (sigma * rng.uniform(0.5, 1.5)))
        iso = rng.random() < 0.5
        rot = rng.random() < 0.5
        out = rng.choice([0.0, 0.05, 0.1, 0.2]) if args.outliers else 0.0
        seed = rng.randint(1, 999)
        tag = "%s L%d %dk s%g%s%s%s" % (name, layout, n // 1000, noise, " iso" if iso else "",
                                        " rot" if rot else "", " o%g" % out if out else "")
        spec = "%s --layout %d -n %d --noise %g --seed %d%s%s%s" % (
            name, layout, n, noise, seed, " --isotropic" if iso else "", " --rotate" if rot else "",
            " --outliers %g" % out if out else "")
        print("%s | %s" % (tag, spec))


if __name__ == "__main__":
    main()
