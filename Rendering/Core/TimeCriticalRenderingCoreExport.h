// SPDX-License-Identifier: BSD-3-Clause
// Export macro of the VTK-free rendering cores. Written by hand instead of
// using the header VTK's module system generates, which pulls in a VTK header.
#ifndef TimeCriticalRenderingCoreExport_h
#define TimeCriticalRenderingCoreExport_h

#if defined(TIMECRITICALRENDERINGCORE_STATIC_DEFINE)
#define TIMECRITICALRENDERINGCORE_EXPORT
#elif defined(_WIN32)
#if defined(RenderingCore_EXPORTS)
#define TIMECRITICALRENDERINGCORE_EXPORT __declspec(dllexport)
#else
#define TIMECRITICALRENDERINGCORE_EXPORT __declspec(dllimport)
#endif
#else
#define TIMECRITICALRENDERINGCORE_EXPORT __attribute__((visibility("default")))
#endif

#endif
