#!/usr/bin/env bash
# The issue's invariance bar on any list of scenes: each row as given, scaled x1000, moved 1 km and
# turned by three random rotations (rspd_make_scene CLOUD.pcd OUT --scale / --offset / --rotate),
# every copy's labels scored against the original's cloud and truth (same point order), and the
# largest change from the F1 as given; rows whose change exceeds 0.01 are marked.
#
#   bash scripts/invariance.sh [ROWS] [-- rspd_segment options]
#
# ROWS as for scripts/sweep.sh (default scripts/sweep_rows.txt). Needs a build (scripts/build.sh;
# RSPD_BIN=DIR for another).
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=scripts/scene_rows.sh
source scripts/scene_rows.sh
row_script_args "$@"

echo "| row | as given | x1000 | 1 km away | rotation 1 | rotation 2 | rotation 3 | largest change |"
echo "|---|---|---|---|---|---|---|---|"
row ()
{
  local tag=$1 base=$2 v f cells=()
  for v in "" "--scale 1000" "--offset 1000 0 0" "--rotate --seed 1" "--rotate --seed 2" "--rotate --seed 3"; do
    # shellcheck disable=SC2086
    "$bin/rspd_make_scene" "$base.pcd" "$tmp/moved" $v > /dev/null
    "$bin/rspd_segment" "$tmp/moved.pcd" -o "$tmp/out.pcd" "${seg_args[@]}" > /dev/null
    f=$("$bin/rspd_evaluate" "$base.pcd" "$base.gt" "$tmp/out.pcd" --json |
      /usr/bin/python3 -c 'import json, sys; print("%.4f" % json.load(sys.stdin)["f1"])')
    cells+=("$f")
  done
  /usr/bin/python3 -c '
import sys
tag, v = sys.argv[1], [float(x) for x in sys.argv[2:]]
d = max(abs(x - v[0]) for x in v)
print("| %s | %s | %.4f%s |" % (tag, " | ".join("%.4f" % x for x in v), d, " **over 0.01**" if d > 0.01 else ""))' "$tag" "${cells[@]}"
}
each_row "$rows" "$tmp" row
