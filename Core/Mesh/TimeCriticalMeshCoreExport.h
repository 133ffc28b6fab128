// SPDX-License-Identifier: BSD-3-Clause
// Export macro of the VTK-free cores. Written by hand instead of using the
// header VTK's module system generates, which pulls in a VTK header.
#ifndef TimeCriticalMeshCoreExport_h
#define TimeCriticalMeshCoreExport_h

#if defined(TIMECRITICALMESHCORE_STATIC_DEFINE)
#define TIMECRITICALMESHCORE_EXPORT
#elif defined(_WIN32)
#if defined(MeshCore_EXPORTS)
#define TIMECRITICALMESHCORE_EXPORT __declspec(dllexport)
#else
#define TIMECRITICALMESHCORE_EXPORT __declspec(dllimport)
#endif
#else
#define TIMECRITICALMESHCORE_EXPORT __attribute__((visibility("default")))
#endif

#endif
