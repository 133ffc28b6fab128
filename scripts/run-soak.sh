#!/usr/bin/env bash
# Soak test (scripts/soak.py): 10,000 frames of a many-object scene with the
# camera moving while actors are added, removed and given new data; records
# frame times, RSS and heap in use, fails on VTK errors or memory growth.
# Builds nothing: run scripts/build.sh first. Results: ./soak-output/soak.json
# or the folder given as first argument; further arguments go to soak.py
# (e.g. --frames 2000).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TIMECRITICAL_BUILD_DIR:-$root/build}"
out="$root/soak-output"
if [ $# -gt 0 ] && [ "${1#--}" = "$1" ]; then
  out="$1"
  shift
fi
package="$build/lib/python3/dist-packages"
if [ ! -d "$package/timecritical" ]; then
  echo "run-soak.sh: $package/timecritical not found: build first (scripts/build.sh)" >&2
  exit 1
fi
launcher=()
if [ -z "${DISPLAY:-}" ]; then
  launcher=(xvfb-run -a -s "-screen 0 1024x768x24 -noreset")
fi
mkdir -p "$out"
PYTHONPATH="$package" "${launcher[@]}" /usr/bin/python3 "$root/scripts/soak.py" \
  --json "$out/soak.json" "$@"
