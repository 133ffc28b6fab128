// SPDX-License-Identifier: BSD-3-Clause
/**
 * A 64-bit hash of everything a hierarchy build depends on: a polydata
 * leaf's points, cells, point data and cell data (type, shape, name and
 * values of every array). Two leaves with equal hashes are taken to have the
 * same content, whether their arrays are the same objects or copies, so a
 * build can be reused (ParaView's geometry filter makes new arrays at every
 * execution). A hash rather than the arrays themselves: a pipeline may refill
 * the same array objects, so holding them would not keep the old content.
 * Several GB/s; safe to call from any thread on a leaf no thread modifies.
 */
#ifndef LeafContentHash_h
#define LeafContentHash_h

#include <cstdint>

class vtkPolyData;

namespace timecritical
{
uint64_t HashLeafContent(vtkPolyData* leaf);
}

#endif
