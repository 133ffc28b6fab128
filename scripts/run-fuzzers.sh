#!/usr/bin/env bash
# Builds the libFuzzer targets of the VTK-free cores (Testing/Fuzz, with
# clang++, AddressSanitizer and UndefinedBehaviorSanitizer) in ./build-fuzz
# (or $TIMECRITICAL_FUZZ_BUILD_DIR), writes the seed corpus from the shared
# meshes, and runs each target for the given number of seconds (default 60).
#
#   scripts/run-fuzzers.sh [SECONDS] [TARGET...]    (targets: fuzz_tom fuzz_builder fuzz_refine)
#
# New inputs that reach new code are kept in build-fuzz/corpus/<target> (so
# later runs start from there); crashes, sanitizer reports, violated
# invariants, leaks and inputs slower than $TIMECRITICAL_FUZZ_TIMEOUT seconds
# (default 30) are saved to build-fuzz/artifacts/<target>/ and fail the run.
# Replay one with: build-fuzz/<target> <artifact>. Prints the executions per
# target. Runs under nice; set TIMECRITICAL_FUZZ_JOBS=N to run N processes
# per target (libFuzzer -fork), for long runs on idle machines.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TIMECRITICAL_FUZZ_BUILD_DIR:-$root/build-fuzz}"
seconds="${1:-60}"
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_tom fuzz_builder fuzz_refine)
case "$seconds" in
  '' | *[!0-9]*) echo "usage: $0 [SECONDS] [TARGET...]" >&2; exit 2 ;;
esac
timeout_s="${TIMECRITICAL_FUZZ_TIMEOUT:-30}"
jobs="${TIMECRITICAL_FUZZ_JOBS:-1}"
data="${TIMECRITICAL_SHARED_DATA_DIR:-$root/../shared/data}"

if ! command -v clang++ >/dev/null 2>&1; then
  echo "run-fuzzers: clang++ not found (Debian: scripts/install-deps.sh installs clang and libclang-rt-14-dev)" >&2
  exit 1
fi

echo "run-fuzzers: building in $build"
mkdir -p "$build"
nice -n 10 cmake -S "$root/Testing/Fuzz" -B "$build" -DCMAKE_CXX_COMPILER=clang++ >"$build/configure.log" 2>&1 ||
  { cat "$build/configure.log"; exit 1; }
nice -n 10 cmake --build "$build" -j "$(nproc)"

# Seeds are written afresh each run (small pieces of the shared meshes);
# without the shared folder only the generated meshes' seeds are written.
rm -rf "$build/seeds"
"$build/GenerateFuzzSeeds" "$build/seeds" "$data"

# The fuzzers' own reports: leaks are checked (libFuzzer's -detect_leaks);
# UBSan aborts (-fno-sanitize-recover) and prints a stack.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_stack_use_after_return=1:strict_string_checks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

failed=()
summary=()
for target in "${targets[@]}"; do
  [ -x "$build/$target" ] || { echo "run-fuzzers: no target $target" >&2; exit 2; }
  corpus="$build/corpus/$target"
  artifacts="$build/artifacts/$target"
  mkdir -p "$corpus" "$artifacts"
  log="$build/$target.log"
  echo "run-fuzzers: $target for ${seconds}s (log: $log)"
  # First corpus folder: where new inputs go; then the seeds and the
  # committed regression inputs (read only).
  inputs=("$corpus" "$build/seeds/$target")
  [ -d "$root/Testing/Fuzz/regressions/$target" ] && inputs+=("$root/Testing/Fuzz/regressions/$target")
  extra=()
  [ "$jobs" -gt 1 ] && extra=(-fork="$jobs" -ignore_crashes=0)
  status=0
  nice -n 10 "$build/$target" "${extra[@]}" -max_total_time="$seconds" -timeout="$timeout_s" \
    -max_len=8192 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$artifacts/" \
    "${inputs[@]}" >"$log" 2>&1 || status=$?
  runs="$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)"
  [ -n "$runs" ] || runs="$(sed -n 's/^Done \([0-9]*\) runs.*/\1/p' "$log" | tail -1)"
  [ -n "$runs" ] || runs="$(sed -n 's/^#\([0-9]*\).*/\1/p' "$log" | tail -1)"
  kept="$(find "$corpus" -type f | wc -l)"
  line="$target: ${runs:-?} executions in ${seconds}s, corpus $kept inputs"
  if [ $status -ne 0 ]; then
    failed+=("$target")
    line="$line, FAILED (exit $status)"
    grep -E "invariant violated|ERROR: |SUMMARY: |runtime error|Test unit written|==[0-9]+==" "$log" | head -20 || true
  fi
  summary+=("$line")
done

echo "run-fuzzers: summary"
printf '  %s\n' "${summary[@]}"
if [ ${#failed[@]} -gt 0 ]; then
  echo "run-fuzzers: FAILED: ${failed[*]}; inputs in $build/artifacts/<target>/, replay with $build/<target> <input>"
  exit 1
fi
