#!/usr/bin/env bash
# W1 walkthrough benchmark (529 cows, every resolution policy, Fig. 8 plot).
# Builds nothing: run scripts/build.sh (or scripts/run-demo.sh) first.
# Results go to ./walkthrough-output or the folder given as first argument;
# further arguments go to WalkthroughBenchmark (e.g. --quick, --frames 120).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/benchmark-runner.sh"
benchmark_extra_args=()
run_benchmark WalkthroughBenchmark walkthrough-output walkthrough plot_walkthrough.py "$@"
