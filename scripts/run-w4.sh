#!/usr/bin/env bash
# W4 changing-data benchmark (issue 20): a time series of a ~1M-triangle
# isosurface (and its 200-block variant) and a contour edit, played in
# ParaView's Render View and the Time-Critical Render View under pvbatch.
# Builds nothing: run scripts/build.sh (or scripts/run-demo.sh) first.
#
#   scripts/run-w4.sh [OUTPUT] [options of scripts/w4_benchmark.py]
#
# Results go to ./w4-output or the folder given as first argument (w4.json,
# w4.png, key frames); the series is generated into ./w4-data when missing
# (override with --data DIR; --tiny for a small series that runs in seconds).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TIMECRITICAL_BUILD_DIR:-$root/build}"
name="$(basename "$0")"
out="$root/w4-output"
if [ $# -gt 0 ] && [ "${1#--}" = "$1" ]; then
  out="$1"
  shift
fi
plugin="${TIMECRITICAL_PLUGIN:-$build/lib/paraview-plugins/TimeCritical/TimeCritical.so}"
if [ ! -f "$plugin" ]; then
  echo "$name: $plugin not found: build first (scripts/build.sh)" >&2
  exit 1
fi
# The data folder and the generation options are the benchmark's: pass them on.
data="$root/w4-data"
generate=()
args=("$@")
for ((i = 0; i < ${#args[@]}; i++)); do
  case "${args[$i]}" in
    --data) data="${args[$((i + 1))]}" ;;
    --tiny) generate+=(--tiny) ;;
    --steps | --resolution | --blocks) generate+=("${args[$i]}" "${args[$((i + 1))]}") ;;
  esac
done
mkdir -p "$out"
# Generate first, outside pvbatch (it writes the files the benchmark reads).
/usr/bin/python3 "$root/scripts/make_w4_series.py" --output "$data" "${generate[@]}"
launcher=()
if [ -z "${DISPLAY:-}" ]; then
  launcher=(xvfb-run -a -s "-screen 0 1024x768x24 -noreset")
fi
export PYTHONPATH="$build/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}"
"${launcher[@]}" pvbatch --force-offscreen-rendering "$root/scripts/w4_benchmark.py" \
  --plugin "$plugin" --data "$data" --output "$out" "$@"
if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  /usr/bin/python3 "$root/scripts/plot_w4.py" "$out/w4.json" --output "$out/w4.png"
else
  echo "$name: /usr/bin/python3 has no matplotlib: no plot" >&2
fi
