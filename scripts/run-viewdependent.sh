#!/usr/bin/env bash
# W2 view-dependent benchmark (igea after one Loop subdivision, fronts vs full and uniform TOM).
# Builds nothing: run scripts/build.sh (or scripts/run-demo.sh) first.
# Results go to ./viewdependent-output or the folder given as first argument;
# further arguments go to ViewDependentBenchmark (e.g. --quick, --mixed, --frames 60).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TIMECRITICAL_BUILD_DIR:-$root/build}"
out="$root/viewdependent-output"
if [ $# -gt 0 ] && [ "${1#--}" = "$1" ]; then
  out="$1"
  shift
fi
bin="$build/bin/ViewDependentBenchmark"
if [ ! -x "$bin" ]; then
  echo "run-viewdependent.sh: $bin not found: build first (scripts/build.sh)" >&2
  exit 1
fi
launcher=()
if [ -z "${DISPLAY:-}" ]; then
  # VTK here is an X build: render into a virtual screen.
  launcher=(xvfb-run -a -s "-screen 0 1024x768x24 -noreset")
fi
mkdir -p "$out"
w1=()
if [ -f "$root/walkthrough-output/walkthrough.json" ]; then
  # --mixed shows W1's TimeCritical figures of the last W1 run next to its own.
  w1=(--w1-json "$root/walkthrough-output/walkthrough.json")
fi
"${launcher[@]}" "$bin" --output "$out" --no-plot "${w1[@]}" "$@"
if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  /usr/bin/python3 "$root/scripts/plot_viewdependent.py" "$out/viewdependent.json" \
    --output "$out/viewdependent.png"
else
  echo "run-viewdependent.sh: /usr/bin/python3 has no matplotlib: no plot" >&2
fi
