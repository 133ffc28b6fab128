// SPDX-License-Identifier: BSD-3-Clause
// Export macro of the VTK-free cores. Written by hand instead of using the
// header VTK's module system generates, which pulls in a VTK header.
#ifndef TimeCriticalFiltersCoreExport_h
#define TimeCriticalFiltersCoreExport_h

#if defined(TIMECRITICALFILTERSCORE_STATIC_DEFINE)
#define TIMECRITICALFILTERSCORE_EXPORT
#elif defined(_WIN32)
#if defined(FiltersCore_EXPORTS)
#define TIMECRITICALFILTERSCORE_EXPORT __declspec(dllexport)
#else
#define TIMECRITICALFILTERSCORE_EXPORT __declspec(dllimport)
#endif
#else
#define TIMECRITICALFILTERSCORE_EXPORT __attribute__((visibility("default")))
#endif

#endif
