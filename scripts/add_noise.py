#!/usr/bin/python3
"""Move every point of a generated scene by isotropic noise of a chosen shape (heavier-tailed than
the generator's Gaussian), keeping its truth: a probe of how the detector reads noise that is not
Gaussian.

    rspd_make_scene cube /tmp/c --noise 0
    /usr/bin/python3 scripts/add_noise.py /tmp/c /tmp/c_laplace laplace 0.01 [SEED]
    rspd_segment /tmp/c_laplace.pcd -o /tmp/out.pcd
    rspd_evaluate /tmp/c_laplace.pcd /tmp/c_laplace.gt /tmp/out.pcd

IN.pcd must be a binary PCD of x y z floats (as rspd_make_scene writes); IN.gt is copied to OUT.gt.
KIND is gauss, laplace or t3 (Student-t, 3 degrees of freedom), drawn per axis; SIGMA is the
noise's robust σ (1.4826 times the median absolute draw over all axes), so each kind has the spread
the detector measures.
Needs numpy (apt-get install python3-numpy).
"""
import shutil
import sys

import numpy as np

import xyz_pcd


def main():
    if len(sys.argv) not in (5, 6):
        sys.exit('usage: add_noise.py IN OUT gauss|laplace|t3 SIGMA [SEED]')
    src, dst, kind, sigma = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
    rng = np.random.default_rng(int(sys.argv[5]) if len(sys.argv) == 6 else 1)
    header, xyz = xyz_pcd.read(src + '.pcd', 'add_noise.py')
    n = len(xyz)
    draw = {'gauss': lambda: rng.standard_normal((n, 3)),
            'laplace': lambda: rng.laplace(size=(n, 3)),
            't3': lambda: rng.standard_t(3, size=(n, 3))}
    if kind not in draw:
        sys.exit('add_noise.py: KIND is gauss, laplace or t3')
    e = draw[kind]()
    e *= sigma / (1.4826 * np.median(np.abs(e)))
    xyz_pcd.write(dst + '.pcd', header, xyz.astype(np.float64) + e)
    shutil.copy(src + '.gt', dst + '.gt')


if __name__ == '__main__':
    main()
