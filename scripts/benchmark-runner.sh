# Sourced by run-walkthrough.sh and run-viewdependent.sh: runs a benchmark of
# the build (scripts/build.sh first) into an output folder, under Xvfb when
# there is no display, then its matplotlib plot.
#
#   run_benchmark <binary> <output folder name> <stem> <plot script> [args...]
#
# The first argument that does not start with -- is the output folder
# (default ./<output folder name>); the others go to the binary, after the
# caller's array benchmark_extra_args. Results: <folder>/<stem>.json and .png.
run_benchmark() {
  local binary="$1" default_output="$2" stem="$3" plot="$4"
  shift 4
  local root build out bin name
  root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
  build="${TIMECRITICAL_BUILD_DIR:-$root/build}"
  name="$(basename "$0")"
  out="$root/$default_output"
  if [ $# -gt 0 ] && [ "${1#--}" = "$1" ]; then
    out="$1"
    shift
  fi
  bin="$build/bin/$binary"
  if [ ! -x "$bin" ]; then
    echo "$name: $bin not found: build first (scripts/build.sh)" >&2
    exit 1
  fi
  local launcher=()
  if [ -z "${DISPLAY:-}" ]; then
    # VTK here is an X build: render into a virtual screen.
    launcher=(xvfb-run -a -s "-screen 0 1024x768x24 -noreset")
  fi
  mkdir -p "$out"
  "${launcher[@]}" "$bin" --output "$out" --no-plot "${benchmark_extra_args[@]}" "$@"
  if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
    /usr/bin/python3 "$root/scripts/$plot" "$out/$stem.json" --output "$out/$stem.png"
  else
    echo "$name: /usr/bin/python3 has no matplotlib: no plot" >&2
  fi
}
