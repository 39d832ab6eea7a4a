#!/usr/bin/python3
"""A plant unlike rspd_make_scene's industrial yard, with its truth: a probe of planes that end at
curved surfaces (a flat-topped tank's top at its wall) and of thin pipes.

    /usr/bin/python3 scripts/make_plant.py OUT POINTS SIGMA SEED [OUTLIERS] [--isotropic]
    rspd_segment OUT.pcd -o /tmp/out.pcd
    rspd_evaluate OUT.pcd OUT.gt /tmp/out.pcd
    rspd_compare OUT.pcd OUT.gt            # the PCL peers on the same cloud

A 16-24 m yard (SEED draws every size): the ground, two walls 4-7 m high meeting in a corner, a
platform in the far corner (top and two sides), a pump box on the ground (top and four sides): 12
planes, truth 1..12. Curved surfaces, truth 0: a vertical tank with a flat round top (the top is
plane 7), a tank lying on its side with round ends, a spherical tank, a horizontal pipe with a
quarter elbow, and a vertical pipe 0.1-0.6 m across. Samples uniform by area, none inside a solid;
Gaussian noise SIGMA along each surface's normal (--isotropic: per axis); OUTLIERS (a share, default
0) uniform in the yard's box, truth 0. Writes OUT.pcd (binary x y z) and OUT.gt (uint32 per point).
Needs numpy (apt-get install python3-numpy).
"""
import argparse

