#!/usr/bin/env bash
# Installs, builds and runs every test headless (rendering tests start their own
# Xvfb through xvfb-run), then the sanitizer and fuzzing checks:
#   1. the build in ./build (or $TIMECRITICAL_BUILD_DIR) and all its ctest tests;
#      extra arguments go to this ctest, e.g. -L core;
#   2. scripts/run-sanitizers.sh: the C++ tests (labels core, vtk) built with
#      AddressSanitizer + UndefinedBehaviorSanitizer in ./build-asan (or
#      $TIMECRITICAL_ASAN_BUILD_DIR); TIMECRITICAL_RUN_SANITIZERS=0 skips it;
#   3. scripts/run-fuzzers.sh: the libFuzzer targets of the cores in
#      ./build-fuzz (or $TIMECRITICAL_FUZZ_BUILD_DIR), each for
#      $TIMECRITICAL_FUZZ_SECONDS seconds (default 60; 0 skips it).
# Every part runs even when an earlier one failed; the exit status is 1 if any did.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TIMECRITICAL_BUILD_DIR:-$root/build}"
fuzz_seconds="${TIMECRITICAL_FUZZ_SECONDS:-60}"
"$root/scripts/install-deps.sh"

failed=()
timings=()
part() { # part <name> <command...>: runs it, records its time and status
  local name="$1" start status=0
  shift
  start=$(date +%s)
  echo "run-tests: === $name ==="
  "$@" || status=$?
  timings+=("$name: $(($(date +%s) - start)) s$([ $status -eq 0 ] || echo ", FAILED (exit $status)")")
  [ $status -eq 0 ] || failed+=("$name")
}
tests() {
  "$root/scripts/build.sh" && (cd "$build" && ctest --output-on-failure -j "$(nproc)" "$@")
}

part "build and tests" tests "$@"
if [ "${TIMECRITICAL_RUN_SANITIZERS:-1}" != 0 ]; then
  part "sanitizers (ASan + UBSan)" "$root/scripts/run-sanitizers.sh"
fi
if [ "$fuzz_seconds" != 0 ]; then
  part "fuzzing (${fuzz_seconds} s per target)" "$root/scripts/run-fuzzers.sh" "$fuzz_seconds"
fi

echo "run-tests: summary"
printf '  %s\n' "${timings[@]}"
if [ ${#failed[@]} -gt 0 ]; then
  echo "run-tests: FAILED: ${failed[*]}"
  exit 1
fi
echo "run-tests: all passed"
