// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_QuadricRecord_h
#define timecritical_QuadricRecord_h

/*
 * Internal to TimeCritical::MeshCore: the per-vertex quadric record of the
 * collapse engine, in single precision around its vertex, and the two
 * functions that change its matrix and its face weight.
 */

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace timecritical
{
namespace collapse
{
/**
 * The per-vertex quadric (face planes + weighted constraint planes, which
 * order the collapses), read only to compute the vertex's own candidates.
 *
 * It is stored relative to the vertex's own position p0, as
 * Q(p0 + d) = C + 2 G.d + d^T A d, which is well conditioned even in single
 * precision: d is an edge length or so, and C is the error accumulated at the
 * vertex itself. Single precision fits the record in one cache line.
 */
struct alignas(64) QuadricRecord
{
  float A00, A01, A02, A11, A12, A22;
  float G0, G1, G2;
  float C;
  float FaceWeight; // total area behind the face planes
  uint32_t Slot;    // index into the constraint records, Invalid when none
  double InverseRootWeight; // 1 / sqrt(FaceWeight), see SetFaceWeight
};
static_assert(sizeof(QuadricRecord) == 64, "one cache line per quadric");

/// Adds the symmetric matrix of m (any record with A00 ... A22) to r's, in
/// single precision: the one place where a record's matrix grows.
template <typename M>
inline void AddMatrix(QuadricRecord& r, const M& m)
{
  r.A00 = static_cast<float>(r.A00 + m.A00);
  r.A01 = static_cast<float>(r.A01 + m.A01);
  r.A02 = static_cast<float>(r.A02 + m.A02);
  r.A11 = static_cast<float>(r.A11 + m.A11);
  r.A12 = static_cast<float>(r.A12 + m.A12);
  r.A22 = static_cast<float>(r.A22 + m.A22);
}

/// Sets the face weight of r and its inverse square root, which every cost
/// evaluation reads (CollapseEngine::Cost): computed once per change, not per
/// evaluation.
inline void SetFaceWeight(QuadricRecord& r, float weight)
{
  r.FaceWeight = weight;
  r.InverseRootWeight = 1.0 / std::sqrt(double(std::max(weight, std::numeric_limits<float>::min())));
}
}
}

#endif
