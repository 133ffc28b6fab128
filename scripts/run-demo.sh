#!/usr/bin/env bash
# Main job: install, build, and run the W1 walkthrough benchmark (529 cows,
# every resolution policy, about 10 minutes). The plot, the statistics and
# key frames (with resolution maps) go to ./walkthrough-output, or to the
# folder given as first argument; further arguments go to WalkthroughBenchmark
# (e.g. --frames 120, --policies none,timecritical).
# Without ../shared/data the scene is made of a generated cow-sized mesh.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
"$root/scripts/run-walkthrough.sh" "$@"
