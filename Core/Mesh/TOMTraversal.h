// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_TOMTraversal_h
#define timecritical_TOMTraversal_h

#include "TimeCriticalMeshCoreExport.h"

#include <cstdint>
#include <vector>

namespace timecritical
{
struct TOMMesh;

/**
 * Extracts a TOM at any resolution (Gobbetti & Bouvier, section 6.1.2): walks
 * the triangle prefix, maps every corner down its substitution chain to an
 * active vertex and stops at the first collapsed triangle.
 *
 * Holds views on arrays owned by the caller. Nothing is allocated by the
 * extraction calls when the output buffer is large enough.
 */
class TIMECRITICALMESHCORE_EXPORT TOMTraversal
{
public:
  TOMTraversal() = default;
  explicit TOMTraversal(const TOMMesh& mesh);
  TOMTraversal(const uint32_t* substitution, uint32_t numberOfVertices, const uint32_t* triangles,
    uint32_t numberOfTriangles, uint32_t baseVertexCount);

  uint32_t GetNumberOfVertices() const { return this->NumberOfVertices; }
  uint32_t GetNumberOfTriangles() const { return this->NumberOfTriangles; }

  /// Smallest vertex count at which triangle t is alive (0 for base triangles).
  uint32_t GetMinimumVertexCount(uint32_t t) const;

  /**
   * Vertex count of the finest mesh with at most `triangles` triangles
   * (never below the base vertex count, whose mesh may have more).
   */
  uint32_t GetVertexCountForTriangles(uint32_t triangles) const;

  /// Triangle count for a resolution r in [0,1] (fraction of the full triangle count,
  /// rounded; r is clamped to [0,1] and NaN gives 0, the cheapest answer).
  uint32_t GetTrianglesForResolution(double r) const;

  /**
   * Writes the triangles (3 active vertex ids each) of the mesh with
   * `vertexCount` active vertices into out, which holds `capacity` triangles.
   * Returns the number of triangles of that mesh (may exceed capacity, in which
   * case only `capacity` were written). Entries of out past the returned count
   * (but within capacity) may be used as scratch space. chainSteps, when given,
   * receives the number of substitution steps taken over the corners of the
   * returned triangles (the paper's extra vertices). Vertex counts are clamped
   * to [base vertex count, number of vertices].
   */
  uint32_t Extract(uint32_t vertexCount, uint32_t* out, uint32_t capacity,
    uint64_t* chainSteps = nullptr) const;

  /// Same into a vector, which is only grown (never shrunk) so repeated calls do not allocate.
  uint32_t Extract(uint32_t vertexCount, std::vector<uint32_t>& out,
    uint64_t* chainSteps = nullptr) const;

  /// Active vertex that full-resolution vertex v maps to with vertexCount active vertices.
  uint32_t GetActiveVertex(uint32_t v, uint32_t vertexCount) const;

  /**
   * Geomorph of the last active vertex (v = vertexCount - 1): its attribute
   * interpolated between its substitution target at this resolution (factor 0)
   * and its own value (factor 1). attributes holds `components` values per vertex.
   * vertexCount is clamped to [1, N], factor to [0, 1] (NaN gives 1); base
   * vertices do not move.
   */
  void Geomorph(uint32_t vertexCount, double factor, const float* attributes, int components,
    float* result) const;

private:
  /// vertexCount clamped to [BaseVertexCount, NumberOfVertices].
  uint32_t ClampVertexCount(uint32_t vertexCount) const;
  /// Triangle count of the mesh with n active vertices, by binary search on minimum counts.
  uint32_t CountTriangles(uint32_t n) const;

  const uint32_t* Substitution = nullptr;
  const uint32_t* Triangles = nullptr;
  uint32_t NumberOfVertices = 0;
  uint32_t NumberOfTriangles = 0;
  uint32_t BaseVertexCount = 0;
};
}

#endif
