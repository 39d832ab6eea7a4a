#!/usr/bin/env bash
# A digest of rspd_segment's labels per row of a sweep list: for checking that a change meant to
# be faster (or a refactoring) leaves every label where it was. Run it before and after, and diff.
#
#   bash scripts/label_digests.sh [ROWS] [-- rspd_segment options]
#
# ROWS as for scripts/sweep.sh (default scripts/sweep_rows.txt). Prints "TAG  SHA1" a row; the
# digest is of the label column alone (the binary PCD's header and coordinates never change).
# RSPD_BIN picks another build directory, e.g. a copy of the build before the change.
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=scripts/scene_rows.sh
source scripts/scene_rows.sh
row_script_args "$@"

row ()
{
  "$bin/rspd_segment" "$2.pcd" -o "$tmp/out.pcd" "${seg_args[@]}" > /dev/null
  /usr/bin/python3 - "$tmp/out.pcd" "$1" << 'EOF'
import hashlib, sys
data = open(sys.argv[1], "rb").read()
head, _, body = data.partition(b"DATA binary\n")
fields, sizes, counts = [], [], []
for line in head.decode().splitlines():
    key, _, rest = line.partition(" ")
    if key == "FIELDS": fields = rest.split()
    if key == "SIZE": sizes = [int(s) for s in rest.split()]
    if key == "COUNT": counts = [int(c) for c in rest.split()]
    if key == "POINTS": n = int(rest)
if not counts: counts = [1] * len(fields)
width = [s * c for s, c in zip(sizes, counts)]
stride, at = sum(width), sum(width[:fields.index("label")])
w = width[fields.index("label")]
labels = b"".join(body[i * stride + at:i * stride + at + w] for i in range(n))
print("%-40s %s" % (sys.argv[2], hashlib.sha1(labels).hexdigest()))
EOF
}
each_row "$rows" "$tmp" row
