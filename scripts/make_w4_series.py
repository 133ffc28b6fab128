#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Write the W4 data (changing data, issue 20): a time series of an
isosurface of moving blobs, as one polydata per step and as a multiblock of
BLOCKS leaves per step, and one volume for the contour edit.

The field on [-1, 1]^3 is a sum of Gaussian blobs whose centres follow
Lissajous paths (one period over the series, so that looping the animation
is seamless) plus a small travelling ripple that gives the surface detail;
vtkFlyingEdges3D extracts the isosurface (with normals) on a RESOLUTION^3
grid, so the triangle count grows with RESOLUTION^2 (about 1M triangles at
the default 432). The multiblock variant splits each step's surface into
BLOCKS leaves of equal triangle counts by recursive bisection of the
triangles' centroids (each leaf a closed piece of the same surface, with its
own copy of the shared points).

Output (DIR, default ./w4-data; never commit it):
    surface.pvd + surface/surface_NNN.vtp     one polydata per step
    blocks.pvd  + blocks/blocks_NNN.vtm (+ blocks/blocks_NNN/*.vtp)
    volume.vti                                the field of step 0 (contour edit)
    series.json                               settings, triangles per step, edit values

Files are binary XML, not appended (Debian 12's libexpat deb12u2 and later
break VTK 9.2's reading of appended XML), uncompressed (reading time is
measured apart, and compressed reading is slower). The time value of step k
is k.

    /usr/bin/python3 scripts/make_w4_series.py [--output DIR] [--steps 20] [--resolution 432]
    /usr/bin/python3 scripts/make_w4_series.py --output /tmp/w4-tiny --tiny   # seconds
"""

import argparse
import json
import math
import os
import sys
import time

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import (vtkCellArray, vtkImageData, vtkMultiBlockDataSet,
                                           vtkPolyData)
from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D
from vtkmodules.vtkIOXML import (vtkXMLImageDataWriter, vtkXMLMultiBlockDataWriter,
                                 vtkXMLPolyDataWriter)

# Increment when the generated data changes for the same options, so that
# ensure_series() regenerates an old folder.
FORMAT_VERSION = 1
FIELD_NAME = "blobs"
ISOVALUE = 0.5
# The contour edit: 10 changes away from ISOVALUE, then the same values back.
EDIT_STEP = 0.02
EDIT_CHANGES = 10
# A blob adds nothing beyond CUTOFF widths from its centre (exp(-CUTOFF^2 / 2) = 3e-4 of its peak).
CUTOFF = 4.0


def parse_arguments(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output", default="w4-data", help="folder (default: %(default)s)")
    parser.add_argument("--steps", type=int, default=20, help="time steps (default: %(default)s)")
    parser.add_argument("--resolution", type=int, default=432,
                        help="grid points per axis; triangles grow as its square "
                             "(default: %(default)s, about 1M triangles)")
    parser.add_argument("--blobs", type=int, default=16, help="moving blobs (default: %(default)s)")
    parser.add_argument("--blocks", type=int, default=200,
                        help="leaves per step of the multiblock variant (default: %(default)s)")
    parser.add_argument("--seed", type=int, default=4004, help="blob placement seed")
    parser.add_argument("--tiny", action="store_true",
                        help="a small series for smoke tests: 4 steps, resolution 40, 8 blocks "
                             "(explicit --steps/--resolution/--blocks win)")
    parser.add_argument("--force", action="store_true", help="write even if the folder is current")
    args = parser.parse_args(argv)
    apply_tiny(args, argv if argv is not None else sys.argv[1:])
    if args.steps < 2 or args.resolution < 8 or args.blocks < 1 or args.blobs < 1:
        parser.error("--steps >= 2, --resolution >= 8, --blocks >= 1 and --blobs >= 1 are required")
    return args


def apply_tiny(args, argv):
    if not args.tiny:
        return
    given = " ".join(argv)
    if "--steps" not in given:
        args.steps = 4
    if "--resolution" not in given:
        args.resolution = 40
    if "--blocks" not in given:
        args.blocks = 8


# ---------------------------------------------------------------------------
# The field and its isosurface

def blob_paths(count, seed):
    """Per blob: amplitude, width, and Lissajous frequencies and phases."""
    rng = np.random.default_rng(seed)
    return {"amplitude": rng.uniform(0.8, 1.2, count),
            "sigma": rng.uniform(0.11, 0.2, count),
            "frequency": rng.integers(1, 3, (count, 3)),
            "phase": rng.uniform(0, 2 * math.pi, (count, 3)),
            "reach": rng.uniform(0.4, 0.7, (count, 3))}


def field(resolution, phase, blobs):
    """The blob field on the grid at the animation phase (radians), as a
    float32 array indexed [z, y, x] (VTK's point order when raveled)."""
    axis = np.linspace(-1.0, 1.0, resolution, dtype=np.float32)
    values = np.zeros((resolution,) * 3, dtype=np.float32)
    for b in range(len(blobs["sigma"])):
        centre = blobs["reach"][b] * np.sin(blobs["frequency"][b] * phase + blobs["phase"][b])
        sigma = blobs["sigma"][b]
        # Only within CUTOFF widths: the rest adds nothing visible.
        box = [np.flatnonzero(np.abs(axis - c) < CUTOFF * sigma) for c in centre]  # x, y, z
        if any(len(k) == 0 for k in box):
            continue
        scale = np.float32(-0.5 / sigma ** 2)
        g = [np.exp(scale * (axis[k] - np.float32(c)) ** 2) for k, c in zip(box, centre)]
        values[box[2][0]:box[2][-1] + 1, box[1][0]:box[1][-1] + 1, box[0][0]:box[0][-1] + 1] += (
            np.float32(blobs["amplitude"][b])
            * (g[2][:, None, None] * g[1][None, :, None] * g[0][None, None, :]))
    # A travelling ripple: surface detail that moves with the blobs.
    ripple = (np.sin(9.0 * axis + phase)[None, None, :] * np.sin(7.0 * axis - phase)[None, :, None]
              * np.cos(8.0 * axis + 2 * phase)[:, None, None])
    values += np.float32(0.04) * ripple.astype(np.float32)
    return values


def image(values):
    resolution = values.shape[0]
    data = vtkImageData()
    data.SetDimensions(resolution, resolution, resolution)
    data.SetOrigin(-1.0, -1.0, -1.0)
    spacing = 2.0 / (resolution - 1)
    data.SetSpacing(spacing, spacing, spacing)
    array = numpy_to_vtk(values.ravel(), deep=True)
    array.SetName(FIELD_NAME)
    data.GetPointData().SetScalars(array)
    return data


def isosurface(data, value=ISOVALUE):
    contour = vtkFlyingEdges3D()
    contour.SetInputData(data)
    contour.SetValue(0, value)
    contour.ComputeNormalsOn()
    contour.ComputeScalarsOff()
    contour.ComputeGradientsOff()
    contour.Update()
    surface = vtkPolyData()
    surface.ShallowCopy(contour.GetOutput())
    return surface


# ---------------------------------------------------------------------------
# The multiblock split

def triangles_of(surface):
    polys = surface.GetPolys()
    offsets = vtk_to_numpy(polys.GetOffsetsArray())
    connectivity = vtk_to_numpy(polys.GetConnectivityArray())
    if len(offsets) > 1 and not np.all(np.diff(offsets) == 3):
        raise ValueError("the isosurface holds cells other than triangles")
    return connectivity.reshape(-1, 3)


def bisect(centroids, cells, parts, out):
    """Split cells (indices into centroids) into parts groups of nearly
    equal size: halve the count along the widest axis, recursively."""
    if parts == 1 or len(cells) <= 1:
        out.append(cells)
        return
    points = centroids[cells]
    axis = int(np.argmax(points.max(axis=0) - points.min(axis=0)))
    left_parts = parts // 2
    cut = len(cells) * left_parts // parts
    order = np.argpartition(points[:, axis], cut) if 0 < cut < len(cells) else np.arange(len(cells))
    bisect(centroids, cells[order[:cut]], left_parts, out)
    bisect(centroids, cells[order[cut:]], parts - left_parts, out)


def piece(points, normals, triangles):
    """A polydata of the triangles (rows of point ids into points), with
    only the points they use."""
    used, inverse = np.unique(triangles.ravel(), return_inverse=True)
    leaf = vtkPolyData()
    leaf_points = vtkPoints()
    leaf_points.SetData(numpy_to_vtk(np.ascontiguousarray(points[used]), deep=True))
    leaf.SetPoints(leaf_points)
    if normals is not None:
        array = numpy_to_vtk(np.ascontiguousarray(normals[used]), deep=True)
        array.SetName("Normals")
        leaf.GetPointData().SetNormals(array)
    cells = vtkCellArray()
    offsets = np.arange(0, 3 * len(triangles) + 1, 3, dtype=np.int64)
    cells.SetData(numpy_to_vtkIdTypeArray(offsets, deep=True),
                  numpy_to_vtkIdTypeArray(inverse.astype(np.int64), deep=True))
    leaf.SetPolys(cells)
    return leaf


def split(surface, blocks):
    """The surface as a vtkMultiBlockDataSet of `blocks` leaves."""
    points = vtk_to_numpy(surface.GetPoints().GetData())
    normals_array = surface.GetPointData().GetNormals()
    normals = vtk_to_numpy(normals_array) if normals_array is not None else None
    triangles = triangles_of(surface)
    centroids = points[triangles].mean(axis=1)
    groups = []
    bisect(centroids, np.arange(len(triangles)), blocks, groups)
    output = vtkMultiBlockDataSet()
    output.SetNumberOfBlocks(len(groups))
    for index, cells in enumerate(groups):
        output.SetBlock(index, piece(points, normals, triangles[np.sort(cells)]))
    return output


# ---------------------------------------------------------------------------
# Writing

def configure(writer, path):
    writer.SetFileName(path)
    writer.SetDataModeToBinary()  # not appended: see the module comment
    writer.SetCompressorTypeToNone()
    if not writer.Write():
        raise RuntimeError("could not write " + path)


def write_polydata(data, path):
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(data)
    configure(writer, path)


def write_collection(path, files):
    """A ParaView data collection (.pvd): time value k for files[k]."""
    lines = ['<?xml version="1.0"?>',
             '<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">',
             "  <Collection>"]
    lines += ['    <DataSet timestep="%d" group="" part="0" file="%s"/>' % (k, f)
              for k, f in enumerate(files)]
    lines += ["  </Collection>", "</VTKFile>", ""]
    with open(path, "w") as stream:
        stream.write("\n".join(lines))


def settings_of(args):
    return {"format_version": FORMAT_VERSION, "steps": args.steps,
            "resolution": args.resolution, "blobs": args.blobs, "blocks": args.blocks,
            "seed": args.seed}


def edit_values():
    """The contour edit: ISOVALUE, 10 changes away, then the same 10 back."""
    away = [round(ISOVALUE + k * EDIT_STEP, 6) for k in range(1, EDIT_CHANGES + 1)]
    return {"start": ISOVALUE, "changes": away + away[-2::-1] + [ISOVALUE],
            "back_from_change": EDIT_CHANGES}


def is_current(folder, settings):
    try:
        with open(os.path.join(folder, "series.json")) as stream:
            return json.load(stream)["settings"] == settings
    except (OSError, ValueError, KeyError):
        return False


def write_series(args):
    folder = args.output
    for sub in ("surface", "blocks"):
        os.makedirs(os.path.join(folder, sub), exist_ok=True)
    blobs = blob_paths(args.blobs, args.seed)
    surfaces, multiblocks, triangles = [], [], []
    start = time.perf_counter()
    for step in range(args.steps):
        values = field(args.resolution, 2 * math.pi * step / args.steps, blobs)
        data = image(values)
        if step == 0:
            writer = vtkXMLImageDataWriter()
            writer.SetInputData(data)
            configure(writer, os.path.join(folder, "volume.vti"))
        surface = isosurface(data)
        triangles.append(surface.GetNumberOfCells())
        name = "surface/surface_%03d.vtp" % step
        write_polydata(surface, os.path.join(folder, name))
        surfaces.append(name)
        multiblock = split(surface, args.blocks)
        name = "blocks/blocks_%03d.vtm" % step
        writer = vtkXMLMultiBlockDataWriter()
        writer.SetInputData(multiblock)
        configure(writer, os.path.join(folder, name))
        multiblocks.append(name)
        print("step %d: %s triangles, %d blocks (%.1f s)" % (
            step, format(triangles[-1], ","), multiblock.GetNumberOfBlocks(),
            time.perf_counter() - start), flush=True)
    write_collection(os.path.join(folder, "surface.pvd"), surfaces)
    write_collection(os.path.join(folder, "blocks.pvd"), multiblocks)
    manifest = {"generator": "scripts/make_w4_series.py", "settings": settings_of(args),
                "field": FIELD_NAME, "isovalue": ISOVALUE, "edit": edit_values(),
                "triangles": triangles, "surface": "surface.pvd", "blocks": "blocks.pvd",
                "volume": "volume.vti", "bounds": [-1, 1, -1, 1, -1, 1]}
    with open(os.path.join(folder, "series.json"), "w") as stream:
        json.dump(manifest, stream, indent=1)
    return manifest


def ensure_series(args):
    """The manifest of args.output, written first unless it is current."""
    if not args.force and is_current(args.output, settings_of(args)):
        with open(os.path.join(args.output, "series.json")) as stream:
            return json.load(stream)
    return write_series(args)


def main():
    args = parse_arguments()
    manifest = ensure_series(args)
    t = manifest["triangles"]
    print("%s: %d steps, %s-%s triangles per step, %d blocks" % (
        args.output, len(t), format(min(t), ","), format(max(t), ","),
        manifest["settings"]["blocks"]))


if __name__ == "__main__":
    main()
