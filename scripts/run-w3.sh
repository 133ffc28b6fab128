#!/usr/bin/env bash
# W3 scale benchmark: >= 10M triangles in >= 2,000 objects
# at a 100 ms target, with the renderer's memory above the input data.
# Builds nothing: run scripts/build.sh (or scripts/run-demo.sh) first.
# Results go to ./w3-output or the folder given as first argument (the TOMs
# are cached there as .vtp, so reruns skip building them); further arguments
# go to W3Benchmark (e.g. --frames 60, --scale 0.5, --quick).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/benchmark-runner.sh"
benchmark_extra_args=()
run_benchmark W3Benchmark w3-output w3 plot_w3.py "$@"
