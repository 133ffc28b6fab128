#!/usr/bin/env bash
# W2 view-dependent benchmark (igea after one Loop subdivision, fronts vs full and uniform TOM).
# Builds nothing: run scripts/build.sh (or scripts/run-demo.sh) first.
# Results go to ./viewdependent-output or the folder given as first argument;
# further arguments go to ViewDependentBenchmark (e.g. --quick, --mixed, --frames 60).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/benchmark-runner.sh"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
benchmark_extra_args=()
if [ -f "$root/walkthrough-output/walkthrough.json" ]; then
  # --mixed shows W1's TimeCritical figures of the last W1 run next to its own.
  benchmark_extra_args=(--w1-json "$root/walkthrough-output/walkthrough.json")
fi
run_benchmark ViewDependentBenchmark viewdependent-output viewdependent plot_viewdependent.py "$@"
