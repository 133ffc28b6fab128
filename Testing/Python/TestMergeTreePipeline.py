#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Merge trees and view-dependent extraction from Python.

Two parts, both run under the system Python (`/usr/bin/python3
TestMergeTreePipeline.py`) and under pvbatch:

* the wrapped classes (`timecritical` package) in a plain VTK pipeline:
  build, binary .vtp round trip, corrupted arrays, extraction for a camera;
* the ParaView plugin through paraview.simple: the filters "Build Merge Tree"
  and "Extract View-Dependent Mesh" with their camera properties.

Environment: PYTHONPATH holds the build tree's lib/python3/dist-packages;
TIMECRITICAL_PLUGIN is the path of TimeCritical.so; TIMECRITICAL_SHARED_DATA_DIR
names the folder with cow.obj (its test is skipped when absent);
TIMECRITICAL_TEST_OUTPUT_DIR receives scratch files.
"""

import os
import sys
import unittest

import numpy as np

# Star import: LoadPlugin(ns=globals()) adds the plugin's filters to this namespace.
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter
from vtkmodules.vtkRenderingCore import vtkCamera

from timecritical import (vtkExtractViewDependentMesh, vtkMergeTreeBuilder,
                          vtkMergeTreeFieldData)

from timecritical_testing import COW, ProxyTests, load_plugin, noisy_cube, output_dir  # noqa: E402

POINT_ARRAYS = ("TOMSubstitution", "MergeTreeLevel", "MergeTreeError", "MergeTreeRadius",
                "MergeTreeConeAxis", "MergeTreeConeCosine")
FIELD_ARRAYS = ("TOMCounts", "TOMErrorCurve", "MergeTreeDependencyOffsets",
                "MergeTreeDependencies", "MergeTreeLevelCount")






def merge_tree_arrays(data):
    """numpy copies of the TOM and merge-tree arrays of a vtkPolyData."""
    result = {}
    for name in POINT_ARRAYS:
        array = data.GetPointData().GetArray(name)
        if array is not None:
            result[name] = vtk_to_numpy(array).copy()
    for name in FIELD_ARRAYS:
        array = data.GetFieldData().GetArray(name)
        if array is not None:
            result[name] = vtk_to_numpy(array).copy()
    return result


def triangles(data):
    return vtk_to_numpy(data.GetPolys().GetConnectivityArray()).astype(np.int64).reshape(-1, 3)


def check_closed_manifold(test, data):
    """A closed, consistently oriented manifold with the sphere's Euler characteristic 2."""
    tris = triangles(data)
    test.assertEqual(data.GetNumberOfCells(), len(tris))
    test.assertEqual(data.GetPolys().GetNumberOfCells() * 3, tris.size)
    directed = np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]])
    keys = directed[:, 0] * (data.GetNumberOfPoints() + 1) + directed[:, 1]
    reverse = directed[:, 1] * (data.GetNumberOfPoints() + 1) + directed[:, 0]
    test.assertEqual(len(np.unique(keys)), len(keys), "an edge is used twice in one direction")
    test.assertTrue(np.all(np.isin(reverse, keys)), "an edge has one triangle only")
    test.assertEqual(len(np.unique(tris)), data.GetNumberOfPoints(), "unused points")
    vertices, edges, faces = data.GetNumberOfPoints(), len(keys) // 2, len(tris)
    test.assertEqual(vertices - edges + faces, 2, (vertices, edges, faces))


class ErrorLog:
    """Error messages an object emits."""

    def __init__(self, obj):
        self.messages = []

        @calldata_type(VTK_STRING)
        def record(caller, event, message):
            self.messages.append(message)
        obj.AddObserver(vtkCommand.ErrorEvent, record)

    def contains(self, text):
        return any(text in m for m in self.messages)


def sphere(resolution=48):
    source = vtkSphereSource()
    source.SetThetaResolution(resolution)
    source.SetPhiResolution(resolution)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(source.GetOutputPort())
    normals.SplittingOff()
    return normals


