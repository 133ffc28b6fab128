# SPDX-License-Identifier: BSD-3-Clause
"""Binary PLY files with a `tristrips` element (igea.ply), which vtkPLYReader
reads as points without faces. Shared by the scripts that read such meshes."""

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData


def read_ply_tristrips(path):
    """Binary PLY with a `tristrips` element (which vtkPLYReader cannot decode)."""
    types = {"char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "i2",
             "int16": "i2", "ushort": "u2", "uint16": "u2", "int": "i4", "int32": "i4",
             "uint": "u4", "uint32": "u4", "float": "f4", "float32": "f4", "double": "f8",
             "float64": "f8"}
    with open(path, "rb") as stream:
        header = []
        while True:
            line = stream.readline()
            if not line:
                raise ValueError("no end_header")
            line = line.decode("ascii", "replace").strip()
            header.append(line)
            if line == "end_header":
                break
        body = stream.read()
    fmt = next((l.split()[1] for l in header if l.startswith("format")), "")
    if fmt not in ("binary_little_endian", "binary_big_endian"):
        raise ValueError("only binary PLY strips are decoded here (format %s)" % fmt)
    endian = "<" if fmt == "binary_little_endian" else ">"
    elements = []
    for line in header:
        words = line.split()
        if words[0] == "element":
            elements.append([words[1], int(words[2]), []])
        elif words[0] == "property":
            elements[-1][2].append(words[1:])
    offset = 0
    points = strips = None
    for name, count, properties in elements:
        if name == "vertex":
            if any(p[0] == "list" for p in properties):
                raise ValueError("list properties on vertices are not supported")
            dtype = np.dtype([(p[1], endian + types[p[0]]) for p in properties])
            vertices = np.frombuffer(body, dtype=dtype, count=count, offset=offset)
            offset += dtype.itemsize * count
            points = np.stack([vertices["x"], vertices["y"], vertices["z"]], axis=1).astype(
                np.float64)
        elif name == "tristrips" and len(properties) == 1 and properties[0][0] == "list":
            count_type = np.dtype(endian + types[properties[0][1]])
            index_type = np.dtype(endian + types[properties[0][2]])
            parts = []
            for _ in range(count):
                length = int(np.frombuffer(body, dtype=count_type, count=1, offset=offset)[0])
                offset += count_type.itemsize
                parts.append(np.frombuffer(body, dtype=index_type, count=length, offset=offset))
                offset += index_type.itemsize * length
            strips = np.concatenate(parts).astype(np.int64)
        else:
            raise ValueError("unsupported PLY element %s" % name)
    if points is None or strips is None:
        raise ValueError("no vertex or tristrips element")
    # Strips are separated by -1; triangle i of a strip alternates its winding.
    triangles = []
    breaks = np.flatnonzero(strips < 0)
    start = 0
    for stop in list(breaks) + [len(strips)]:
        strip = strips[start:stop]
        start = stop + 1
        if len(strip) < 3:
            continue
        tri = np.stack([strip[:-2], strip[1:-1], strip[2:]], axis=1)
        odd = np.arange(len(tri)) % 2 == 1
        tri[odd] = tri[odd][:, [1, 0, 2]]
        triangles.append(tri)
    triangles = np.concatenate(triangles)
    keep = ((triangles[:, 0] != triangles[:, 1]) & (triangles[:, 1] != triangles[:, 2])
            & (triangles[:, 0] != triangles[:, 2]))
    return polydata_from_arrays(points, triangles[keep])


def polydata_from_arrays(points, triangles):
    data = vtkPolyData()
    pts = vtkPoints()
    pts.SetData(numpy_to_vtk(np.ascontiguousarray(points), deep=True))
    data.SetPoints(pts)
    cells = vtkCellArray()
    offsets = np.arange(0, 3 * len(triangles) + 1, 3, dtype=np.int64)
    cells.SetData(numpy_to_vtk(offsets, deep=True),
                  numpy_to_vtk(np.ascontiguousarray(triangles.ravel(), dtype=np.int64), deep=True))
    data.SetPolys(cells)
    return data
