// SPDX-License-Identifier: BSD-3-Clause
// Export macro of the VTK-free rendering cores. Written by hand instead of
// using the header VTK's module system generates, which pulls in a VTK header.
#ifndef TimeCriticalBudgetCoreExport_h
#define TimeCriticalBudgetCoreExport_h

#if defined(TIMECRITICALBUDGETCORE_STATIC_DEFINE)
#define TIMECRITICALBUDGETCORE_EXPORT
#elif defined(_WIN32)
#if defined(BudgetCore_EXPORTS)
#define TIMECRITICALBUDGETCORE_EXPORT __declspec(dllexport)
#else
#define TIMECRITICALBUDGETCORE_EXPORT __declspec(dllimport)
#endif
#else
#define TIMECRITICALBUDGETCORE_EXPORT __attribute__((visibility("default")))
#endif

#endif
