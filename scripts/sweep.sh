#!/usr/bin/env bash
# pcl_rspd on a list of scenes with given rspd_segment options: the sweeps behind the README's
# "every other row identical" statements, for comparing a setting off and on.
#
#   bash scripts/sweep.sh [ROWS] [-- rspd_segment options]
#
# ROWS (default scripts/sweep_rows.txt) holds one row a line: "TAG | SCENE OPTIONS" runs
# rspd_make_scene SCENE with OPTIONS; "TAG | @NAME" takes ../shared/data/NAME.pcd and NAME.gt
# (skipped when absent); '#' starts a comment. Each row: rspd_segment (its own normals) and
# rspd_evaluate against the truth. Prints a markdown table on stdout; "claimed" is the share of the
# truth's no-plane samples that planes hold: in a scene without outliers, its curved surfaces'.
# Needs a build (scripts/build.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=scripts/scene_rows.sh
source scripts/scene_rows.sh
row_script_args "$@"

echo "| row | F1 | precision | recall | found | fragments | false planes | claimed |"
echo "|---|---|---|---|---|---|---|---|"
row ()
{
  "$bin/rspd_segment" "$2.pcd" -o "$tmp/out.pcd" "${seg_args[@]}" > /dev/null
  "$bin/rspd_evaluate" "$2.pcd" "$2.gt" "$tmp/out.pcd" --json | /usr/bin/python3 -c '
import json, sys
j = json.load(sys.stdin)
claimed = 100.0 * j["unlabelled_claimed"] / j["unlabelled"] if j["unlabelled"] else 0.0
print("| %s | %.4f | %.4f | %.4f | %d/%d | %d | %d | %.2f %% |" % (sys.argv[1], j["f1"], j["precision"], j["recall"],
      j["found"], j["planes"], j["fragments"], j["false_planes"], claimed))' "$1"
}
each_row "$rows" "$tmp" row