import numpy as np


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("points", type=int)
    parser.add_argument("sigma", type=float)
    parser.add_argument("seed", type=int)
    parser.add_argument("outliers", type=float, nargs="?", default=0.0)
    parser.add_argument("--isotropic", action="store_true")
    args = parser.parse_args()
    rng = np.random.RandomState(args.seed)

    surfaces = []  # (area, sampler: count -> (points, normals), truth label)

    def rect(origin, u, v, label):
        origin, u, v = (np.asarray(a, float) for a in (origin, u, v))
        n = np.cross(u, v)
        area = np.linalg.norm(n)

        def draw(k):
            a, b = rng.rand(k, 1), rng.rand(k, 1)
            return origin + a * u + b * v, np.repeat((n / area)[None], k, 0)
        surfaces.append((area, draw, label))

    def disc(centre, r, label):
        centre = np.asarray(centre, float)

        def draw(k):
            rr, t = r * np.sqrt(rng.rand(k)), 2 * np.pi * rng.rand(k)
            return centre + np.stack([rr * np.cos(t), rr * np.sin(t), 0 * rr], 1), np.repeat([[0, 0, 1.0]], k, 0)
        surfaces.append((np.pi * r * r, draw, label))

    def cylinder(base, axis, length, r):
        base, a = np.asarray(base, float), np.asarray(axis, float) / np.linalg.norm(axis)
        e1 = np.cross(a, [1.0, 0, 0] if abs(a[0]) < 0.9 else [0, 1.0, 0])
        e1 /= np.linalg.norm(e1)
        e2 = np.cross(a, e1)

        def draw(k):
            h, t = length * rng.rand(k, 1), 2 * np.pi * rng.rand(k, 1)
            n = np.cos(t) * e1 + np.sin(t) * e2
            return base + h * a + r * n, n
        surfaces.append((2 * np.pi * r * length, draw, 0))

    def sphere(centre, r):
        centre = np.asarray(centre, float)

        def draw(k):
            n = rng.randn(k, 3)
            n /= np.linalg.norm(n, axis=1)[:, None]
            return centre + r * n, n
        surfaces.append((4 * np.pi * r * r, draw, 0))

    def elbow(centre, bend, r):  # a quarter torus in the x-z plane
        centre = np.asarray(centre, float)

        def draw(k):
            s, t = 0.5 * np.pi * rng.rand(k), 2 * np.pi * rng.rand(k)
            line = np.stack([bend * np.cos(s), 0 * s, bend * np.sin(s)], 1)
            out = np.stack([np.cos(s), 0 * s, np.sin(s)], 1)
            n = np.cos(t)[:, None] * out + np.sin(t)[:, None] * np.array([0, 1.0, 0])
            return centre + line + r * n, n
        surfaces.append((2 * np.pi * r * bend * 0.5 * np.pi, draw, 0))

    side = rng.uniform(16, 24)
    wall = rng.uniform(4, 7)
    rect([0, 0, 0], [side, 0, 0], [0, side, 0], 1)             # ground
    rect([0, 0, 0], [side, 0, 0], [0, 0, wall], 2)             # back wall
    rect([0, 0, 0], [0, side, 0], [0, 0, wall], 3)             # side wall
    plat, plat_h = rng.uniform(0.2, 0.3) * side, rng.uniform(1, 3)
    rect([0, side - plat, plat_h], [plat, 0, 0], [0, plat, 0], 4)
    rect([plat, side - plat, 0], [0, plat, 0], [0, 0, plat_h], 5)
    rect([0, side - plat, 0], [plat, 0, 0], [0, 0, plat_h], 6)
    tank_r, tank_h, tank = rng.uniform(0.8, 1.5), rng.uniform(4, 8), (0.6 * side, 0.7 * side)
    cylinder([tank[0], tank[1], 0], [0, 0, 1], tank_h, tank_r)
    disc([tank[0], tank[1], tank_h], tank_r, 7)
    lying_r, lying_l = rng.uniform(0.8, 1.5), rng.uniform(5, 9)
    lying = np.array([0.3 * side, 0.35 * side, lying_r + 0.4])
    cylinder(lying, [1, 0, 0], lying_l, lying_r)
    sphere(lying, lying_r)
    sphere(lying + [lying_l, 0, 0], lying_r)
    ball_r = rng.uniform(1.0, 1.5)
    sphere([0.8 * side, 0.3 * side, ball_r + 1.0], ball_r)
    pipe_r = rng.uniform(0.08, 0.25)
    cylinder([0, 0.55 * side, 2.5], [1, 0, 0], 0.5 * side, pipe_r)
    elbow([0.5 * side, 0.55 * side, 2.5], 0.6, pipe_r)
    cylinder([0.15 * side, 0.15 * side, 0], [0, 0, 1], wall, rng.uniform(0.05, 0.3))
    box = (0.45 * side, 0.8 * side)
    bw, bd, bh = rng.uniform(0.6, 1.2), rng.uniform(0.6, 1.2), rng.uniform(0.5, 1.0)
    rect([box[0], box[1], bh], [bw, 0, 0], [0, bd, 0], 8)
    rect([box[0], box[1], 0], [bw, 0, 0], [0, 0, bh], 9)
    rect([box[0], box[1] + bd, 0], [bw, 0, 0], [0, 0, bh], 10)
    rect([box[0], box[1], 0], [0, bd, 0], [0, 0, bh], 11)
    rect([box[0] + bw, box[1], 0], [0, bd, 0], [0, 0, bh], 12)

    def inside(p):  # inside a solid standing on the ground: hidden
        x, y, z = p[:, 0], p[:, 1], p[:, 2]
        hidden = (x < plat) & (y > side - plat) & (z < plat_h)
        hidden |= ((x - tank[0]) ** 2 + (y - tank[1]) ** 2 < tank_r ** 2) & (z < tank_h)
        hidden |= (x > box[0]) & (x < box[0] + bw) & (y > box[1]) & (y < box[1] + bd) & (z < bh)
        return hidden

    areas = np.array([s[0] for s in surfaces])
    on_surfaces = int(round(args.points * (1.0 - args.outliers)))
    counts = rng.multinomial(on_surfaces, areas / areas.sum())
    points, labels = [], []
    for (_, draw, label), k in zip(surfaces, counts):
        p, n = draw(2 * k + 10)
        keep = ~inside(p + 1e-6 * n)  # a sample on a solid's face is outside it
        p, n = p[keep][:k], n[keep][:k]
        noise = rng.randn(len(p), 3) * args.sigma if args.isotropic else n * rng.randn(len(p), 1) * args.sigma
        points.append(p + noise)
        labels.append(np.full(len(p), label, np.uint32))
    p, labels = np.concatenate(points), np.concatenate(labels)
    clutter = args.points - len(p)  # the outliers, and any sample a solid hid twice over
    if clutter > 0:
        p = np.concatenate([p, rng.uniform([0, 0, 0], [side, side, wall], (clutter, 3))])
        labels = np.concatenate([labels, np.zeros(clutter, np.uint32)])
    order = rng.permutation(len(p))
    p, labels = p[order].astype(np.float32), labels[order]
    with open(args.out + ".pcd", "wb") as f:
        f.write(("VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH %d\nHEIGHT 1\n"
                 "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS %d\nDATA binary\n" % (len(p), len(p))).encode())
        f.write(p.tobytes())
    labels.astype("<u4").tofile(args.out + ".gt")
    print("%s: %d points, 12 planes, %d on curved surfaces, %d outliers" %
          (args.out, len(p), int(np.sum(labels == 0)) - max(clutter, 0), max(clutter, 0)))


if __name__ == "__main__":
    main()
