#!/usr/bin/env bash
# Installs whiskermap's build, test and tool dependencies from Debian's packages.
# Idempotent: packages already installed are skipped, and apt is not touched at all
# when everything is present. Usage: scripts/install-deps.sh [--tools]
#   --tools  also install the stock MRPT / OctoMap tools used by the tests
#            (rawlog-edit, pf-localization, convert_octree), python3 (scripts/eval-categories.sh),
#            pytest and matplotlib (the Python module's tests and example).
set -euo pipefail

build_pkgs=(cmake g++ make pkg-config libmrpt-maps-dev libmrpt-slam-dev
            libeigen3-dev liboctomap-dev libgtest-dev libbenchmark-dev libcli11-dev
            nlohmann-json3-dev clang libclang-rt-14-dev python3-dev pybind11-dev python3-numpy)
tool_pkgs=(mrpt-apps octomap-tools python3 python3-pytest python3-matplotlib)

want=("${build_pkgs[@]}")
[[ "${1:-}" == "--tools" ]] && want+=("${tool_pkgs[@]}")

missing=()
for p in "${want[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [[ ${#missing[@]} -eq 0 ]]; then
  echo "install-deps: all ${#want[@]} packages already installed"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
[[ $(id -u) -ne 0 ]] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
