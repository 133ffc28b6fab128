#!/usr/bin/env bash
# W5: the Time-Critical Render View on a mixed multiblock (300 blocks, 3.5M
# triangles, a fly-in, a sudden turn), and the same at VTK level.
# Builds nothing: run scripts/build.sh first. Results go to ./w5-output or the
# folder given as first argument; further arguments go to w5_benchmark.py
# (e.g. --runs 3, --quick).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TIMECRITICAL_BUILD_DIR:-$root/build}"
out="$root/w5-output"
if [ $# -gt 0 ] && [ "${1#--}" = "$1" ]; then
  out="$1"
  shift
fi
plugin="$build/lib/paraview-plugins/TimeCritical/TimeCritical.so"
[ -f "$plugin" ] || { echo "run-w5.sh: $plugin not found: build first (scripts/build.sh)" >&2; exit 1; }
launcher=()
[ -n "${DISPLAY:-}" ] || launcher=(xvfb-run -a -s "-screen 0 1024x768x24 -noreset")
PYTHONPATH="$build/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}" \
  "${launcher[@]}" pvbatch --force-offscreen-rendering "$root/scripts/w5_benchmark.py" \
  --plugin "$plugin" --output "$out" "$@"
