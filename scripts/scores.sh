#!/usr/bin/env bash
# pcl_rspd's own scores with its defaults (its own normals, unlike rspd_compare, which gives every
# method the same PCL normals): rspd_segment + rspd_evaluate on every generated scene (and the
# 1M-point cube of issue 6), on the ../shared/data clouds with ground truth, and on each generated
# scene scaled x1000, randomly rotated and moved 1 km, scored against its own truth.
# Needs a build (scripts/build.sh). Prints markdown tables on stdout.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=./build
data=../shared/data
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

score () { # CLOUD TRUTH -> "F1 precision recall found false"
  "$bin/rspd_segment" "$1" -o "$tmp/out.pcd" > /dev/null
  "$bin/rspd_evaluate" "$1" "$2" "$tmp/out.pcd" --json | /usr/bin/python3 -c '
import json, sys
j = json.load(sys.stdin)
print("%.3f %.3f %.3f %d/%d %d %d" % (j["f1"], j["precision"], j["recall"], j["found"], j["planes"], j["fragments"], j["false_planes"]))'
}

echo "| cloud | F1 | precision | recall | found | fragments | false planes |"
echo "|---|---|---|---|---|---|---|"
for s in cube:1000000 cube room staircase facade industrial; do
  name=${s%%:*}; n=${s#*:}; [ "$n" = "$s" ] && n=""
  "$bin/rspd_make_scene" "$name" "$tmp/scene" ${n:+-n $n} > /dev/null
  read -r f p r found frag false < <(score "$tmp/scene.pcd" "$tmp/scene.gt")
  echo "| $name${n:+ ($n points)} | $f | $p | $r | $found | $frag | $false |"
done
for c in synpeb_pc01 synpeb_test100 cgal_building; do
  if [ -f "$data/$c.pcd" ] && [ -f "$data/$c.gt" ]; then
    read -r f p r found frag false < <(score "$data/$c.pcd" "$data/$c.gt")
    echo "| $c | $f | $p | $r | $found | $frag | $false |"
  fi
done

echo
echo "| scene | F1 as generated | x1000 | rotated | 1 km away | largest change |"
echo "|---|---|---|---|---|---|"
for s in cube room staircase facade industrial; do
  row=()
  for v in "" "--scale 1000" "--rotate" "--offset 1000 0 0"; do
    # shellcheck disable=SC2086
    "$bin/rspd_make_scene" "$s" "$tmp/scene" $v > /dev/null
    read -r f _ < <(score "$tmp/scene.pcd" "$tmp/scene.gt")
    row+=("$f")
  done
  delta=$(/usr/bin/python3 -c "import sys; v=[float(x) for x in sys.argv[1:]]; print('%.3f' % max(abs(x - v[0]) for x in v))" "${row[@]}")
  echo "| $s | ${row[0]} | ${row[1]} | ${row[2]} | ${row[3]} | $delta |"
done
