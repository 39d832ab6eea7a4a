"""Read and write the binary x y z PCD files rspd_make_scene writes, for the analysis scripts
(scripts/add_noise.py, scripts/thin_density.py). Needs numpy (apt-get install python3-numpy)."""
import sys

import numpy as np


def read(path, tool):
    """The header's lines (text, up to DATA) and the points as an n x 3 float32 array; exits with a
    message naming \a tool when the file is no binary x y z PCD."""
    with open(path, 'rb') as f:
        header = []
        while True:
            line = f.readline()
            if not line:
                sys.exit('%s: %s has no DATA line' % (tool, path))
            header.append(line.decode())
            if line.startswith(b'DATA'):
                break
        words = dict((l.split()[0], l.split()[1:]) for l in header if l.strip() and not l.startswith('#'))
        if words.get('FIELDS') != ['x', 'y', 'z'] or words.get('DATA') != ['binary']:
            sys.exit('%s: %s is no binary PCD of x y z (rspd_make_scene writes those)' % (tool, path))
        n = int(words['POINTS'][0])
        xyz = np.frombuffer(f.read(n * 12), dtype='<f4').reshape(n, 3)
    return header, xyz


def write(path, header, xyz):
    """\a xyz under \a header (from read), its WIDTH and POINTS set to the points written."""
    lines = []
    for line in header:
        key = line.split()[0] if line.strip() else ''
        lines.append('%s %d\n' % (key, len(xyz)) if key in ('WIDTH', 'POINTS') else line)
    with open(path, 'wb') as f:
        f.write(''.join(lines).encode())
        f.write(np.ascontiguousarray(xyz, dtype='<f4').tobytes())