class WrappedClasses(unittest.TestCase):
    """The wrapped classes in a plain VTK pipeline."""

    @classmethod
    def setUpClass(cls):
        cls.source = sphere()
        cls.builder = vtkMergeTreeBuilder()
        cls.builder.SetInputConnection(cls.source.GetOutputPort())
        cls.builder.Update()
        cls.tree = cls.builder.GetOutput()

    def extractor(self, data=None):
        extract = vtkExtractViewDependentMesh()
        if data is None:
            extract.SetInputConnection(self.builder.GetOutputPort())
        else:
            extract.SetInputData(data)
        camera = vtkCamera()
        camera.SetPosition(0, 0, 3)
        camera.SetFocalPoint(0, 0, 0)
        extract.SetCamera(camera)
        return extract, camera

    def test_tree_arrays(self):
        reader = vtkMergeTreeFieldData()
        self.assertTrue(reader.Read(self.tree), reader.GetErrorMessage())
        a = merge_tree_arrays(self.tree)
        n = self.tree.GetNumberOfPoints()
        self.assertEqual(a["MergeTreeLevel"].dtype, np.uint16)
        self.assertEqual(a["MergeTreeError"].dtype, np.float32)
        self.assertEqual(a["MergeTreeConeAxis"].shape, (n, 3))
        self.assertEqual(a["MergeTreeDependencyOffsets"].dtype, np.uint32)
        self.assertEqual(len(a["MergeTreeDependencyOffsets"]), n + 1)
        self.assertEqual(a["MergeTreeDependencyOffsets"][-1], len(a["MergeTreeDependencies"]))
        level_count = int(a["MergeTreeLevelCount"][0])
        self.assertEqual(level_count, self.builder.GetLevelCount())
        self.assertEqual(reader.GetLevelCount(), level_count)
        base = int(a["TOMCounts"][2])
        np.testing.assert_array_equal(a["MergeTreeLevel"][:base], level_count)
        self.assertTrue(np.all(a["MergeTreeLevel"][base:] < level_count))
        self.assertTrue(np.all(a["MergeTreeError"] >= 0))
        self.assertTrue(np.all(np.abs(a["MergeTreeConeCosine"]) <= 1))

    def test_binary_vtp_round_trip(self):
        path = os.path.join(output_dir('TestMergeTreePipeline'), "sphere-merge-tree.vtp")
        writer = vtkXMLPolyDataWriter()
        writer.SetFileName(path)
        writer.SetInputData(self.tree)
        writer.SetDataModeToBinary()  # appended mode is unreadable here (see README)
        self.assertEqual(writer.Write(), 1)
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(path)
        reader.Update()
        back = reader.GetOutput()
        before, after = merge_tree_arrays(self.tree), merge_tree_arrays(back)
        self.assertEqual(sorted(before), sorted(after))
        for name, value in before.items():
            self.assertEqual(after[name].dtype, value.dtype, name)
            np.testing.assert_array_equal(after[name], value, err_msg=name)
        # The reloaded tree extracts the same front.
        original, _ = self.extractor()
        reloaded, _ = self.extractor(back)
        original.Update()
        reloaded.Update()
        np.testing.assert_array_equal(triangles(reloaded.GetOutput()),
                                      triangles(original.GetOutput()))

    def test_corrupted_array_is_reported(self):
        from vtkmodules.vtkCommonDataModel import vtkPolyData
        bad = vtkPolyData()
        bad.DeepCopy(self.tree)
        bad.GetPointData().GetArray("MergeTreeConeCosine").SetValue(5, 3.0)
        reader = vtkMergeTreeFieldData()
        self.assertFalse(reader.Read(bad))
        self.assertIn("MergeTreeConeCosine of point 5 (3) is not a cosine in [-1, 1]",
                      reader.GetErrorMessage())
        extract, _ = self.extractor(bad)
        log = ErrorLog(extract)
        extract.Update()
        self.assertTrue(log.contains("MergeTreeConeCosine of point 5"), log.messages)
        self.assertEqual(extract.GetOutput().GetNumberOfCells(), 0)

    def test_front_threshold_and_camera(self):
        extract, camera = self.extractor()
        counts = []
        for tau in (0.5, 1.0, 2.0, 4.0, 8.0):
            extract.SetPixelThreshold(tau)
            extract.Update()
            check_closed_manifold(self, extract.GetOutput())
            counts.append(extract.GetOutput().GetNumberOfCells())
        self.assertEqual(counts, sorted(counts, reverse=True))
        self.assertLess(counts[-1], counts[0])
        # Moving the camera object re-executes the filter.
        extract.SetPixelThreshold(1.0)
        extract.Update()
        near = extract.GetOutput().GetNumberOfCells()
        camera.SetPosition(0, 0, 30)
        extract.Update()
        far = extract.GetOutput().GetNumberOfCells()
        self.assertLess(far, near)
        check_closed_manifold(self, extract.GetOutput())


