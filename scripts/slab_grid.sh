#!/usr/bin/env bash
# A unit plane at σ 1 cm inside a slab of uniform outliers (rspd_make_scene plane), the grid behind
# the volume-layer departures' figures: outlier shares 10-40 %, seeds 1-3, each cloud as given,
# scaled x1000, moved 1 km and turned by three random rotations, every copy scored against the
# original's truth (same point order). One line a cell, then the false planes summed.
#
#   bash scripts/slab_grid.sh [-- rspd_segment options]
#
# Needs a build (scripts/build.sh; RSPD_BIN=DIR for another). SHARES and SEEDS (space-separated
# lists in the environment) narrow the grid.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${RSPD_BIN:-./build}
[ $# -gt 0 ] && [ "$1" = "--" ] && shift
seg_args=("$@")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

echo "| outliers | seed | as given | x1000 | 1 km | rotation 1 | rotation 2 | rotation 3 | false planes |"
echo "|---|---|---|---|---|---|---|---|---|"
total_false=0
for share in ${SHARES:-0.1 0.2 0.3 0.4}; do
  for seed in ${SEEDS:-1 2 3}; do
    "$bin/rspd_make_scene" plane "$tmp/p" -n 100000 --noise 0.01 --outliers "$share" --seed "$seed" > /dev/null
    cells="" false=0
    for t in given scale offset rot1 rot2 rot3; do
      case $t in
        given) cp "$tmp/p.pcd" "$tmp/m.pcd" ;;
        scale) "$bin/rspd_make_scene" "$tmp/p.pcd" "$tmp/m" --scale 1000 > /dev/null ;;
        offset) "$bin/rspd_make_scene" "$tmp/p.pcd" "$tmp/m" --offset 1000 0 0 > /dev/null ;;
        rot*) "$bin/rspd_make_scene" "$tmp/p.pcd" "$tmp/m" --rotate --seed "${t#rot}" > /dev/null ;;
      esac
      "$bin/rspd_segment" "$tmp/m.pcd" -o "$tmp/out.pcd" "${seg_args[@]}" > /dev/null
      read -r f fp < <("$bin/rspd_evaluate" "$tmp/p.pcd" "$tmp/p.gt" "$tmp/out.pcd" --json | /usr/bin/python3 -c '
import json, sys
j = json.load(sys.stdin)
print("%.4f %d" % (j["f1"], j["false_planes"]))')
      cells="$cells | $f"
      false=$((false + fp))
    done
    total_false=$((total_false + false))
    echo "| $share | $seed$cells | $false |"
  done
done
echo
echo "false planes in all: $total_false"
