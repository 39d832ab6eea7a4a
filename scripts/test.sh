#!/usr/bin/env bash
# Fresh machine to a tested build: install dependencies, build, run the whole suite with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(bash scripts/jobs.sh)" "$@"