class PluginFilters(ProxyTests, unittest.TestCase):
    """The plugin's filters through paraview.simple."""

    def setUp(self):
        self.created = []
        self.source = self.new(Sphere(ThetaResolution=48, PhiResolution=48))
        self.tree_proxy = self.new(BuildMergeTree(Input=self.source))

    def extract(self, input_proxy, **properties):
        values = dict(CameraPosition=[0, 0, 3], CameraFocalPoint=[0, 0, 0],
                      CameraViewUp=[0, 1, 0])
        values.update(properties)
        return self.new(ExtractViewDependentMesh(Input=input_proxy, **values))

    def test_defaults(self):
        self.assertEqual(self.tree_proxy.PreserveBoundaries, 1)
        self.assertEqual(self.tree_proxy.FeatureAngle, 45.0)
        self.assertEqual(self.tree_proxy.LockFeatureEdges, 0)
        self.assertEqual(self.tree_proxy.FeatureWeight, 10.0)
        self.assertEqual(self.tree_proxy.MinimumTriangleQuality, 0.0)
        self.assertEqual(self.tree_proxy.LevelCostRatio, 2.0)
        self.assertEqual(self.tree_proxy.ShadingWeight, 1.0)
        extract = self.new(ExtractViewDependentMesh(Input=self.tree_proxy))
        self.assertEqual(list(extract.ViewportSize), [512, 512])
        self.assertEqual(extract.PixelThreshold, 1.0)
        self.assertEqual(extract.CameraViewAngle, 30.0)
        self.assertEqual(extract.RefinementMode, "Fixed Accuracy")
        self.assertEqual(extract.BackFaceSimplification, 1)
        # Silhouette and highlight refinement as in the mapper and the renderer.
        self.assertEqual(extract.SilhouetteRefinement, 1)
        self.assertEqual(extract.SilhouetteFactor, 0.25)
        self.assertEqual(extract.HighlightRefinement, 1)
        self.assertEqual(extract.HighlightFactor, 0.5)

    def test_tree(self):
        tree = self.fetch(self.tree_proxy)
        a = merge_tree_arrays(tree)
        for name in POINT_ARRAYS + FIELD_ARRAYS:
            self.assertIn(name, a)
        self.assertEqual(tree.GetNumberOfPolys(), self.fetch(self.source).GetNumberOfPolys())
        self.assertEqual(tree.GetNumberOfPoints(), self.fetch(self.source).GetNumberOfPoints())
        reader = vtkMergeTreeFieldData()
        self.assertTrue(reader.Read(tree), reader.GetErrorMessage())

    def test_extract(self):
        extract = self.extract(self.tree_proxy, PixelThreshold=1.0, GenerateLocalLevels=1)
        front = self.fetch(extract)
        check_closed_manifold(self, front)
        full = self.fetch(self.tree_proxy).GetNumberOfPolys()
        self.assertLess(front.GetNumberOfPolys(), full)
        levels = front.GetCellData().GetArray("LocalLevel")
        self.assertIsNotNone(levels)
        self.assertGreater(vtk_to_numpy(levels).max(), 0)
        for name in POINT_ARRAYS:
            self.assertIsNone(front.GetPointData().GetArray(name), name)
        self.assertIsNotNone(front.GetPointData().GetArray("Normals"))

        # The threshold and the camera properties drive the front.
        extract.PixelThreshold = 8.0
        coarse = self.fetch(extract).GetNumberOfPolys()
        self.assertLess(coarse, front.GetNumberOfPolys())
        extract.PixelThreshold = 1.0
        extract.CameraPosition = [0, 0, 30]
        far = self.fetch(extract)
        check_closed_manifold(self, far)
        self.assertLess(far.GetNumberOfPolys(), front.GetNumberOfPolys())
        extract.CameraPosition = [0, 0, 3]
        self.assertEqual(self.fetch(extract).GetNumberOfPolys(), front.GetNumberOfPolys())

        extract.RefinementMode = "Triangle Budget"
        extract.TriangleBudget = 600
        budget = self.fetch(extract).GetNumberOfPolys()
        self.assertLessEqual(budget, 600 + 16)
        self.assertGreater(budget, 400)

    def test_feature_edge_properties(self):
        # Lock Feature Edges and Feature Weight reach the filter: on a cube with
        # bumpy faces each changes the merge tree's TOM; weight 0 gives that of
        # unpreserved creases; a lock ignores the weight.
        path = os.path.join(output_dir('TestMergeTreePipeline'), "noisy-cube.vtp")
        writer = vtkXMLPolyDataWriter()
        writer.SetFileName(path)
        writer.SetInputData(noisy_cube())
        writer.SetDataModeToBinary()
        self.assertEqual(writer.Write(), 1)
        tree = self.new(BuildMergeTree(Input=self.new(XMLPolyDataReader(FileName=[path]))))

        def order(**properties):
            for name, value in properties.items():
                setattr(tree, name, value)
            data = self.fetch(tree)
            self.assertEqual(data.GetNumberOfPolys(), 12 * 8 * 8)
            return (vtk_to_numpy(data.GetPoints().GetData()).copy(), triangles(data),
                    merge_tree_arrays(data)["TOMSubstitution"])

        def same(a, b):
            return all(np.array_equal(x, y) for x, y in zip(a, b))

        weighted = order()
        unweighted = order(FeatureWeight=0.0)
        self.assertFalse(same(weighted, unweighted), "FeatureWeight not forwarded")
        self.assertTrue(same(unweighted, order(PreserveFeatureEdges=0, FeatureWeight=10.0)))
        locked = order(PreserveFeatureEdges=1, LockFeatureEdges=1)
        self.assertFalse(same(weighted, locked), "LockFeatureEdges not forwarded")
        self.assertTrue(same(locked, order(FeatureWeight=0.0)))

    def test_save_binary_and_extract_again(self):
        path = os.path.join(output_dir('TestMergeTreePipeline'), "plugin-merge-tree.vtp")
        SaveData(path, proxy=self.tree_proxy, DataMode="Binary")
        reader = self.new(XMLPolyDataReader(FileName=[path]))
        expected = merge_tree_arrays(self.fetch(self.tree_proxy))
        got = merge_tree_arrays(self.fetch(reader))
        for name, value in expected.items():
            self.assertIn(name, got)
            self.assertEqual(got[name].dtype, value.dtype, name)
            np.testing.assert_array_equal(got[name], value, err_msg=name)
        a = self.fetch(self.extract(self.tree_proxy, PixelThreshold=2.0))
        b = self.fetch(self.extract(reader, PixelThreshold=2.0))
        np.testing.assert_array_equal(triangles(a), triangles(b))

    def test_not_a_merge_tree_gives_empty_output(self):
        extract = self.extract(self.source)
        sys.stderr.write("\n(an error about a missing merge tree is expected here)\n")
        data = self.fetch(extract)
        self.assertEqual(data.GetNumberOfCells(), 0)

    @unittest.skipUnless(os.path.isfile(COW), "no %s (shared test data)" % COW)
    def test_cow(self):
        cow = self.new(OpenDataFile(COW))
        tree_proxy = self.new(BuildMergeTree(Input=cow, MinimumTriangleQuality=0.1))
        tree = self.fetch(tree_proxy)
        bounds = tree.GetBounds()
        center = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2,
                  (bounds[4] + bounds[5]) / 2]
        size = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
        extract = self.extract(tree_proxy, CameraFocalPoint=center,
                               CameraPosition=[center[0], center[1], center[2] + 2 * size],
                               SilhouetteRefinement=1, PixelThreshold=2.0)
        front = self.fetch(extract)
        self.assertGreater(front.GetNumberOfPolys(), 0)
        self.assertLess(front.GetNumberOfPolys(), tree.GetNumberOfPolys())


if __name__ == "__main__":
    load_plugin(globals(), ('BuildMergeTree', 'ExtractViewDependentMesh'))
    result = unittest.main(argv=[sys.argv[0]], verbosity=2, exit=False).result
    sys.exit(0 if result.wasSuccessful() else 1)
