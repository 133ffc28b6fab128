# SPDX-License-Identifier: BSD-3-Clause
"""Parallel leaf builds (issue 20, item 2): vtkMultiresolutionHierarchyBuilder
on 1 thread against N threads, alternating (1, N, 1, N, ...), each run with an
empty cache of its own, on LEAVES moved copies of one shared mesh (the moved
copies share one cell array, as vtkTransformFilter's outputs do).

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \\
        scripts/parallel_build_benchmark.py [--mesh igea.ply] [--leaves 8] \\
        [--threads 2] [--pairs 5] [--hierarchy tom|mergetree] [--output DIR]

Prints each pair, the medians and the speed-up (median of the pair ratios),
and writes parallel_build.json. Run it on a quiet machine.
"""

import argparse
import json
import os
import statistics
import time

from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersGeneral import vtkTransformFilter
from vtkmodules.vtkIOGeometry import vtkOBJReader
from vtkmodules.vtkIOPLY import vtkPLYReader

import timecritical  # noqa: F401
from ply_strips import read_ply_tristrips
from timecritical.TimeCriticalFilters import (vtkHierarchyBuildCache,
                                              vtkMultiresolutionHierarchyBuilder)

HERE = os.path.dirname(os.path.abspath(__file__))
SHARED = os.path.normpath(os.path.join(HERE, "..", "..", "shared", "data"))


def read_mesh(path):
    reader = vtkPLYReader() if path.endswith(".ply") else vtkOBJReader()
    reader.SetFileName(path)
    reader.Update()
    mesh = reader.GetOutput()
    if path.endswith(".ply") and mesh.GetNumberOfPolys() == 0:
        mesh = read_ply_tristrips(path)  # vtkPLYReader drops triangle strips
    if mesh.GetNumberOfPolys() == 0:
        raise RuntimeError("%s holds no polygons" % path)
    return mesh


def moved_copies(mesh, count):
    blocks = vtkMultiBlockDataSet()
    blocks.SetNumberOfBlocks(count)
    size = max(mesh.GetBounds()[1] - mesh.GetBounds()[0], 1e-6)
    for i in range(count):
        move = vtkTransform()
        move.Translate(1.5 * size * i, 0.0, 0.0)
        copy = vtkTransformFilter()
        copy.SetTransform(move)
        copy.SetInputData(mesh)
        copy.Update()
        blocks.SetBlock(i, copy.GetOutput())
    return blocks


def build_seconds(blocks, threads, hierarchy):
    builder = vtkMultiresolutionHierarchyBuilder()
    builder.SetCache(vtkHierarchyBuildCache())  # empty: every leaf is built
    builder.SetHierarchy(hierarchy)
    builder.SetNumberOfThreads(threads)
    builder.SetInputData(blocks)
    start = time.perf_counter()
    builder.Update()
    seconds = time.perf_counter() - start
    if builder.GetNumberOfBuiltLeaves() != blocks.GetNumberOfBlocks():
        raise RuntimeError("built %d leaves of %d" % (builder.GetNumberOfBuiltLeaves(),
                                                       blocks.GetNumberOfBlocks()))
    return seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--mesh", default="igea.ply")
    parser.add_argument("--leaves", type=int, default=8)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--pairs", type=int, default=5)
    parser.add_argument("--hierarchy", choices=("tom", "mergetree"), default="tom")
    parser.add_argument("--output", default=".")
    args = parser.parse_args()
    path = args.mesh if os.path.isfile(args.mesh) else os.path.join(SHARED, args.mesh)
    mesh = read_mesh(path)
    blocks = moved_copies(mesh, args.leaves)
    triangles = args.leaves * mesh.GetNumberOfCells()
    hierarchy = 0 if args.hierarchy == "tom" else 1
    pairs = []
    for pair in range(args.pairs):
        serial = build_seconds(blocks, 1, hierarchy)
        parallel = build_seconds(blocks, args.threads, hierarchy)
        pairs.append({"serial_s": serial, "parallel_s": parallel, "ratio": serial / parallel})
        print("pair %d: 1 thread %.3f s, %d threads %.3f s, speed-up %.2f"
              % (pair + 1, serial, args.threads, parallel, serial / parallel), flush=True)
    result = {
        "mesh": os.path.basename(path), "leaves": args.leaves, "cells": triangles,
        "hierarchy": args.hierarchy, "threads": args.threads, "cores": os.cpu_count(),
        "pairs": pairs,
        "median_serial_s": statistics.median(p["serial_s"] for p in pairs),
        "median_parallel_s": statistics.median(p["parallel_s"] for p in pairs),
        "median_speedup": statistics.median(p["ratio"] for p in pairs),
    }
    result["serial_mcells_per_s"] = triangles / result["median_serial_s"] / 1e6
    result["parallel_mcells_per_s"] = triangles / result["median_parallel_s"] / 1e6
    print("%s x %d (%d cells, %s): median 1 thread %.3f s (%.2f Mcells/s), %d threads %.3f s "
          "(%.2f Mcells/s); speed-up (median of pair ratios) %.2f on %d cores"
          % (result["mesh"], args.leaves, triangles, args.hierarchy, result["median_serial_s"],
             result["serial_mcells_per_s"], args.threads, result["median_parallel_s"],
             result["parallel_mcells_per_s"], result["median_speedup"], os.cpu_count()))
    os.makedirs(args.output, exist_ok=True)
    with open(os.path.join(args.output, "parallel_build.json"), "w") as out:
        json.dump(result, out, indent=2)


if __name__ == "__main__":
    main()
