#!/usr/bin/env bash
# The whole test suite from a fresh machine: installs what it needs (Debian packages,
# including the stock MRPT and OctoMap tools the tests drive), builds, runs ctest; then the
# whole suite again under ASan + UBSan and every fuzz target for FUZZ_SECONDS (default 60:
# issue 8's "a minute per fuzz target") each (scripts/sanitize-tests.sh; doc/reliability.md has
# the long form).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh" --tools
"$root/scripts/build.sh"
cd "${BUILD_DIR:-$root/build}"
ctest --output-on-failure -j "${JOBS:-2}"
"$root/scripts/sanitize-tests.sh" --fuzz-seconds "${FUZZ_SECONDS:-60}"
