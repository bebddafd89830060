#!/usr/bin/env bash
# Installs, with apt-get, whatever isopatch needs that this Debian 12 machine does not have yet, then
# the viewer's npm packages (web/package-lock.json: three for the page of 'isopatch view',
# playwright-core and gltf-validator for its tests) with npm ci when web/node_modules is not current.
# Usage: scripts/install-deps.sh [--bench]   (as root, or with sudo available)
#   --bench  also what only the performance report's peers need (scripts/performance_report.sh):
#            VTK for the Flying Edges peer and GNU time for the peak memory; never the library's
set -euo pipefail
packages=(build-essential cmake ninja-build pkg-config libeigen3-dev libcli11-dev libgtest-dev libgmock-dev
          libbenchmark-dev nlohmann-json3-dev libstb-dev libpng-dev libtbb-dev libcgal-dev python3 zlib1g-dev
          python3-dev pybind11-dev python3-numpy python3-pytest python3-meshio python3-skimage
          libtinygltf-dev libcpp-httplib-dev lib3mf-dev nodejs npm chromium doxygen)
# libcgal-dev (above): header-only CGAL, the tests' exact checks and the library's planar caps (src/planar)
packages+=(prusa-slicer)  # the tests' slicer: python/tests/test_print_clients.py runs prusa-slicer --info
packages+=(python3-distributed)  # isopatch.distributed: blocked runs on Dask (docs/distributed.md)
packages+=(clang-format clang-tidy)  # scripts/check_format.sh, scripts/check_tidy.sh (version 14 on Debian 12)
packages+=(dpkg-dev man-db)  # the Debian package: dpkg-shlibdeps for its dependencies, man for its page's test
packages+=(python3-mypy)  # python/tests/test_typing.py: type checkers see the package's API
packages+=(libopenvdb-dev python3-openvdb)  # .vdb input (src/vdb); the tests write level sets with pyopenvdb
packages+=(python3-open3d python3-scipy)  # python/tests/test_real_clients.py: Open3D reads the meshes
packages+=(python3-pygalmesh)  # python/bench/compare_peers.py: CGAL's mesher from Python, side by side
packages+=(python3-pip python3-setuptools python3-wheel python3-build)  # pip install . and the wheel (package.pip)
[ "${1:-}" = "--bench" ] && packages+=(libvtk9-dev time)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# nodejs and npm: any installed node with npm will do (a machine may have node from elsewhere).
if command -v node >/dev/null && command -v npm >/dev/null; then
  filtered=()
  for p in "${missing[@]}"; do [ "$p" = nodejs ] || [ "$p" = npm ] || filtered+=("$p"); done
  missing=("${filtered[@]}")
fi
# The viewer's JavaScript packages, exactly as locked; skipped when the last npm ci here installed this
# very lock file (a copy of it is kept in node_modules as the stamp).
install_web_packages() {
  local web
  web="$(cd "$(dirname "$0")/../web" && pwd)"
  if ! cmp -s "$web/package-lock.json" "$web/node_modules/.isopatch-installed-lock.json"; then
    echo "isopatch: installing the viewer's npm packages (web/package-lock.json)"
    (cd "$web" && npm ci --no-audit --no-fund --loglevel=error)
    cp "$web/package-lock.json" "$web/node_modules/.isopatch-installed-lock.json"
  fi
}
if [ ${#missing[@]} -eq 0 ]; then
  echo "isopatch: all build dependencies are installed"
  install_web_packages
  exit 0
fi
echo "isopatch: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
install_web_packages
