// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_CollapseQuadric_h
#define timecritical_CollapseQuadric_h

/*
 * Internal to TimeCritical::MeshCore: the quadrics of the collapse engine:
 * the double-precision quadric of the constraint planes (Quadric), the
 * per-vertex record in single precision around its vertex (QuadricRecord),
 * its double-precision working copy (LocalQuadric), the planes added to
 * records (PlaneThroughOrigin) and the constraint planes kept apart
 * (ConstraintRecord).
 */

#include "ConstraintRecord.h"
#include "LocalQuadric.h"
#include "PlaneThroughOrigin.h"
#include "Quadric.h"
#include "QuadricRecord.h"

#endif
