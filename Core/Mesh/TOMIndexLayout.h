// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_TOMIndexLayout_h
#define timecritical_TOMIndexLayout_h

#include <cstddef>
#include <cstdint>

namespace timecritical
{
/**
 * Index layouts of the non-surface representations, shared by the mappers
 * that draw TOM triangles as lines or points: one GL_TRIANGLES primitive
 * becomes three GL_LINES edges (VTK's wireframe layout), and the points of a
 * TOM at a resolution are its active vertices [0, vertexCount). `base` is
 * added to every index (the object's first point in a merged vertex buffer).
 */

/// Writes 6 indices per triangle (edges ab, bc, ca) of `count` triangles.
inline void WriteTriangleEdges(
  const uint32_t* triangles, std::size_t count, uint32_t base, uint32_t* edges)
{
  for (std::size_t t = 0; t < count; ++t, triangles += 3, edges += 6)
  {
    const uint32_t a = triangles[0] + base;
    const uint32_t b = triangles[1] + base;
    const uint32_t c = triangles[2] + base;
    edges[0] = a;
    edges[1] = b;
    edges[2] = b;
    edges[3] = c;
    edges[4] = c;
    edges[5] = a;
  }
}

/// Writes base, base + 1, ..., base + count - 1.
inline void WriteVertexRange(std::size_t count, uint32_t base, uint32_t* out)
{
  for (std::size_t v = 0; v < count; ++v)
  {
    out[v] = base + static_cast<uint32_t>(v);
  }
}
}

#endif
