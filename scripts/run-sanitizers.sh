#!/usr/bin/env bash
# Builds the project with AddressSanitizer + UndefinedBehaviorSanitizer
# (TIMECRITICAL_SANITIZERS=address,undefined) in ./build-asan (or
# $TIMECRITICAL_ASAN_BUILD_DIR) and runs the C++ tests of the cores and of
# the VTK classes there (ctest labels core and vtk, the rendering tests under
# Xvfb included). Leaks are detected; any report fails its test. The test
# executables carry their sanitizer options and the LeakSanitizer
# suppressions of Testing/Sanitizers/lsan.supp (SanitizerSupport.cxx);
# ASAN_OPTIONS, LSAN_OPTIONS and UBSAN_OPTIONS in the environment add to them.
#
# Not run here: the Python tests (label python), which would load the
# instrumented modules into the uninstrumented /usr/bin/python3 and pvbatch,
# the benchmarks, the install test, and the tests that time the cores against
# a speed goal (timing_tests below), which sanitizers slow down several times.
# Only the C++ test executables are built (target timecritical_cxx_tests).
#
# Then a ThreadSanitizer build (TIMECRITICAL_SANITIZERS=thread) in
# ./build-tsan (or $TIMECRITICAL_TSAN_BUILD_DIR) runs the tests labelled
# threads (worker-thread code: background hierarchy builds, caches). Only
# their executables are built ($TIMECRITICAL_TSAN_TARGETS, below). VTK is not
# instrumented: Testing/Sanitizers/tsan.supp suppresses what TSan reports
# inside it, with a reason per line. TIMECRITICAL_TSAN=0 skips this part.
# Extra arguments go to ctest, e.g. -R Mapper.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TIMECRITICAL_ASAN_BUILD_DIR:-$root/build-asan}"
timing_tests='^(MergeTreeAttributes\.Speed|WeldPoints\.LargeMeshIsFast|ActiveSetOptimizer\.HonoursTinyTimeLimits)$'
mkdir -p "$build"

# -O1 -g1 compiles much faster than -O2 -g (the tests of the VTK classes
# dominate) and still gives file:line in the reports; NDEBUG stays off.
nice -n 10 cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1" \
  -DTIMECRITICAL_SANITIZERS=address,undefined -DTIMECRITICAL_BUILD_BENCHMARKS=OFF \
  -DTIMECRITICAL_REQUIRE_ALL_DEPENDENCIES=ON >"$build/configure.log" 2>&1 ||
  { cat "$build/configure.log"; exit 1; }
# (gtest_discover_tests runs the instrumented executables at build time.)
nice -n 10 cmake --build "$build" -j "$(nproc)" --target timecritical_cxx_tests
cd "$build"
# The rendering tests one at a time: some check frame times their renderer
# measured, which a second instrumented test rendering next to them can skew.
status=0
nice -n 10 ctest --output-on-failure -j "$(nproc)" -L 'core|vtk' -LE 'python|render' \
  -E "$timing_tests" "$@" || status=$?
nice -n 10 ctest --output-on-failure -L render -LE python -E "$timing_tests" "$@" || status=$?

# ThreadSanitizer: the tests labelled threads, built alone.
if [ "${TIMECRITICAL_TSAN:-1}" != 0 ]; then
  tsan_build="${TIMECRITICAL_TSAN_BUILD_DIR:-$root/build-tsan}"
  tsan_targets="${TIMECRITICAL_TSAN_TARGETS:-TestvtkHierarchyBuildQueue TestvtkMultiresolutionPolyDataMapperBackground TestvtkMultiresolutionHierarchyBuilder TestvtkHierarchyBuildCache TestLeafHierarchyBuild}"
  mkdir -p "$tsan_build"
  nice -n 10 cmake -S "$root" -B "$tsan_build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1" \
    -DTIMECRITICAL_SANITIZERS=thread -DTIMECRITICAL_BUILD_BENCHMARKS=OFF \
    -DTIMECRITICAL_REQUIRE_ALL_DEPENDENCIES=ON >"$tsan_build/configure.log" 2>&1 ||
    { cat "$tsan_build/configure.log"; exit 1; }
  # shellcheck disable=SC2086 # a list of targets
  nice -n 10 cmake --build "$tsan_build" -j "$(nproc)" --target $tsan_targets
  cd "$tsan_build"
  # halt_on_error: a report fails its test. The kernel's 32-bit mmap
  # randomization of recent kernels breaks TSan's memory layout ("unexpected
  # memory mapping"): setarch -R runs the tests without it.
  export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$root/Testing/Sanitizers/tsan.supp${TSAN_OPTIONS:+:$TSAN_OPTIONS}"
  nice -n 10 setarch "$(uname -m)" -R ctest --output-on-failure -L threads -LE python "$@" ||
    status=$?
fi
exit $status
