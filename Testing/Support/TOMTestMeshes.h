// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_TOMTestMeshes_h
#define timecritical_TOMTestMeshes_h

#include "TOMMesh.h"

namespace timecritical
{
namespace testing
{
/**
 * The smallest TOM with chains of length 2: a square (0, 1, 2, 3) with a
 * centre 4; 4 -> 3 then 3 -> 0. (1,2,4) survives to the base mesh, (0,1,4)
 * dies when 3 leaves, (2,3,4) and (3,0,4) when 4 leaves: minimum vertex
 * counts 0, 4, 5, 5.
 */
inline TOMMesh MakeFanTOM()
{
  TOMMesh mesh;
  mesh.Substitution = { 0, 1, 2, 0, 3 };
  mesh.BaseVertexCount = 3;
  mesh.Triangles = { 1, 2, 4, 0, 1, 4, 2, 3, 4, 3, 0, 4 };
  mesh.BaseTriangleCount = 1;
  return mesh;
}
}
}

#endif
