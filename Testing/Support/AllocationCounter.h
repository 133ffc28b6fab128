// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_AllocationCounter_h
#define timecritical_AllocationCounter_h

#include <cstddef>

namespace timecritical
{
namespace testing
{
/**
 * Number of global operator new calls so far in this process. Linking the
 * object library TimeCriticalAllocationCounter replaces every form of the
 * global operator new/delete with counting ones, so tests can check that a
 * hot path does not allocate (the count must not change across the call).
 */
std::size_t GetAllocationCount();
}
}

#endif
