// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_TOMErrorCurve_h
#define timecritical_TOMErrorCurve_h

#include "TimeCriticalMeshCoreExport.h"

#include <cstdint>
#include <string>
#include <vector>

namespace timecritical
{
/**
 * A compact accuracy curve (in the spirit of Pasman & Jansen): geometric error
 * of a TOM against its triangle count, kept as a few dozen samples so that a
 * resolution can be chosen by error as well as by count.
 *
 * Samples are sorted by increasing triangle count with non-increasing error;
 * the last sample is the full mesh with error 0. Between samples the error is
 * interpolated linearly in the triangle count.
 */
class TIMECRITICALMESHCORE_EXPORT TOMErrorCurve
{
public:
  struct Sample
  {
    uint32_t Triangles = 0;
    float Error = 0.f;
  };

  TOMErrorCurve() = default;
  explicit TOMErrorCurve(std::vector<Sample> samples);

  /**
   * Build from per-vertex removal errors of a TOM.
   * vertexError[i] is the error of the mesh with i active vertices
   * (i >= baseVertexCount; must be non-increasing in i), and
   * trianglesAtVertexCount[i] the triangle count of the mesh with i vertices
   * (both arrays of size numberOfVertices + 1, entries below baseVertexCount ignored).
   * At most maxSamples samples are kept, spread so that both error and triangle
   * count are well covered.
   */
  static TOMErrorCurve FromVertexErrors(const float* vertexError,
    const uint32_t* trianglesAtVertexCount, uint32_t numberOfVertices, uint32_t baseVertexCount,
    unsigned maxSamples = 48);

  const std::vector<Sample>& GetSamples() const { return this->Samples; }
  bool IsEmpty() const { return this->Samples.empty(); }

  /// Interpolated error of the mesh with the given triangle count (clamped to the
  /// first and last samples; 0 for an empty curve).
  double GetErrorForTriangles(uint32_t triangles) const;

  /// Smallest triangle count whose interpolated error is at most maxError: the
  /// first sample's count when maxError reaches its error, the full count when
  /// maxError is negative or NaN, 0 for an empty curve.
  uint32_t GetTrianglesForError(double maxError) const;

  /// Empty string when the samples are well formed, otherwise what is wrong.
  std::string Check(uint32_t numberOfTriangles) const;

private:
  std::vector<Sample> Samples;
};
}

#endif
