# Sourced by scripts/sweep.sh and scripts/peer_sweep.sh: the rows of a sweep list, one scene at a time.
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
