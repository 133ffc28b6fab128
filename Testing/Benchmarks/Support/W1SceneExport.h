// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_W1SceneExport_h
#define timecritical_W1SceneExport_h

#include <string>

namespace timecritical
{
namespace benchmark
{
struct CowTOM;
struct Scene;
class W1CameraPath;

/**
 * Writes W1's scene as the C++ benchmarks build it (the object, the herd's
 * layout with each replica's 4x4 transform and colour, the camera path per
 * frame) to a JSON file, for the test that compares it with the scene
 * scripts/make_w1_scene.py writes. Throws std::runtime_error when the file
 * cannot be written.
 */
void WriteW1SceneJson(const std::string& file, const CowTOM& object, const Scene& scene,
  const W1CameraPath& path, int frames, unsigned seed);
}
}

#endif
