#!/usr/bin/env bash
# Installs, with apt-get, whatever isopatch needs that this Debian 12 machine does not have yet.
# Usage: scripts/install-deps.sh [--bench]   (as root, or with sudo available)
#   --bench  also what only the performance report's peers need (scripts/performance_report.sh):
#            VTK for the Flying Edges peer and GNU time for the peak memory; never the library's
set -euo pipefail
packages=(build-essential cmake ninja-build pkg-config libeigen3-dev libcli11-dev libgtest-dev libgmock-dev
          libbenchmark-dev nlohmann-json3-dev libstb-dev libpng-dev libtbb-dev libcgal-dev python3 zlib1g-dev
          python3-dev pybind11-dev python3-numpy python3-pytest python3-meshio python3-skimage)
[ "${1:-}" = "--bench" ] && packages+=(libvtk9-dev time)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "isopatch: all build dependencies are installed"
  exit 0
fi
echo "isopatch: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
