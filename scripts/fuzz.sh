#!/usr/bin/env bash
# Builds the libFuzzer targets with clang-14 (ASan + UBSan) in ./build-fuzz and runs each of them for
# a number of executions (default 1000000), one after the other, on two cores at most.
#
#   bash scripts/fuzz.sh [runs] [target...]     # targets: segmentation cloud_reader (default both)
#
# Each run starts from fuzz/corpus/<target> and fuzz/regressions/<target> and grows a working corpus
# in build-fuzz/corpus/<target> (not part of the repository). A crash, leak, timeout or broken
# invariant stops the run and leaves the input in build-fuzz/artifacts/<target>/; minimize it with
#   build-fuzz/fuzz/fuzz_<target> -minimize_crash=1 -runs=100000 -exact_artifact_path=OUT INPUT
# and add it to fuzz/regressions/<target>/ (with a line in fuzz/regressions/README.md): ctest
# replays both directories with the normal compiler (fuzz_replay_<target>).
set -euo pipefail
cd "$(dirname "$0")/.."
runs="${1:-1000000}"
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(segmentation cloud_reader)

# clang-14 with libFuzzer and the sanitizer runtimes (libclang-rt-14-dev), and LLVM's OpenMP
# (libomp-14-dev: the top-level find_package(OpenMP) needs it with clang, although the fuzz targets
# link GCC's libgomp, see fuzz/CMakeLists.txt). The normal build and its tests need none of them.
bash scripts/install_deps.sh clang-14 libclang-rt-14-dev libomp-14-dev

# -O2 -g without NDEBUG: Eigen's own bounds assertions stay on in our code.
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g" \
  -DPCL_RSPD_BUILD_FUZZERS=ON -DPCL_RSPD_BUILD_TOOLS=OFF -DPCL_RSPD_BUILD_TESTS=OFF >/dev/null
jobs=$(bash scripts/jobs.sh)
[ "$jobs" -le 2 ] || jobs=2
cmake --build build-fuzz -j"$jobs" --target "${targets[@]/#/fuzz_}"

# One thread for whatever OpenMP PCL itself runs (FLANN), as the targets ask of the library.
export OMP_NUM_THREADS=1
for t in "${targets[@]}"; do
  case "$t" in
    segmentation) max_len=4096 ;;
    cloud_reader) max_len=16384 ;;
    *) echo "unknown target: $t" >&2; exit 2 ;;
  esac
  mkdir -p "build-fuzz/corpus/$t" "build-fuzz/artifacts/$t"
  echo "== fuzz_$t: $runs runs (progress: tail -f build-fuzz/fuzz_$t.log)"
  start=$(date +%s)
  set +e
  build-fuzz/fuzz/fuzz_"$t" -runs="$runs" -max_len="$max_len" -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="build-fuzz/artifacts/$t/" \
    "build-fuzz/corpus/$t" "fuzz/corpus/$t" "fuzz/regressions/$t" >"build-fuzz/fuzz_$t.log" 2>&1
  status=$?
  set -e
  grep -E '^#[0-9]+[[:space:]]+(INITED|DONE)|^stat::|^SUMMARY|ERROR|invariant violated|Test unit written' \
    "build-fuzz/fuzz_$t.log" || true
  echo "fuzz_$t: exit $status after $(( $(date +%s) - start )) s (full log: build-fuzz/fuzz_$t.log)"
  [ "$status" -eq 0 ] || exit "$status"
done
