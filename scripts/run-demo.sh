#!/usr/bin/env bash
# Main job: install, build, and run the TOM demo. Images and the summary go to
# ./demo-output (or the folder given as first argument).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TIMECRITICAL_BUILD_DIR:-$root/build}"
out="${1:-$root/demo-output}"
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
launcher=()
if [ -z "${DISPLAY:-}" ]; then
  launcher=(xvfb-run -a -s "-screen 0 1024x768x24 -noreset")
fi
PYTHONPATH="$build/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}" \
  "${launcher[@]}" /usr/bin/python3 "$root/scripts/tom_demo.py" --output "$out"
