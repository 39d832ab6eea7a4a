#!/usr/bin/python3
"""Thin a generated scene so that its density falls tenfold along its longest axis, keeping each
kept point's truth: a probe of a scanner's falling density on one cloud.

    rspd_make_scene room /tmp/r
    /usr/bin/python3 scripts/thin_density.py /tmp/r /tmp/r_thin [SEED]
    rspd_segment /tmp/r_thin.pcd -o /tmp/out.pcd
    rspd_evaluate /tmp/r_thin.pcd /tmp/r_thin.gt /tmp/out.pcd

A point at t along the longest axis (0 at its lowest coordinate, 1 at its highest) is kept with
probability 0.1 + 0.9 t. IN.pcd must be a binary PCD of x y z floats (as rspd_make_scene writes).
Needs numpy (apt-get install python3-numpy).
"""
import sys

import numpy as np

import xyz_pcd


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit('usage: thin_density.py IN OUT [SEED]')
    src, dst = sys.argv[1], sys.argv[2]
    rng = np.random.default_rng(int(sys.argv[3]) if len(sys.argv) == 4 else 1)
    header, xyz = xyz_pcd.read(src + '.pcd', 'thin_density.py')
    n = len(xyz)
    truth = np.fromfile(src + '.gt', dtype='<u4')
    axis = int(np.argmax(np.ptp(xyz, 0)))
    t = (xyz[:, axis] - xyz[:, axis].min()) / np.ptp(xyz[:, axis])
    keep = rng.random(n) < 0.1 + 0.9 * t
    xyz_pcd.write(dst + '.pcd', header, xyz[keep])
    truth[keep].astype('<u4').tofile(dst + '.gt')


if __name__ == '__main__':
    main()
