#!/usr/bin/env bash
# Fresh machine to first result: install dependencies, build, and segment the bundled default scene
# (a generated room scanned from one position) with rspd_segment.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/build.sh
./build/rspd_segment --demo -o build/demo_labeled.pcd --png build/demo.png -v "$@"
