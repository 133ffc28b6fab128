#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The wrapped TimeCritical classes in plain VTK pipelines.

source -> vtkTOMBuilder -> vtkExtractTOMResolution / vtkTOMPolyDataMapper,
with every property of a TOM checked against an independent numpy
re-implementation of the prefix traversal, plus bad and corrupted input.

Environment: PYTHONPATH must reach the `timecritical` package (the build
tree's lib/python3/dist-packages); TIMECRITICAL_SHARED_DATA_DIR names the
folder with cow.obj (tests on it are skipped when it is absent);
TIMECRITICAL_TEST_OUTPUT_DIR receives scratch files (a temporary folder
otherwise). Rendering needs an X display (run under xvfb-run -a).
"""

import math
import os
import sys
import unittest

import numpy as np

try:
    from timecritical import (vtkExtractTOMResolution, vtkTOMBuilder,
                              vtkTOMFieldData, vtkTOMPolyDataMapper)
except ImportError as error:  # pragma: no cover - environment problem
    sys.stderr.write(
        "Cannot import the timecritical package (%s).\nSet PYTHONPATH to the "
        "build tree's lib/python3/dist-packages folder.\n" % error)
    raise

from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import (VTK_STRING, VTK_UNSIGNED_INT, vtkCommand,
                                      vtkDoubleArray, vtkIntArray, vtkObject,
                                      vtkPoints)
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOGeometry import vtkOBJReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter

from timecritical_testing import COW, noisy_cube, output_dir  # noqa: E402




# ---------------------------------------------------------------------------
# Observers: collect errors and warnings instead of printing them.
class Messages:
    """Errors and warnings of a VTK object (and its executive, for algorithms)."""

    def __init__(self, *objects):
        self.errors = []
        self.warnings = []

        @calldata_type(VTK_STRING)
        def on_error(_obj, _event, text):
            self.errors.append(text or "")

        @calldata_type(VTK_STRING)
        def on_warning(_obj, _event, text):
            self.warnings.append(text or "")

        self._callbacks = (on_error, on_warning)
        for obj in objects:
            obj.AddObserver(vtkCommand.ErrorEvent, on_error)
            obj.AddObserver(vtkCommand.WarningEvent, on_warning)
            if hasattr(obj, "GetExecutive"):
                obj.GetExecutive().AddObserver(vtkCommand.ErrorEvent, on_error)
                obj.GetExecutive().AddObserver(vtkCommand.WarningEvent, on_warning)

    def text(self):
        return "\n".join(self.errors + self.warnings)


# ---------------------------------------------------------------------------
# Inputs.
def sphere(resolution=200):
    """UV sphere with point normals, a cell id array and a field array."""
    source = vtkSphereSource()
    source.SetThetaResolution(resolution)
    source.SetPhiResolution(resolution)
    source.SetRadius(2.0)
    source.Update()
    data = vtkPolyData()
    data.DeepCopy(source.GetOutput())
    return decorate(data)


def cow():
    reader = vtkOBJReader()
    reader.SetFileName(COW)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(reader.GetOutputPort())
    normals.SplittingOff()  # no new points: one normal per input point
    normals.ConsistencyOff()  # keep the input's triangles as they are
    normals.ComputeCellNormalsOff()
    normals.Update()
    data = vtkPolyData()
    data.DeepCopy(normals.GetOutput())
    return decorate(data)


def decorate(data):
    ids = vtkIntArray()
    ids.SetName("InputCellId")
    ids.SetNumberOfTuples(data.GetNumberOfCells())
    vtk_to_numpy(ids)[:] = np.arange(data.GetNumberOfCells(), dtype=np.int32)
    data.GetCellData().AddArray(ids)
    # Numeric: VTK 9.2's XML writer cannot round-trip a vtkStringArray in
    # field data in its default (appended, base64) mode.
    note = vtkDoubleArray()
    note.SetName("Provenance")
    note.InsertNextValue(42.5)
    data.GetFieldData().AddArray(note)
    return data


def build(data, **options):
    builder = vtkTOMBuilder()
    for key, value in options.items():
        getattr(builder, "Set" + key)(value)
    builder.SetInputData(data)
    messages = Messages(builder)
    builder.Update()
    return builder, messages


def extract(tom, **selection):
    extractor = vtkExtractTOMResolution()
    extractor.SetInputData(tom)
    for key, value in selection.items():
        getattr(extractor, "Set" + key)(value)
    messages = Messages(extractor)
    extractor.Update()
    return extractor, messages


# ---------------------------------------------------------------------------
# numpy views and an independent traversal.
def points_of(data):
    return vtk_to_numpy(data.GetPoints().GetData()).astype(np.float64)


def triangles_of(data):
    polys = data.GetPolys()
    offsets = vtk_to_numpy(polys.GetOffsetsArray())
    connectivity = vtk_to_numpy(polys.GetConnectivityArray()).astype(np.int64)
    assert np.all(np.diff(offsets) == 3), "non-triangle cells"
    return connectivity.reshape(-1, 3)


def tom_arrays(tom):
    substitution = vtk_to_numpy(tom.GetPointData().GetArray("TOMSubstitution")).astype(np.int64)
    counts = vtk_to_numpy(tom.GetFieldData().GetArray("TOMCounts")).astype(np.int64)
    curve = vtk_to_numpy(tom.GetFieldData().GetArray("TOMErrorCurve")).astype(np.float64)
    return substitution, counts, curve.reshape(-1, 2)


def active_map(substitution, n):
    """Vertex -> the active vertex it maps to when vertices [0, n) are active."""
    mapping = np.arange(len(substitution))
    mapping[n:] = substitution[n:]
    while True:  # pointer jumping: chains halve every round
        jumped = mapping[mapping]
        if np.array_equal(jumped, mapping):
            return mapping
        mapping = jumped


def alive_triangles(substitution, triangles, n):
    """Triangles of the mesh with n active vertices, checking the prefix order."""
    mapped = active_map(substitution, n)[triangles]
    alive = ((mapped[:, 0] != mapped[:, 1]) & (mapped[:, 1] != mapped[:, 2])
             & (mapped[:, 0] != mapped[:, 2]))
    count = int(alive.sum())
    assert alive[:count].all() and not alive[count:].any(), \
        "alive triangles with %d vertices are not a prefix" % n
    return mapped[:count]


def canonical_triangles(triangles):
    """Rotate each triangle so its smallest id comes first (winding kept), sort rows."""
    rotation = np.argmin(triangles, axis=1)
    rows = np.arange(len(triangles))[:, None]
    rotated = triangles[rows, (rotation[:, None] + np.arange(3)) % 3]
    return rotated[np.lexsort(rotated.T[::-1])]


def position_index(points):
    """Map from exact position to point id (ids of repeated positions are dropped)."""
    index = {}
    repeated = set()
    for i, p in enumerate(map(tuple, points)):
        if p in index:
            repeated.add(p)
        index[p] = i
    for p in repeated:
        del index[p]
    return index


def appended_xml_readable(folder):
    """Whether this VTK reads back a plain .vtp in the writer's default (appended) mode.

    Debian 12's VTK 9.2 with its patched expat fails to parse appended XML
    files of more than a few hundred bytes ("junk after document element"),
    with or without TOM arrays; inline binary and ASCII files read fine.
    """
    source = vtkSphereSource()
    source.SetThetaResolution(64)
    source.SetPhiResolution(64)
    path = os.path.join(folder, "appended-probe.vtp")
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(source.GetOutputPort())
    writer.Write()
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    Messages(reader)  # keep the expected parse errors quiet
    shown = vtkObject.GetGlobalWarningDisplay()
    vtkObject.GlobalWarningDisplayOff()  # and those of the reader's internal parser
    try:
        reader.Update()
    finally:
        vtkObject.SetGlobalWarningDisplay(shown)
    return reader.GetOutput().GetNumberOfPoints() == 64 * 62 + 2


# ---------------------------------------------------------------------------
class TOMChecks:
    """Checks of one TOM; subclasses provide make_input()."""

    @classmethod
    def setUpClass(cls):
        cls.input = cls.make_input()
        cls.builder, cls.build_messages = build(cls.input)
        cls.tom = cls.builder.GetOutput()
        assert not cls.build_messages.errors, cls.build_messages.text()
        cls.substitution, cls.counts, cls.curve = tom_arrays(cls.tom)
        cls.points = points_of(cls.tom)
        cls.triangles = triangles_of(cls.tom)
        print("\n%s: %d points, %d triangles in; TOM %s (vertices, triangles, base vertices, "
              "base triangles), %d error-curve samples, built in %.3f s"
              % (cls.__name__, cls.input.GetNumberOfPoints(), cls.input.GetNumberOfCells(),
                 cls.counts.tolist(), len(cls.curve), cls.builder.GetBuildTime()))

    def test_counts(self):
        n, t, base_n, base_t = self.counts.tolist()
        self.assertEqual(self.tom.GetFieldData().GetArray("TOMCounts").GetNumberOfTuples(), 4)
        self.assertEqual(n, self.tom.GetNumberOfPoints())
        self.assertEqual(t, self.tom.GetNumberOfPolys())
        self.assertEqual(self.tom.GetNumberOfCells(), t)  # triangles only
        self.assertEqual(n, self.input.GetNumberOfPoints() - self.builder.GetNumberOfMergedPoints())
        self.assertEqual(t, self.input.GetNumberOfCells() - self.builder.GetNumberOfDroppedCells())
        self.assertGreaterEqual(base_n, 3)
        self.assertLess(base_n, n // 20, "the base mesh should be far coarser")
        self.assertGreaterEqual(base_t, 1)
        self.assertLess(base_t, t // 20)
        # Base triangles are those alive at the base vertex count.
        self.assertEqual(len(alive_triangles(self.substitution, self.triangles, base_n)), base_t)
        # vtkTOMFieldData reads the same counts.
        reader = vtkTOMFieldData()
        self.assertTrue(reader.Read(self.tom), reader.GetErrorMessage())
        self.assertEqual(reader.GetErrorMessage(), "")
        self.assertEqual([reader.GetNumberOfVertices(), reader.GetNumberOfTriangles(),
                          reader.GetBaseVertexCount(), reader.GetBaseTriangleCount()],
                         [n, t, base_n, base_t])
        self.assertTrue(vtkTOMFieldData.HasTOMArrays(self.tom))
        self.assertFalse(vtkTOMFieldData.HasTOMArrays(self.input))

    def test_substitution(self):
        array = self.tom.GetPointData().GetArray("TOMSubstitution")
        self.assertEqual(array.GetDataType(), VTK_UNSIGNED_INT)
        self.assertEqual(array.GetNumberOfComponents(), 1)
        self.assertEqual(array.GetNumberOfTuples(), self.tom.GetNumberOfPoints())
        base_n = int(self.counts[2])
        ids = np.arange(len(self.substitution))
        np.testing.assert_array_equal(self.substitution[:base_n], ids[:base_n])
        self.assertTrue(np.all(self.substitution[base_n:] < ids[base_n:]))

    def test_triangles_are_the_input_triangles(self):
        # Same triangles, same winding, only reordered (with their cell data).
        in_points = points_of(self.input)
        index = position_index(in_points)
        to_input = np.array([index.get(tuple(p), -1) for p in self.points])
        self.assertTrue(np.all(to_input >= 0), "TOM points missing from the input")
        self.assertEqual(len(np.unique(to_input)), len(to_input))
        in_triangles = triangles_of(self.input)
        mapped = to_input[self.triangles]
        np.testing.assert_array_equal(canonical_triangles(mapped), canonical_triangles(in_triangles))
        # Cell data: each output triangle carries the id of the input triangle it is.
        cell_ids = vtk_to_numpy(self.tom.GetCellData().GetArray("InputCellId"))
        np.testing.assert_array_equal(mapped, in_triangles[cell_ids])

    def test_point_data_travels(self):
        in_points = points_of(self.input)
        index = position_index(in_points)
        to_input = np.array([index.get(tuple(p), -1) for p in self.points])
        self.assertTrue(np.all(to_input >= 0))
        normals = vtk_to_numpy(self.tom.GetPointData().GetArray("Normals"))
        in_normals = vtk_to_numpy(self.input.GetPointData().GetArray("Normals"))
        self.assertEqual(normals.shape, (self.tom.GetNumberOfPoints(), 3))
        np.testing.assert_array_equal(normals, in_normals[to_input])

    def test_field_data_travels(self):
        note = self.tom.GetFieldData().GetAbstractArray("Provenance")
        self.assertIsNotNone(note)
        self.assertEqual(note.GetValue(0), 42.5)

    def test_error_curve(self):
        t = int(self.counts[1])
        self.assertEqual(self.tom.GetFieldData().GetArray("TOMErrorCurve").GetNumberOfComponents(), 2)
        self.assertGreaterEqual(len(self.curve), 2)
        triangles, errors = self.curve[:, 0], self.curve[:, 1]
        self.assertTrue(np.all(np.diff(triangles) > 0), triangles)
        self.assertTrue(np.all(np.diff(errors) <= 0), errors)
        self.assertEqual(triangles[-1], t)
        self.assertEqual(errors[-1], 0.0)
        self.assertGreater(errors[0], 0.0)
        self.assertGreaterEqual(triangles[0], 0)
        # The error is in world units: below the size of the object.
        diagonal = self.tom.GetLength()
        self.assertLess(errors[0], diagonal)

    def check_extraction(self, extractor, messages):
        """Everything an extraction must satisfy; returns (vertices, triangles)."""
        self.assertEqual(messages.errors, [])
        out = extractor.GetOutput()
        nv, nt = out.GetNumberOfPoints(), out.GetNumberOfPolys()
        self.assertEqual(nv, extractor.GetExtractedVertexCount())
        self.assertEqual(nt, extractor.GetExtractedTriangleCount())
        self.assertEqual(out.GetNumberOfCells(), nt)
        self.assertGreaterEqual(nv, int(self.counts[2]))
        # Points and point data are a prefix of the TOM's.
        np.testing.assert_array_equal(points_of(out), self.points[:nv])
        np.testing.assert_array_equal(
            vtk_to_numpy(out.GetPointData().GetArray("Normals")),
            vtk_to_numpy(self.tom.GetPointData().GetArray("Normals"))[:nv])
        # Triangles: the TOM's prefix with corners moved down their chains.
        expected = alive_triangles(self.substitution, self.triangles, nv)
        np.testing.assert_array_equal(triangles_of(out), expected)
        # Cell data is a prefix too.
        np.testing.assert_array_equal(
            vtk_to_numpy(out.GetCellData().GetArray("InputCellId")),
            vtk_to_numpy(self.tom.GetCellData().GetArray("InputCellId"))[:nt])
        # The output is an ordinary mesh: no TOM arrays, other field data kept.
        self.assertIsNone(out.GetPointData().GetAbstractArray("TOMSubstitution"))
        self.assertIsNone(out.GetFieldData().GetAbstractArray("TOMCounts"))
        self.assertIsNone(out.GetFieldData().GetAbstractArray("TOMErrorCurve"))
        self.assertIsNotNone(out.GetFieldData().GetAbstractArray("Provenance"))
        # Estimated error: the error curve at this triangle count.
        expected_error = np.interp(nt, self.curve[:, 0], self.curve[:, 1])
        self.assertAlmostEqual(extractor.GetExtractedError(), expected_error,
                               delta=1e-6 * max(1.0, expected_error))
        self.assertGreaterEqual(extractor.GetExtractionTime(), 0.0)
        return nv, nt

    def assert_finest_within(self, nv, nt, limit):
        """nv is the finest vertex count whose mesh has at most `limit` triangles."""
        n, _, base_n, base_t = self.counts.tolist()
        self.assertLessEqual(nt, max(limit, base_t))
        if nv < n and nv >= base_n and nt <= limit:
            finer = len(alive_triangles(self.substitution, self.triangles, nv + 1))
            self.assertGreater(finer, limit, "a finer mesh within %d triangles exists" % limit)

    def test_extract_resolutions(self):
        n, t = int(self.counts[0]), int(self.counts[1])
        previous = None
        for resolution in (0.1, 0.5, 1.0):
            extractor, messages = extract(self.tom, Resolution=resolution)
            nv, nt = self.check_extraction(extractor, messages)
            target = int(round(resolution * t))
            self.assert_finest_within(nv, nt, target)
            self.assertGreater(nt, 0.8 * target, "resolution %g: %d triangles" % (resolution, nt))
            if previous:
                self.assertGreaterEqual(nv, previous[0])
                self.assertGreaterEqual(nt, previous[1])
            previous = (nv, nt)
        # Full resolution is the TOM itself.
        self.assertEqual(previous, (n, t))
        self.assertEqual(extractor.GetExtractedError(), 0.0)
        np.testing.assert_array_equal(triangles_of(extractor.GetOutput()), self.triangles)

    def test_extract_out_of_range_resolution(self):
        base_n, base_t = int(self.counts[2]), int(self.counts[3])
        for resolution in (0.0, -3.0):
            extractor, messages = extract(self.tom, Resolution=resolution)
            self.assertEqual(extractor.GetResolution(), 0.0)
            self.assertEqual(self.check_extraction(extractor, messages), (base_n, base_t))
        extractor, messages = extract(self.tom, Resolution=7.0)
        self.assertEqual(extractor.GetResolution(), 1.0)
        self.assertEqual(self.check_extraction(extractor, messages),
                         (int(self.counts[0]), int(self.counts[1])))

    def test_extract_by_target_triangles(self):
        t, base_t = int(self.counts[1]), int(self.counts[3])
        previous = None
        for target in (0, base_t, 500, t // 3, t - 1, t, 10 * t):
            extractor, messages = extract(self.tom, TargetTriangles=target)
            self.assertEqual(extractor.GetSelectionMode(), vtkExtractTOMResolution.BY_TRIANGLE_COUNT)
            nv, nt = self.check_extraction(extractor, messages)
            self.assert_finest_within(nv, nt, min(target, t))
            if previous:
                self.assertGreaterEqual(nt, previous)
            previous = nt
        self.assertEqual(previous, t)

    def test_extract_by_maximum_error(self):
        errors = self.curve[:, 1]
        base_n = int(self.counts[2])
        # From coarse to fine: smaller allowed errors select more triangles.
        # Sample values of the curve and values between samples.
        requests = {float(errors[0]) * 2.0, float(errors[0]), float(errors[len(errors) // 4]),
                    float(errors[len(errors) // 2]), float(errors[-2]) / 2.0, 0.0}
        requests.update(float(e) for e in np.geomspace(errors[0] * 0.95, errors[-2] * 0.9, 15))
        requests = sorted(requests, reverse=True)
        counts = []
        for maximum in requests:
            extractor, messages = extract(self.tom, MaximumError=maximum)
            self.assertEqual(extractor.GetSelectionMode(), vtkExtractTOMResolution.BY_MAXIMUM_ERROR)
            nv, nt = self.check_extraction(extractor, messages)
            # Within the bound...
            self.assertLessEqual(extractor.GetExtractedError(), maximum * (1 + 1e-6) + 1e-12,
                                 "error %g asked, %d triangles (%d vertices) with error %g given"
                                 % (maximum, nt, nv, extractor.GetExtractedError()))
            # ...and the coarsest mesh that is.
            if nv > base_n:
                coarser = len(alive_triangles(self.substitution, self.triangles, nv - 1))
                self.assertGreater(np.interp(coarser, self.curve[:, 0], errors), maximum,
                                   "error %g asked: a coarser mesh fits" % maximum)
            counts.append(nt)
        self.assertEqual(counts, sorted(counts), list(zip(requests, counts)))
        self.assertEqual(counts[0], int(self.counts[3]))  # twice the largest error: the base mesh
        self.assertEqual(counts[-1], int(self.counts[1]))  # no error: the full mesh

    def test_geomorph(self):
        resolution = 0.3
        exact, _ = extract(self.tom, Resolution=resolution)
        nv = exact.GetExtractedVertexCount()
        last = nv - 1
        self.assertGreaterEqual(last, int(self.counts[2]))
        target = int(active_map(self.substitution, nv - 1)[self.substitution[last]])
        normals = vtk_to_numpy(self.tom.GetPointData().GetArray("Normals"))
        for factor in (0.0, 0.25, 1.0):
            extractor, messages = extract(self.tom, Resolution=resolution)
            extractor.SetGeomorphFactor(factor)
            extractor.Update()
            self.assertEqual(messages.errors, [])
            out = extractor.GetOutput()
            self.assertEqual(out.GetNumberOfPoints(), nv)
            self.assertEqual(out.GetNumberOfPolys(), exact.GetExtractedTriangleCount())
            moved = points_of(out)
            np.testing.assert_array_equal(moved[:last], self.points[:last])
            expected = self.points[target] + factor * (self.points[last] - self.points[target])
            np.testing.assert_allclose(moved[last], expected, rtol=1e-6, atol=1e-6)
            # Point data follows the point: at factor 0 the target's attributes.
            expected_normal = normals[target] + factor * (normals[last] - normals[target])
            np.testing.assert_allclose(
                vtk_to_numpy(out.GetPointData().GetArray("Normals"))[last], expected_normal,
                rtol=1e-5, atol=1e-5, err_msg="geomorphed normal at factor %g" % factor)

    def test_vtp_roundtrip(self):
        folder = output_dir('TestTOMPipeline')
        for mode in ("default", "ascii", "binary"):
            with self.subTest(mode=mode):
                if mode == "default" and not appended_xml_readable(folder):
                    print("\n  skipped the appended (default) mode: this system's VTK cannot read "
                          "back even a plain sphere written in it (expat/VTK XML parser "
                          "incompatibility, not a TOM problem)")
                    continue
                path = os.path.join(folder, "%s-%s.vtp" % (type(self).__name__, mode))
                writer = vtkXMLPolyDataWriter()
                writer.SetFileName(path)
                writer.SetInputData(self.tom)
                if mode == "ascii":
                    writer.SetDataModeToAscii()
                elif mode == "binary":
                    writer.SetDataModeToBinary()
                self.assertEqual(writer.Write(), 1)
                reader = vtkXMLPolyDataReader()
                reader.SetFileName(path)
                messages = Messages(reader)
                reader.Update()
                self.assertEqual(messages.errors, [])
                self.check_same_tom(reader.GetOutput())

    def check_same_tom(self, back):
        """back holds the same points, triangles and arrays as the TOM."""
        np.testing.assert_array_equal(points_of(back), self.points)
        np.testing.assert_array_equal(triangles_of(back), self.triangles)
        for attributes in ("GetPointData", "GetCellData", "GetFieldData"):
            ours, theirs = getattr(self.tom, attributes)(), getattr(back, attributes)()
            self.assertEqual(ours.GetNumberOfArrays(), theirs.GetNumberOfArrays(), attributes)
            for i in range(ours.GetNumberOfArrays()):
                mine = ours.GetAbstractArray(i)
                other = theirs.GetAbstractArray(mine.GetName())
                self.assertIsNotNone(other, mine.GetName())
                self.assertEqual(other.GetDataType(), mine.GetDataType(), mine.GetName())
                self.assertEqual(other.GetNumberOfComponents(), mine.GetNumberOfComponents())
                np.testing.assert_array_equal(vtk_to_numpy(other), vtk_to_numpy(mine),
                                              err_msg=mine.GetName())
        # The reloaded TOM extracts exactly as the original.
        for resolution in (0.25, 0.6):
            a, _ = extract(self.tom, Resolution=resolution)
            b, messages = extract(back, Resolution=resolution)
            self.assertEqual(messages.errors, [])
            np.testing.assert_array_equal(triangles_of(a.GetOutput()), triangles_of(b.GetOutput()))
            np.testing.assert_array_equal(points_of(a.GetOutput()), points_of(b.GetOutput()))
            self.assertEqual(a.GetExtractedError(), b.GetExtractedError())

    @unittest.skipIf(sys.platform.startswith("linux") and not os.environ.get("DISPLAY"),
                     "rendering needs an X display: run under xvfb-run -a")
    def test_render(self):
        from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper,
                                                 vtkRenderer, vtkRenderWindow,
                                                 vtkWindowToImageFilter)
        import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL overrides)

        def snapshot(mapper, representation=None):
            actor = vtkActor()
            actor.SetMapper(mapper)
            actor.GetProperty().SetColor(0.9, 0.6, 0.3)
            if representation is not None:
                actor.GetProperty().SetRepresentation(representation)
            renderer = vtkRenderer()
            renderer.SetBackground(0.1, 0.1, 0.2)
            renderer.AddActor(actor)
            window = vtkRenderWindow()
            window.SetOffScreenRendering(1)
            window.SetMultiSamples(0)
            window.SetSize(320, 320)
            window.AddRenderer(renderer)
            renderer.ResetCamera(self.tom.GetBounds())
            window.Render()
            grab = vtkWindowToImageFilter()
            grab.SetInput(window)
            grab.ReadFrontBufferOff()
            grab.Update()
            image = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).astype(np.int32)
            return image, window, actor

        extractor, _ = extract(self.tom, Resolution=0.25)
        mapper = vtkTOMPolyDataMapper()
        mapper.SetInputData(self.tom)
        mapper.SetResolution(0.25)
        messages = Messages(mapper)
        image, window, actor = snapshot(mapper)
        self.assertEqual(messages.text(), "")
        self.assertTrue(mapper.GetInputIsTOM())
        self.assertEqual(mapper.GetRenderedTriangles(), extractor.GetExtractedTriangleCount())
        self.assertEqual(mapper.GetRenderedVertices(), extractor.GetExtractedVertexCount())
        background = np.array([int(round(0.1 * 255)), int(round(0.1 * 255)), int(round(0.2 * 255))])
        covered = np.any(np.abs(image[:, :3] - background) > 2, axis=1).mean()
        self.assertGreater(covered, 0.05, "the mesh does not show")

        # The same triangles through VTK's own mapper give the same picture.
        plain = vtkPolyDataMapper()
        plain.SetInputData(extractor.GetOutput())
        reference, _, _ = snapshot(plain)
        differing = np.any(np.abs(image - reference) > 8, axis=1).mean()
        self.assertLess(differing, 0.005, "TOM mapper and extracted mesh render differently")

        # A new resolution only changes what is drawn.
        for resolution in (1.0, 0.05, 0.25):
            mapper.SetResolution(resolution)
            window.Render()
            expected, _ = extract(self.tom, Resolution=resolution)
            self.assertEqual(mapper.GetRenderedTriangles(), expected.GetExtractedTriangleCount())
            self.assertEqual(mapper.GetRenderedVertices(), expected.GetExtractedVertexCount())
        # Other representations draw the same triangles.
        actor.GetProperty().SetRepresentationToWireframe()
        window.Render()
        self.assertEqual(mapper.GetRenderedTriangles(), extractor.GetExtractedTriangleCount())
        actor.GetProperty().SetRepresentationToPoints()
        window.Render()
        self.assertEqual(mapper.GetRenderedVertices(), extractor.GetExtractedVertexCount())
        self.assertEqual(messages.errors, [])


class SphereTOM(TOMChecks, unittest.TestCase):
    @staticmethod
    def make_input():
        return sphere(200)


@unittest.skipUnless(os.path.isfile(COW), "no %s (shared test data)" % COW)
class CowTOM(TOMChecks, unittest.TestCase):
    @staticmethod
    def make_input():
        return cow()


# ---------------------------------------------------------------------------
def polydata(points, polys=(), lines=(), verts=()):
    data = vtkPolyData()
    pts = vtkPoints()
    pts.SetDataTypeToDouble()
    for p in points:
        pts.InsertNextPoint(*p)
    data.SetPoints(pts)
    for cells, setter in ((polys, data.SetPolys), (lines, data.SetLines), (verts, data.SetVerts)):
        if cells:
            array = vtkCellArray()
            for cell in cells:
                array.InsertNextCell(len(cell), cell)
            setter(array)
    return data


def grid_surface(n=12):
    """A small open square grid of triangles."""
    points = [(x, y, 0.1 * math.sin(x + y)) for y in range(n) for x in range(n)]
    polys = []
    for y in range(n - 1):
        for x in range(n - 1):
            a = y * n + x
            polys += [(a, a + 1, a + n + 1), (a, a + n + 1, a + n)]
    return points, polys


class BuilderOptions(unittest.TestCase):
    def check_valid(self, builder, messages):
        self.assertEqual(messages.errors, [])
        reader = vtkTOMFieldData()
        self.assertTrue(reader.Read(builder.GetOutput()), reader.GetErrorMessage())
        return reader

    def test_options_give_valid_toms(self):
        points, polys = grid_surface(20)
        surfaces = {"sphere": sphere(40), "grid": decorate(polydata(points, polys))}
        settings = [dict(), dict(PreserveBoundaries=False), dict(PreserveFeatureEdges=False),
                    dict(FeatureAngle=10.0), dict(MaximumNormalDeviation=20.0),
                    dict(MinimumTriangleQuality=0.4), dict(LockFeatureEdges=True),
                    dict(FeatureWeight=0.0), dict(FeatureWeight=100.0),
                    dict(PreserveBoundaries=False, PreserveFeatureEdges=False,
                         MinimumTriangleQuality=1.0, MaximumNormalDeviation=0.0)]
        for name, surface in surfaces.items():
            for options in settings:
                with self.subTest(surface=name, **options):
                    builder, messages = build(surface, **options)
                    for key, value in options.items():
                        self.assertEqual(getattr(builder, "Get" + key)(), value)
                    reader = self.check_valid(builder, messages)
                    self.assertEqual(reader.GetNumberOfTriangles(), surface.GetNumberOfPolys())
                    extractor, extract_messages = extract(builder.GetOutput(), Resolution=0.3)
                    self.assertEqual(extract_messages.errors, [])
                    self.assertLessEqual(extractor.GetExtractedTriangleCount(),
                                         max(round(0.3 * reader.GetNumberOfTriangles()),
                                             reader.GetBaseTriangleCount()))

    def test_preserved_boundary_keeps_the_outline(self):
        # A gently curved open square: with PreserveBoundaries its boundary
        # vertices only slide along the boundary, so every resolution that
        # still has collapses left covers the same square.
        n = 30
        points, polys = grid_surface(n)
        builder, messages = build(polydata(points, polys), PreserveBoundaries=True)
        self.check_valid(builder, messages)
        for resolution in (0.5, 0.3, 0.15):
            extractor, _ = extract(builder.GetOutput(), Resolution=resolution)
            out = extractor.GetOutput()
            xy = points_of(out)[:, :2]
            tri = triangles_of(out)
            a, b, c = xy[tri[:, 0]], xy[tri[:, 1]], xy[tri[:, 2]]
            signed = 0.5 * ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1])
                            - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))
            self.assertTrue(np.all(signed > 0), "flipped triangles at %g" % resolution)
            self.assertAlmostEqual(signed.sum(), (n - 1) ** 2, places=6,
                                   msg="outline changed at resolution %g" % resolution)

    def test_feature_edge_settings(self):
        # LockFeatureEdges and FeatureWeight reach the core (as in
        # TestvtkCollapseHierarchyBuilder's FeatureEdgeSettingsReachTheCore):
        # on a cube with bumpy faces each changes the TOM; weight 0 gives the
        # TOM of PreserveFeatureEdges off; a lock ignores the weight.
        cube = noisy_cube()

        def tom(**options):
            builder, messages = build(cube, **options)
            self.check_valid(builder, messages)
            out = builder.GetOutput()
            return points_of(out), triangles_of(out), tom_arrays(out)[0]

        def same(a, b):
            return all(np.array_equal(x, y) for x, y in zip(a, b))

        weighted = tom()
        self.assertEqual(len(weighted[1]), cube.GetNumberOfPolys())
        unweighted = tom(FeatureWeight=0.0)
        locked = tom(LockFeatureEdges=True)
        self.assertFalse(same(weighted, unweighted), "FeatureWeight not forwarded")
        self.assertFalse(same(weighted, tom(FeatureWeight=1.0)), "FeatureWeight not forwarded")
        self.assertTrue(same(unweighted, tom(PreserveFeatureEdges=False)))
        self.assertFalse(same(weighted, locked), "LockFeatureEdges not forwarded")
        self.assertTrue(same(locked, tom(LockFeatureEdges=True, FeatureWeight=0.0)))

    def test_feature_weight_bad_values(self):
        builder = vtkTOMBuilder()
        messages = Messages(builder)
        self.assertEqual(builder.GetFeatureWeight(), 10.0)
        self.assertFalse(builder.GetLockFeatureEdges())
        builder.SetFeatureWeight(float("nan"))
        self.assertEqual(len(messages.errors), 1)
        self.assertIn("FeatureWeight must be a number in [0, 1000]", messages.errors[0])
        self.assertEqual(builder.GetFeatureWeight(), 10.0)
        builder.SetFeatureWeight(-1.0)
        self.assertEqual(builder.GetFeatureWeight(), 0.0)
        builder.SetFeatureWeight(float("inf"))
        self.assertEqual(builder.GetFeatureWeight(), 1000.0)
        builder.LockFeatureEdgesOn()
        self.assertTrue(builder.GetLockFeatureEdges())

    def test_rebuild_a_tom(self):
        builder, messages = build(sphere(30))
        self.check_valid(builder, messages)
        again, messages = build(builder.GetOutput())
        reader = self.check_valid(again, messages)
        self.assertEqual(reader.GetNumberOfTriangles(), builder.GetOutput().GetNumberOfPolys())
        self.assertEqual(again.GetOutput().GetPointData().GetNumberOfArrays(),
                         builder.GetOutput().GetPointData().GetNumberOfArrays())


class BadInput(unittest.TestCase):
    def assert_build_fails(self, data, *words):
        builder, messages = build(data)
        self.assertTrue(messages.errors, "no error reported")
        for word in words:
            self.assertIn(word, messages.errors[0])
        out = builder.GetOutput()
        self.assertEqual(out.GetNumberOfPoints(), 0)
        self.assertEqual(out.GetNumberOfCells(), 0)
        self.assertFalse(vtkTOMFieldData.HasTOMArrays(out))

    def test_empty_piece_is_quiet(self):
        # A rank without data in parallel: empty output, no message, also downstream.
        builder, messages = build(vtkPolyData())
        self.assertEqual(messages.errors + messages.warnings, [])
        self.assertEqual(builder.GetOutput().GetNumberOfPoints(), 0)
        extractor, messages = extract(builder.GetOutput(), Resolution=0.5)
        self.assertEqual(messages.errors + messages.warnings, [])
        self.assertEqual(extractor.GetOutput().GetNumberOfCells(), 0)

    def test_points_without_cells(self):
        self.assert_build_fails(polydata([(0, 0, 0), (1, 0, 0), (0, 1, 0)]), "no surface cells")

    def test_lines_only(self):
        self.assert_build_fails(
            polydata([(0, 0, 0), (1, 0, 0), (0, 1, 0)], lines=[(0, 1), (1, 2)]),
            "no surface cells")

    def test_vertices_only(self):
        self.assert_build_fails(polydata([(0, 0, 0), (1, 0, 0)], verts=[(0,), (1,)]),
                                "no surface cells")

    def test_nan_point(self):
        points, polys = grid_surface()
        points[17] = (float("nan"), 0.0, 0.0)
        self.assert_build_fails(polydata(points, polys), "point 17", "non-finite")

    def test_infinite_point(self):
        points, polys = grid_surface()
        points[3] = (0.0, float("inf"), 0.0)
        self.assert_build_fails(polydata(points, polys), "point 3", "non-finite")

    def test_only_degenerate_triangles(self):
        self.assert_build_fails(polydata([(0, 0, 0), (1, 0, 0)], polys=[(0, 1, 1), (0, 0, 1)]))

    def test_mixed_cells_warn_and_build(self):
        # Lines, vertices and a degenerate triangle are dropped with warnings;
        # cell data of the remaining triangles still matches them.
        points, polys = grid_surface()
        polys = [(0, 1, 1)] + polys  # degenerate, first
        data = polydata(points, polys=polys, lines=[(0, 5), (5, 9)], verts=[(3,)])
        data = decorate(data)
        builder, messages = build(data)
        self.assertEqual(messages.errors, [])
        self.assertTrue(messages.warnings)
        self.assertEqual(builder.GetNumberOfDroppedCells(), 4)
        tom = builder.GetOutput()
        self.assertEqual(tom.GetNumberOfCells(), len(polys) - 1)
        self.assertEqual(tom.GetNumberOfPolys(), len(polys) - 1)
        # InputCellId counts verts, then lines, then polys (VTK's cell order).
        first_poly = 1 + 2
        in_points = np.array(points, dtype=np.float64)
        index = position_index(in_points)
        to_input = np.array([index[tuple(p)] for p in points_of(tom)])
        ids = vtk_to_numpy(tom.GetCellData().GetArray("InputCellId")) - first_poly
        expected = np.array(polys)[ids]
        np.testing.assert_array_equal(to_input[triangles_of(tom)], expected)

    def test_strips_and_quads(self):
        points, _ = grid_surface(6)
        quads = [(y * 6 + x, y * 6 + x + 1, y * 6 + x + 7, y * 6 + x + 6)
                 for y in range(5) for x in range(5)]
        builder, messages = build(polydata(points, polys=quads))
        self.assertEqual(messages.errors, [])
        self.assertEqual(builder.GetOutput().GetNumberOfPolys(), 50)
        reader = vtkTOMFieldData()
        self.assertTrue(reader.Read(builder.GetOutput()), reader.GetErrorMessage())

    def test_extract_from_non_tom(self):
        extractor, messages = extract(sphere(16), Resolution=0.5)
        self.assertTrue(messages.errors)
        self.assertIn("TOMSubstitution", messages.errors[0])
        self.assertEqual(extractor.GetOutput().GetNumberOfPoints(), 0)
        self.assertEqual(extractor.GetOutput().GetNumberOfCells(), 0)

    def test_extract_from_empty(self):
        # An empty piece, TOM arrays or not: empty output, no message.
        extractor, messages = extract(vtkPolyData(), Resolution=0.5)
        self.assertEqual(messages.errors + messages.warnings, [])
        self.assertEqual(extractor.GetOutput().GetNumberOfPoints(), 0)
        self.assertEqual(extractor.GetOutput().GetNumberOfCells(), 0)

    def test_nan_resolution(self):
        extractor = vtkExtractTOMResolution()
        messages = Messages(extractor)
        extractor.SetResolution(float("nan"))
        self.assertTrue(messages.errors)
        self.assertEqual(extractor.GetResolution(), 0.0)
        extractor.SetMaximumError(float("nan"))
        self.assertEqual(len(messages.errors), 2)
        self.assertEqual(extractor.GetSelectionMode(), vtkExtractTOMResolution.BY_RESOLUTION)


class CorruptedTOM(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        builder, messages = build(sphere(40))
        assert not messages.errors, messages.text()
        cls.tom = vtkPolyData()
        cls.tom.DeepCopy(builder.GetOutput())
        cls.counts = tom_arrays(cls.tom)[1].tolist()

    def copy(self):
        data = vtkPolyData()
        data.DeepCopy(self.tom)
        return data

    def assert_rejected(self, data, *words):
        reader = vtkTOMFieldData()
        self.assertFalse(reader.Read(data))
        for word in words:
            self.assertIn(word, reader.GetErrorMessage())
        extractor, messages = extract(data, Resolution=0.5)
        self.assertTrue(messages.errors, "vtkExtractTOMResolution accepted a corrupted TOM")
        self.assertIn("not a valid Totally Ordered Mesh", messages.errors[0])
        self.assertIn(reader.GetErrorMessage(), messages.errors[0])
        self.assertEqual(extractor.GetOutput().GetNumberOfPoints(), 0)
        self.assertEqual(extractor.GetOutput().GetNumberOfCells(), 0)
        return reader.GetErrorMessage()

    def substitution(self, data):
        return vtk_to_numpy(data.GetPointData().GetArray("TOMSubstitution"))

    def test_intact(self):
        reader = vtkTOMFieldData()
        self.assertTrue(reader.Read(self.tom), reader.GetErrorMessage())

    def test_substitution_not_below(self):
        data = self.copy()
        i = self.counts[0] - 5
        self.substitution(data)[i] = i
        data.GetPointData().GetArray("TOMSubstitution").Modified()
        self.assert_rejected(data, "substitution[%d] = %d is not below %d" % (i, i, i))
        self.substitution(data)[i] = i + 3
        self.assert_rejected(data, "substitution[%d] = %d" % (i, i + 3))

    def test_base_vertex_moved(self):
        data = self.copy()
        self.substitution(data)[1] = 0
        self.assert_rejected(data, "base vertex 1 substitutes to 0")

    def test_substitution_out_of_range(self):
        data = self.copy()
        self.substitution(data)[self.counts[0] - 1] = 4000000000
        self.assert_rejected(data, "substitution")

    def test_shuffled_triangle(self):
        data = self.copy()
        triangles = vtk_to_numpy(data.GetPolys().GetConnectivityArray()).reshape(-1, 3)
        first, last = triangles[0].copy(), triangles[-1].copy()
        triangles[0], triangles[-1] = last, first
        data.GetPolys().Modified()
        data.Modified()
        self.assert_rejected(data, "prefix order")

    def test_degenerate_triangle(self):
        data = self.copy()
        triangles = vtk_to_numpy(data.GetPolys().GetConnectivityArray()).reshape(-1, 3)
        triangles[7, 1] = triangles[7, 0]
        data.GetPolys().Modified()
        self.assert_rejected(data, "triangle 7", "degenerate")

    def test_wrong_counts(self):
        data = self.copy()
        counts = vtk_to_numpy(data.GetFieldData().GetArray("TOMCounts"))
        counts[1] += 1
        self.assert_rejected(data, "TOMCounts says")
        counts[1] -= 1
        counts[3] += 1
        self.assert_rejected(data, "base triangle count")
        counts[3] -= 1
        counts[2] = counts[0] + 1
        self.assert_rejected(data, "base vertex count")

    def test_counts_missing(self):
        data = self.copy()
        data.GetFieldData().RemoveArray("TOMCounts")
        self.assert_rejected(data, "TOMCounts")

    def test_float_substitution(self):
        data = self.copy()
        values = self.substitution(data).astype(np.float64)
        array = numpy_to_vtk(values, deep=True)
        array.SetName("TOMSubstitution")
        data.GetPointData().AddArray(array)
        self.assert_rejected(data, "integer")

    def test_bad_error_curve(self):
        data = self.copy()
        curve = vtk_to_numpy(data.GetFieldData().GetArray("TOMErrorCurve")).reshape(-1, 2)
        curve[-1, 1] = 5.0  # the full mesh must have error 0
        self.assert_rejected(data, "error curve")
        data = self.copy()
        bad = vtkDoubleArray()
        bad.SetName("TOMErrorCurve")
        bad.SetNumberOfComponents(3)
        bad.InsertNextTuple3(1, 2, 3)
        data.GetFieldData().AddArray(bad)
        self.assert_rejected(data, "TOMErrorCurve")

    def test_extra_lines(self):
        data = self.copy()
        lines = vtkCellArray()
        lines.InsertNextCell(2, (0, 1))
        data.SetLines(lines)
        self.assert_rejected(data, "triangles only")

    @unittest.skipIf(sys.platform.startswith("linux") and not os.environ.get("DISPLAY"),
                     "rendering needs an X display: run under xvfb-run -a")
    def test_mapper_renders_corrupted_tom_in_full(self):
        from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer, vtkRenderWindow
        import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

        data = self.copy()
        self.substitution(data)[self.counts[0] - 1] = self.counts[0] + 10
        mapper = vtkTOMPolyDataMapper()
        mapper.SetInputData(data)
        mapper.SetResolution(0.1)
        messages = Messages(mapper)
        actor = vtkActor()
        actor.SetMapper(mapper)
        renderer = vtkRenderer()
        renderer.AddActor(actor)
        window = vtkRenderWindow()
        window.SetOffScreenRendering(1)
        window.SetSize(64, 64)
        window.AddRenderer(renderer)
        window.Render()
        window.Render()
        self.assertFalse(mapper.GetInputIsTOM())
        self.assertEqual(len(messages.warnings), 1, messages.text())
        self.assertIn("not a valid TOM", messages.warnings[0])
        self.assertEqual(mapper.GetRenderedTriangles(), self.counts[1])
        self.assertEqual(mapper.GetRenderedVertices(), self.counts[0])


if __name__ == "__main__":
    unittest.main(verbosity=2)
