// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_TOMMesh_h
#define timecritical_TOMMesh_h

#include "TOMErrorCurve.h"

#include <cstdint>
#include <vector>

namespace timecritical
{
/**
 * A Totally Ordered Mesh (Gobbetti & Bouvier, section 6.1) in plain arrays.
 *
 * Vertices are sorted by removal: the mesh with n active vertices uses exactly
 * vertices [0, n). Vertex i >= BaseVertexCount was removed by the substitution
 * i -> Substitution[i] (always < i); base vertices substitute to themselves.
 * Triangles hold full-resolution vertex ids and are sorted so that the mesh at
 * any resolution is a prefix: triangle t is alive while the vertex count is at
 * least its minimum vertex count, and that count never decreases along the array.
 */
struct TOMMesh
{
  std::vector<uint32_t> Substitution; ///< one entry per vertex
  std::vector<uint32_t> Triangles;    ///< three full-resolution vertex ids per triangle
  uint32_t BaseVertexCount = 0;       ///< vertices never removed (coarsest mesh)
  uint32_t BaseTriangleCount = 0;     ///< triangles of the coarsest mesh
  TOMErrorCurve ErrorCurve;           ///< geometric error against triangle count

  uint32_t GetNumberOfVertices() const { return static_cast<uint32_t>(this->Substitution.size()); }
  uint32_t GetNumberOfTriangles() const { return static_cast<uint32_t>(this->Triangles.size() / 3); }
};
}

#endif
