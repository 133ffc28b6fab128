// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_ConstraintRecord_h
#define timecritical_ConstraintRecord_h

/*
 * Internal to TimeCritical::MeshCore: the constraint planes of a vertex, kept
 * apart from its QuadricRecord.
 */

#include "Quadric.h"

namespace timecritical
{
namespace collapse
{
/// The constraint planes alone, kept apart (few vertices have any) to report
/// a geometric error that their weights do not distort.
struct ConstraintRecord
{
  Quadric Q;
  double Weight;
};
}
}

#endif
