#!/usr/bin/python3
# The likeliest face of every sample of a generated cube with isotropic noise, from the true cube:
# the per-sample labelling no detector can beat on average, scored like a detection.
#
#   /usr/bin/python3 scripts/cube_bayes.py CLOUD.pcd SIGMA OUT.pcd [HALF_EDGE | HX,HY,HZ]
#   build/rspd_evaluate CLOUD.pcd CLOUD.gt OUT.pcd
#
# CLOUD is `rspd_make_scene cube P --isotropic [--noise SIGMA]` (the cube [-HALF_EDGE, HALF_EDGE]^3,
# 0.5 by default, at the origin, not moved; with `--layout L`, the box [-HX, HX] x [-HY, HY] x
# [-HZ, HZ], each half extent the median |coordinate| of its two faces' samples along their axis).
# A face's sample at p has density φ(d_n / σ) times, per in-face axis t, Φ((h - t) / σ) -
# Φ((-h - t) / σ) (the face's extent blurred by the noise); each sample goes to the face of the
# largest. Needs numpy (apt-get install python3-numpy).
import math
import sys

import numpy as np


def read_xyz(path):
    with open(path, 'rb') as f:
        head = {}
        while True:
            words = f.readline().decode().split()
            if words and not words[0].startswith('#'):
                head[words[0]] = words[1:]
                if words[0] == 'DATA':
                    break
        n = int(head['POINTS'][0])
        fields, sizes, types = head['FIELDS'], list(map(int, head['SIZE'])), head['TYPE']
        if head['DATA'][0] == 'ascii':
            table = np.loadtxt(f, ndmin=2)
            return np.stack([table[:, fields.index(a)] for a in 'xyz'], 1)
        if head['DATA'][0] != 'binary':
            sys.exit('cube_bayes.py: ascii or binary PCD only')
        dtype = np.dtype([(name, {'F': '<f', 'U': '<u', 'I': '<i'}[t] + str(s))
                          for name, s, t in zip(fields, sizes, types)])
        cloud = np.frombuffer(f.read(n * dtype.itemsize), dtype=dtype, count=n)
        return np.stack([cloud[a].astype(np.float64) for a in 'xyz'], 1)


def main():
    if len(sys.argv) not in (4, 5):
        sys.exit('usage: cube_bayes.py CLOUD.pcd SIGMA OUT.pcd [HALF_EDGE | HX,HY,HZ]')
    xyz = read_xyz(sys.argv[1])
    sigma = float(sys.argv[2])
    h = [float(v) for v in sys.argv[4].split(',')] if len(sys.argv) == 5 else [0.5]
    h = h * 3 if len(h) == 1 else h
    if len(h) != 3:
        sys.exit('cube_bayes.py: HALF_EDGE is one value or three (HX,HY,HZ)')
    cdf = np.frompyfunc(lambda z: 0.5 * math.erfc(-z / math.sqrt(2.0)), 1, 1)
    inside = np.empty_like(xyz)  # log of the blurred extent along each axis
    for a in range(3):
        mass = (cdf((h[a] - xyz[:, a]) / sigma) - cdf((-h[a] - xyz[:, a]) / sigma)).astype(np.float64)
        inside[:, a] = np.log(np.maximum(mass, 1e-300))
    score = []
    for a in range(3):
        others = inside.sum(1) - inside[:, a]
        for side in (1.0, -1.0):
            score.append(-0.5 * ((side * xyz[:, a] - h[a]) / sigma) ** 2 + others)
    labels = (np.argmax(np.array(score), 0) + 1).astype('<u4')
    n = len(labels)
    out = np.zeros(n, dtype=[('x', '<f4'), ('y', '<f4'), ('z', '<f4'), ('label', '<u4')])
    for a, name in enumerate('xyz'):
        out[name] = xyz[:, a]
    out['label'] = labels
    with open(sys.argv[3], 'wb') as f:
        f.write(('VERSION .7\nFIELDS x y z label\nSIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\n'
                 'WIDTH %d\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS %d\nDATA binary\n' % (n, n)).encode())
        f.write(out.tobytes())


if __name__ == '__main__':
    main()
