#!/usr/bin/env bash
# W6 "overload": 20,000 small objects whose coarsest levels cost about 3x the
# 100 ms target, at VTK level, with dropping on and off in one run.
# Builds nothing: run scripts/build.sh first. Results go to ./w6-output or the
# folder given as first argument; further arguments go to w6_benchmark.py
# (e.g. --objects 30000, --quick).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TIMECRITICAL_BUILD_DIR:-$root/build}"
out="$root/w6-output"
if [ $# -gt 0 ] && [ "${1#--}" = "$1" ]; then
  out="$1"
  shift
fi
package="$build/lib/python3/dist-packages"
[ -d "$package/timecritical" ] || { echo "run-w6.sh: $package/timecritical not found: build first (scripts/build.sh)" >&2; exit 1; }
launcher=()
[ -n "${DISPLAY:-}" ] || launcher=(xvfb-run -a -s "-screen 0 1024x768x24 -noreset")
PYTHONPATH="$package${PYTHONPATH:+:$PYTHONPATH}" \
  "${launcher[@]}" /usr/bin/python3 "$root/scripts/w6_benchmark.py" --output "$out" "$@"
