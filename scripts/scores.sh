#!/usr/bin/env bash
# pcl_rspd's own scores with its defaults (its own normals, unlike rspd_compare, which gives every
# method the same PCL normals): rspd_segment + rspd_evaluate on every generated scene (and the
# 1M-point cube of issue 6), on the ../shared/data clouds with ground truth, and on each generated
# scene and SynPEB cloud scaled x1000, moved 1 km and turned by three random rotations, scored
# against the original's truth.
# Needs a build (scripts/build.sh; RSPD_BIN=DIR for another). Prints markdown tables on stdout. Arguments are passed to
# rspd_segment (e.g. `--frame axes` for the paper's axis-aligned frame).
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${RSPD_BIN:-./build} # RSPD_BIN: another build directory
data=../shared/data
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
seg_args=("$@")

# CLOUD TRUTH [DETECT_ON] -> "F1 precision recall found fragments false": detect on DETECT_ON (a
# moved copy of CLOUD, same point order; CLOUD itself if absent), score against CLOUD and TRUTH.
score () {
  "$bin/rspd_segment" "${3:-$1}" -o "$tmp/out.pcd" "${seg_args[@]}" > /dev/null
  "$bin/rspd_evaluate" "$1" "$2" "$tmp/out.pcd" --phases "${phases:-1}" --json | /usr/bin/python3 -c '
import json, sys
j = json.load(sys.stdin)
print("%.3f %.3f %.3f %d/%d %d %d %.3f %.3f" % (j["f1"], j["precision"], j["recall"], j["found"], j["planes"], j["fragments"], j["false_planes"], j["f1_phase_median"], j["f1_phase_min"]))'
}

# The first table also scores each labelling on 16 voxel grids (the paper's and 15 shifted by fixed
# fractions of a voxel, rspd_evaluate --phases): where a plane's noise band or rim lies near a voxel
# boundary, the paper's single grid moves F1 by itself.
phases=16
echo "| cloud | F1 | precision | recall | found | fragments | false planes | F1 median, 16 grids | F1 lowest |"
echo "|---|---|---|---|---|---|---|---|---|"
for s in cube:1000000 cube room staircase facade industrial boxes; do
  name=${s%%:*}; n=${s#*:}; [ "$n" = "$s" ] && n=""
  "$bin/rspd_make_scene" "$name" "$tmp/scene" ${n:+-n $n} > /dev/null
  read -r f p r found frag false fm fl < <(score "$tmp/scene.pcd" "$tmp/scene.gt")
  echo "| $name${n:+ ($n points)} | $f | $p | $r | $found | $frag | $false | $fm | $fl |"
done
for c in synpeb_pc01 synpeb_test100 cgal_building; do
  if [ -f "$data/$c.pcd" ] && [ -f "$data/$c.gt" ]; then
    read -r f p r found frag false fm fl < <(score "$data/$c.pcd" "$data/$c.gt")
    echo "| $c | $f | $p | $r | $found | $frag | $false | $fm | $fl |"
  fi
done

echo
# Each moved copy keeps the point order, so its labels are scored against the original cloud and
# truth (the voxel metric itself is not rotation-invariant: scoring a turned cloud on its own
# turned truth would mix the metric's change into the detector's).
phases=1
echo "| cloud | F1 as given | x1000 | 1 km away | rotation 1 | rotation 2 | rotation 3 | largest change |"
echo "|---|---|---|---|---|---|---|---|"
clouds=()
for s in cube room staircase facade industrial boxes; do
  "$bin/rspd_make_scene" "$s" "$tmp/$s" > /dev/null
  clouds+=("$tmp/$s")
done
for c in synpeb_pc01 synpeb_test100; do
  [ -f "$data/$c.pcd" ] && [ -f "$data/$c.gt" ] && clouds+=("$data/$c")
done
for c in "${clouds[@]}"; do
  row=()
  for v in "" "--scale 1000" "--offset 1000 0 0" "--rotate --seed 1" "--rotate --seed 2" "--rotate --seed 3"; do
    # shellcheck disable=SC2086
    "$bin/rspd_make_scene" "$c.pcd" "$tmp/moved" $v > /dev/null
    read -r f _ < <(score "$c.pcd" "$c.gt" "$tmp/moved.pcd")
    row+=("$f")
  done
  delta=$(/usr/bin/python3 -c "import sys; v=[float(x) for x in sys.argv[1:]]; print('%.3f' % max(abs(x - v[0]) for x in v))" "${row[@]}")
  echo "| $(basename "$c") | ${row[0]} | ${row[1]} | ${row[2]} | ${row[3]} | ${row[4]} | ${row[5]} | $delta |"
done
