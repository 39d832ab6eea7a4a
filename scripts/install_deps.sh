#!/usr/bin/env bash
# Installs what pcl_rspd needs on Debian bookworm (run as root). Does nothing when all is there.
set -euo pipefail
# Extra package names given as arguments are installed too (scripts/fuzz.sh passes clang's).
packages=(cmake g++ make pkg-config libpcl-dev libeigen3-dev libflann-dev libboost-dev libgtest-dev
          libpng-dev python3-catkin-pkg python3-numpy libbenchmark-dev libcgal-dev "$@")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
