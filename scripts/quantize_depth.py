#!/usr/bin/python3
"""Quantize a cloud's depth as a structured-light camera does, for measuring pcl_rspd on such scans.

    /usr/bin/python3 scripts/quantize_depth.py IN.pcd OUT.pcd --axis X,Y,Z [--k 357] [--dither]
                                               [--fov DEG --gt IN.gt OUT.gt]

IN.pcd: binary PCD with fields x y z (float32), as rspd_make_scene writes; its VIEWPOINT origin is
the camera. Each sample's depth z along the axis (its sign kept, |z| below 0.3 left as it is) is set
to the nearest level K/m for whole m (disparity steps: levels K/m apart by about z^2/K, 7 cm at 5 m
for K = 357 m), the sample moved along its ray from the camera. --dither instead draws its depth
within its level's bin (half the gaps to the neighbouring levels), from a hash of its index: the
quantization error made noise. Same point order, so the scene's .gt still applies; with --fov only
the samples within DEG degrees of the axis (in front of the camera) are kept, as a camera's frame,
and --gt writes their truth. The VIEWPOINT written turns the camera's +z onto the axis (PCL's
sensor_orientation_), so rspd_segment --depth-levels dither finds the levels.
"""
import argparse
import math
import struct


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("src")
    ap.add_argument("dst")
    ap.add_argument("--axis", required=True, help="camera axis X,Y,Z (normalized here)")
    ap.add_argument("--k", type=float, default=357.0, help="disparity constant K, scene units")
    ap.add_argument("--dither", action="store_true")
    ap.add_argument("--fov", type=float, default=0.0, help="keep samples within DEG of the axis")
    ap.add_argument("--gt", nargs=2, metavar=("IN_GT", "OUT_GT"), help="truth to crop with --fov")
    a = ap.parse_args()
    data = open(a.src, "rb").read()
    pos, header = 0, []
    while True:
        end = data.index(b"\n", pos)
        line = data[pos:end].decode()
        header.append(line)
        pos = end + 1
        if line.startswith("DATA"):
            break
    fields = dict((l.split()[0], l.split()[1:]) for l in header if not l.startswith("#"))
    if fields["FIELDS"] != ["x", "y", "z"] or fields["DATA"] != ["binary"] or fields["TYPE"] != ["F", "F", "F"]:
        raise SystemExit("quantize_depth: needs a binary PCD with float fields x y z only")
    origin = [float(v) for v in fields.get("VIEWPOINT", ["0"] * 7)[:3]]
    axis = [float(v) for v in a.axis.split(",")]
    norm = math.sqrt(sum(v * v for v in axis))
    axis = [v / norm for v in axis]
    n = int(fields["POINTS"][0])
    xyz = list(struct.unpack_from("<%df" % (3 * n), data, pos))
    k = a.k
    for i in range(n):
        d = [xyz[3 * i + j] - origin[j] for j in range(3)]
        z = abs(sum(d[j] * axis[j] for j in range(3)))
        if not math.isfinite(z) or z < 0.3:
            continue
        m = round(k / z)
        level = k / m
        if a.dither:
            below = k / m - k / (m + 1)
            above = k / (m - 1) - k / m if m > 1 else below
            u = ((i * 2654435761) & 0xFFFFFFFF) / 2.0 ** 32
            level = level - below * (0.5 - u) if u < 0.5 else level + above * (u - 0.5)
        for j in range(3):
            xyz[3 * i + j] = origin[j] + d[j] * level / z
    keep = list(range(n))
    if a.fov > 0.0:
        cos_fov = math.cos(math.radians(a.fov))
        keep = []
        for i in range(n):
            d = [xyz[3 * i + j] - origin[j] for j in range(3)]
            r = math.sqrt(sum(v * v for v in d))
            if r > 0.0 and sum(d[j] * axis[j] for j in range(3)) >= cos_fov * r:
                keep.append(i)
    # VIEWPOINT: the quaternion that turns +z onto the axis.
    w, qx, qy, qz = 1.0 + axis[2], -axis[1], axis[0], 0.0
    qn = math.sqrt(w * w + qx * qx + qy * qy + qz * qz)
    if qn < 1e-9:
        w, qx, qy, qz, qn = 0.0, 1.0, 0.0, 0.0, 1.0  # axis -z: half a turn about x
    viewpoint = "VIEWPOINT %r %r %r %r %r %r %r" % (origin[0], origin[1], origin[2], w / qn, qx / qn, qy / qn, qz / qn)
    lines = []
    for line in header:
        key = line.split()[0] if line.split() else ""
        if key in ("WIDTH", "POINTS"):
            line = "%s %d" % (key, len(keep))
        elif key == "HEIGHT":
            line = "HEIGHT 1"
        elif key == "VIEWPOINT":
            line = viewpoint
        lines.append(line)
    with open(a.dst, "wb") as out:
        out.write(("\n".join(lines) + "\n").encode())
        out.write(b"".join(struct.pack("<3f", *xyz[3 * i:3 * i + 3]) for i in keep))
    if a.gt:
        truth = open(a.gt[0], "rb").read()
        with open(a.gt[1], "wb") as out:
            out.write(b"".join(truth[4 * i:4 * i + 4] for i in keep))


if __name__ == "__main__":
    main()
