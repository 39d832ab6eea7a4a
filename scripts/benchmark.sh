#!/usr/bin/env bash
# The README's speed table (issue #5): builds Release in ./build (scripts/build.sh), then runs the
# end-to-end benchmark - RSPD vs pcl::RegionGrowing, read -> detect -> write, each run in a process
# of its own, medians of 3 - on the cube at 100k, 1M and 4M points and the room at 300k, and the
# 1 vs 2 thread comparison on the 1M cube. Prints markdown tables on stdout, progress on stderr.
# Takes about ten minutes on 2 cores. Run it on an otherwise idle machine: times are wall clock.
#
#   bash scripts/benchmark.sh                   # the README's tables
#   bash scripts/benchmark.sh --kernels         # ... and the Google Benchmark kernels at 100k and 1M
#   bash scripts/benchmark.sh -- ARGS...        # only rspd_benchmark ARGS (see rspd_benchmark --help)
set -euo pipefail
cd "$(dirname "$0")/.."
kernels=0
if [ "${1:-}" = "--kernels" ]; then kernels=1; shift; fi
bash scripts/build.sh >&2
bench=./build/bench
if [ ! -x "$bench/rspd_benchmark" ]; then
  echo "benchmark: build/bench/rspd_benchmark was not built (Google Benchmark missing? run scripts/install_deps.sh)" >&2
  exit 1
fi
if [ "${1:-}" = "--" ]; then
  shift
  exec "$bench/rspd_benchmark" "$@"
fi
"$bench/rspd_benchmark" --repeats 3 --markdown
echo
"$bench/rspd_benchmark" --threads-compare --repeats 3 --markdown
if [ "$kernels" = 1 ]; then
  echo
  "$bench/bench_kernels" --large
fi
