#!/usr/bin/env bash
# The whole test suite from a fresh machine: installs what it needs (Debian packages,
# including the stock MRPT and OctoMap tools the tests drive), builds, runs ctest.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh" --tools
"$root/scripts/build.sh"
cd "${BUILD_DIR:-$root/build}"
ctest --output-on-failure -j "${JOBS:-2}"
