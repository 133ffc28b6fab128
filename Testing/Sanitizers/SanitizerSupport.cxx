// SPDX-License-Identifier: BSD-3-Clause
// Linked into every C++ test executable of a build with TIMECRITICAL_SANITIZERS
// (see the top-level CMakeLists.txt), and only there.
//
// 1. Default options of the sanitizer runtimes and the LeakSanitizer
//    suppressions of lsan.supp, so that every way of running the tests (ctest,
//    scripts/run-sanitizers.sh, a test executable by hand, the test discovery
//    at build time) checks the same; ASAN_OPTIONS, LSAN_OPTIONS and
//    UBSAN_OPTIONS in the environment are applied after these and win.
// 2. Shared libraries are never unloaded. Mesa loads its OpenGL driver
//    (swrast_dri.so with llvmpipe, and LLVM) for every X display that VTK
//    opens and unloads it when the display closes; the memory the driver
//    still holds through its own globals then looks leaked to LeakSanitizer,
//    and the frames of the unloaded library cannot be named, so no
//    suppression can select them. Kept loaded, that memory stays reachable
//    and every frame keeps its library's name (lsan.supp can name it).
//    Nothing else changes: dlopen() of a loaded library returns it again.
#include "TimeCriticalLsanSuppressions.h" // generated from lsan.supp

extern "C"
{
  // The suppressions of lsan.supp, compiled in (TIMECRITICAL_LSAN_SUPPRESSIONS).
  const char* __lsan_default_suppressions()
  {
    return TIMECRITICAL_LSAN_SUPPRESSIONS;
  }

  const char* __asan_default_options()
  {
    return "detect_leaks=1:halt_on_error=1:check_initialization_order=1:strict_init_order=1:"
           "detect_stack_use_after_return=1:strict_string_checks=1";
  }

  const char* __ubsan_default_options()
  {
    return "print_stacktrace=1:halt_on_error=1";
  }

  // Interposes glibc's dlclose() for the whole process (the executable's
  // definition comes first in the global symbol scope).
  int dlclose(void*)
  {
    return 0;
  }
}
