// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_MergeTree_h
#define timecritical_MergeTree_h

#include <cstdint>
#include <cstring>
#include <vector>

namespace timecritical
{
/**
 * View-dependent refinement data of a TOM: the merge tree of Xia, El-Sana &
 * Varshney (sections 4.1-4.4) stored beside the TOM arrays (TOMMesh) of the
 * same mesh, so that one dataset serves the uniform prefix traversal and
 * view-dependent refinement.
 *
 * The merge tree is the TOM's substitution forest: vertex v >= BaseVertexCount
 * is the child that the half-edge collapse (event) e_v merged into its parent
 * Substitution[v] (intermediate vertex = parent position, as in the paper, so
 * vertex positions never change). Vertex ids order the events: a larger id
 * collapsed earlier. The children of a vertex split back in increasing id
 * order (the last collapsed first).
 *
 * Per-vertex arrays have one entry per TOM vertex. For v >= BaseVertexCount
 * they describe the node created by e_v (the parent after absorbing v, i.e.
 * everything merged into the parent up to that event); for a base vertex, its
 * whole subtree (the root node).
 */
/// The smallest float not below x: radii and errors stored as float must stay
/// upper bounds (the builder's and the refinement's widened nodes).
inline float FloatNotBelow(double x)
{
  float f = static_cast<float>(x);
  if (static_cast<double>(f) < x)
  {
    // The next float up (std::nextafter towards +inf, without the call: this
    // runs twice per event at build time): one ulp more in magnitude above 0,
    // less below.
    uint32_t bits;
    std::memcpy(&bits, &f, sizeof(bits));
    bits = f == 0.0f ? 1u : (f > 0.0f ? bits + 1 : bits - 1);
    std::memcpy(&f, &bits, sizeof(f));
  }
  return f;
}

struct MergeTree
{
  /// Level of the independent set whose collapse removed v (0 = finest);
  /// LevelCount for base vertices.
  std::vector<uint16_t> Level;
  uint16_t LevelCount = 0;

  /// Error (world units) of the node: the geometric error (distance between the
  /// original surface of its subtree and its simplified surface) or, with a
  /// shading weight (MergeTreeErrorOptions), the larger of it and the shading
  /// error (lost normal variation times the node's radius); never smaller
  /// than the error of any event that must be split before it (monotone), so
  /// the projected error decides splits and merges alike (downswitch = upswitch).
  std::vector<float> Error;

  /// Radius of the sphere around the parent's position that holds every
  /// original vertex of the node's subtree (screen-space projection, culling).
  std::vector<float> Radius;

  /// Normal cone of the subtree's original surface normals (Gauss-map circle,
  /// section 4.3): unit axis, three floats per vertex, and the cosine of the
  /// half-angle (-1: the cone is the whole sphere).
  std::vector<float> ConeAxis;
  std::vector<float> ConeCosine;

  /**
   * Dependencies (section 4.4), compressed rows: for v >= BaseVertexCount the
   * vertices adjacent to v or its parent just before e_v (the boundary of
   * e_v's region of influence), which must be displayed as those very
   * vertices for e_v to be split or merged. Row v is
   * Dependencies[DependencyOffsets[v], DependencyOffsets[v + 1]); rows of base
   * vertices are empty. DependencyOffsets has one entry per vertex plus one.
   */
  std::vector<uint32_t> DependencyOffsets;
  std::vector<uint32_t> Dependencies;

  uint32_t GetNumberOfVertices() const { return static_cast<uint32_t>(this->Error.size()); }
};
}

#endif
