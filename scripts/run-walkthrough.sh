#!/usr/bin/env bash
# W1 walkthrough benchmark (529 cows, every resolution policy, Fig. 8 plot).
# Builds nothing: run scripts/build.sh (or scripts/run-demo.sh) first.
# Results go to ./walkthrough-output or the folder given as first argument;
# further arguments go to WalkthroughBenchmark (e.g. --quick, --frames 120).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TIMECRITICAL_BUILD_DIR:-$root/build}"
out="$root/walkthrough-output"
if [ $# -gt 0 ] && [ "${1#--}" = "$1" ]; then
  out="$1"
  shift
fi
bin="$build/bin/WalkthroughBenchmark"
if [ ! -x "$bin" ]; then
  echo "run-walkthrough.sh: $bin not found: build first (scripts/build.sh)" >&2
  exit 1
fi
launcher=()
if [ -z "${DISPLAY:-}" ]; then
  # VTK here is an X build: render into a virtual screen.
  launcher=(xvfb-run -a -s "-screen 0 1024x768x24 -noreset")
fi
mkdir -p "$out"
"${launcher[@]}" "$bin" --output "$out" --no-plot "$@"
if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  /usr/bin/python3 "$root/scripts/plot_walkthrough.py" "$out/walkthrough.json" \
    --output "$out/walkthrough.png"
else
  echo "run-walkthrough.sh: /usr/bin/python3 has no matplotlib: no plot" >&2
fi
