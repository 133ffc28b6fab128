#!/usr/bin/env bash
# Configures and builds TimeCritical in ./build (or $TIMECRITICAL_BUILD_DIR).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TIMECRITICAL_BUILD_DIR:-$root/build}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DTIMECRITICAL_REQUIRE_ALL_DEPENDENCIES=ON "$@"
cmake --build "$build" -j "$(nproc)"
