# Sourced by scripts/sweep.sh, peer_sweep.sh, label_digests.sh and invariance.sh: the rows of a sweep
# list, one scene at a time, and the command line the row scripts share.
#
#   row_script_args "$@"
#
# Parses "[ROWS] [-- rspd_segment options]": sets rows (default scripts/sweep_rows.txt) and
# seg_args, bin (RSPD_BIN, default ./build) and data, and tmp, a directory removed on exit.
row_script_args ()
{
  bin=${RSPD_BIN:-./build}
  data=../shared/data
  rows=scripts/sweep_rows.txt
  if [ $# -gt 0 ] && [ "$1" != "--" ]; then rows=$1; shift; fi
  [ $# -gt 0 ] && [ "$1" = "--" ] && shift
  seg_args=("$@")
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
}

# The rows, one scene at a time:
#
#   each_row ROWS TMPDIR HANDLER
#
# ROWS holds one row a line: "TAG | SCENE OPTIONS" runs "$bin/rspd_make_scene SCENE OPTIONS" into
# TMPDIR/scene; "TAG | @NAME" takes $data/NAME.pcd and NAME.gt (skipped when absent); '#' starts a
# comment. For each row, HANDLER is called with TAG and the scene's path without extension. Needs
# $bin and $data.
each_row ()
{
  local rows=$1 tmp=$2 handler=$3 line tag spec base
  while IFS= read -r line || [ -n "$line" ]; do
    line=${line%%#*}
    [[ "$line" == *"|"* ]] || continue
    tag=$(echo "${line%%|*}" | xargs)
    spec=$(echo "${line#*|}" | xargs)
    if [[ "$spec" == @* ]]; then
      base=$data/${spec#@}
      [ -f "$base.pcd" ] && [ -f "$base.gt" ] || continue
    else
      base=$tmp/scene
      # shellcheck disable=SC2086
      "$bin/rspd_make_scene" $spec "$base" > /dev/null
    fi
    "$handler" "$tag" "$base"
  done < "$rows"
}
