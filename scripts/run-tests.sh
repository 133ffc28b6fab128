#!/usr/bin/env bash
# Installs, builds and runs every test headless (rendering tests start their own
# Xvfb through xvfb-run). Extra arguments go to ctest, e.g. -L core.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TIMECRITICAL_BUILD_DIR:-$root/build}"
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
cd "$build"
ctest --output-on-failure -j "$(nproc)" "$@"
