#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The TimeCritical ParaView plugin through paraview.simple.

Runs under pvbatch (`pvbatch TestTOMPlugin.py`) and under the system Python
(`/usr/bin/python3 TestTOMPlugin.py`, builtin session).

Environment: TIMECRITICAL_PLUGIN is the path of TimeCritical.so (the build
tree's lib/paraview-plugins/TimeCritical/TimeCritical.so);
TIMECRITICAL_SHARED_DATA_DIR names the folder with cow.obj (its test is
skipped when absent); TIMECRITICAL_TEST_OUTPUT_DIR receives scratch files.
"""

import os
import sys
import unittest

import numpy as np

from paraview import servermanager
# Star import: LoadPlugin(ns=globals()) adds the plugin's filters to this namespace.
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy

from timecritical_testing import COW, load_plugin, noisy_cube, output_dir  # noqa: E402






def fetch(proxy):
    proxy.UpdatePipeline()
    data = servermanager.Fetch(proxy)
    if data is None:
        raise AssertionError("nothing fetched from %s" % proxy.GetXMLLabel())
    return data


def arrays(data):
    """numpy copies of the points, triangles and TOM arrays of a vtkPolyData."""
    result = {
        "points": vtk_to_numpy(data.GetPoints().GetData()).astype(np.float64),
        "triangles": vtk_to_numpy(data.GetPolys().GetConnectivityArray()).astype(np.int64),
    }
    substitution = data.GetPointData().GetArray("TOMSubstitution")
    counts = data.GetFieldData().GetArray("TOMCounts")
    curve = data.GetFieldData().GetArray("TOMErrorCurve")
    if substitution is not None:
        result["TOMSubstitution"] = vtk_to_numpy(substitution).copy()
    if counts is not None:
        result["TOMCounts"] = vtk_to_numpy(counts).copy()
    if curve is not None:
        result["TOMErrorCurve"] = vtk_to_numpy(curve).reshape(-1, 2).copy()
    return result


class PluginChecks:
    """Checks of the plugin's filters on one source; subclasses set make_source()."""

    def setUp(self):
        self.source = self.make_source()
        self.tom_proxy = BuildTotallyOrderedMesh(Input=self.source)
        self.tom = fetch(self.tom_proxy)
        self.tom_arrays = arrays(self.tom)

    def tearDown(self):
        for proxy in getattr(self, "created", []) + [self.tom_proxy, self.source]:
            Delete(proxy)

    def new(self, proxy):
        self.created = getattr(self, "created", [])
        self.created.insert(0, proxy)
        return proxy

    def test_tom(self):
        a = self.tom_arrays
        self.assertIn("TOMSubstitution", a)
        self.assertIn("TOMCounts", a)
        self.assertIn("TOMErrorCurve", a)
        n, t, base_n, base_t = (int(v) for v in a["TOMCounts"])
        self.assertEqual(n, self.tom.GetNumberOfPoints())
        self.assertEqual(t, self.tom.GetNumberOfPolys())
        self.assertEqual(self.tom.GetNumberOfCells(), t)
        self.assertGreater(t, 1000)
        self.assertTrue(0 < base_n < n // 20, (base_n, n))
        self.assertTrue(0 < base_t < t // 20, (base_t, t))
        self.assertEqual(a["TOMSubstitution"].dtype, np.uint32)
        sub = a["TOMSubstitution"].astype(np.int64)
        ids = np.arange(n)
        np.testing.assert_array_equal(sub[:base_n], ids[:base_n])
        self.assertTrue(np.all(sub[base_n:] < ids[base_n:]))
        curve = a["TOMErrorCurve"]
        self.assertEqual(curve[-1, 0], t)
        self.assertEqual(curve[-1, 1], 0.0)
        self.assertTrue(np.all(np.diff(curve[:, 1]) <= 0))
        # Defaults of the proxy as documented in the XML.
        self.assertEqual(self.tom_proxy.PreserveBoundaries, 1)
        self.assertEqual(self.tom_proxy.PreserveFeatureEdges, 1)
        self.assertEqual(self.tom_proxy.FeatureAngle, 45.0)
        self.assertEqual(self.tom_proxy.LockFeatureEdges, 0)
        self.assertEqual(self.tom_proxy.FeatureWeight, 10.0)
        self.assertEqual(self.tom_proxy.MinimumTriangleQuality, 0.0)

    def check_extracted(self, extracted, proxy=None):
        """An extraction is a prefix of the TOM's points with at most its triangles."""
        out = arrays(extracted)
        nv, nt = extracted.GetNumberOfPoints(), extracted.GetNumberOfPolys()
        n, t, base_n, _ = (int(v) for v in self.tom_arrays["TOMCounts"])
        self.assertTrue(base_n <= nv <= n, (base_n, nv, n))
        self.assertLessEqual(nt, t)
        self.assertEqual(extracted.GetNumberOfCells(), nt)
        np.testing.assert_array_equal(out["points"], self.tom_arrays["points"][:nv])
        self.assertTrue(np.all(out["triangles"] < nv))
        self.assertNotIn("TOMSubstitution", out)
        self.assertNotIn("TOMCounts", out)
        return nv, nt

    def test_extract_resolution(self):
        t = int(self.tom_arrays["TOMCounts"][1])
        extract = self.new(ExtractTOMResolution(Input=self.tom_proxy, Resolution=0.25))
        self.assertEqual(extract.SelectionMode, "Resolution")
        nv, nt = self.check_extracted(fetch(extract))
        self.assertLessEqual(nt, round(0.25 * t))
        self.assertGreater(nt, 0.2 * t)
        previous = (nv, nt)
        extract.Resolution = 0.5
        nv, nt = self.check_extracted(fetch(extract))
        self.assertLessEqual(nt, round(0.5 * t))
        self.assertGreater(nt, 0.45 * t)
        self.assertGreater(nv, previous[0])
        extract.Resolution = 1.0
        full = fetch(extract)
        self.assertEqual(self.check_extracted(full), (self.tom.GetNumberOfPoints(), t))
        np.testing.assert_array_equal(arrays(full)["triangles"], self.tom_arrays["triangles"])

    def test_extract_by_count_and_error(self):
        t = int(self.tom_arrays["TOMCounts"][1])
        base_t = int(self.tom_arrays["TOMCounts"][3])
        extract = self.new(ExtractTOMResolution(Input=self.tom_proxy))
        extract.SelectionMode = "Target Triangles"
        extract.TargetTriangles = 1000
        _, nt = self.check_extracted(fetch(extract))
        self.assertLessEqual(nt, max(1000, base_t))
        self.assertGreater(nt, 900)
        extract.SelectionMode = "Maximum Error"
        counts = []
        curve = self.tom_arrays["TOMErrorCurve"]
        for maximum in (float(curve[0, 1]) * 2, float(curve[len(curve) // 2, 1]), 0.0):
            extract.MaximumError = maximum
            counts.append(self.check_extracted(fetch(extract))[1])
        self.assertEqual(counts[0], base_t)
        self.assertLess(counts[0], counts[1])
        self.assertLess(counts[1], counts[2])
        self.assertEqual(counts[2], t)

    def test_save_and_reload(self):
        folder = output_dir('TestTOMPlugin')
        extract = self.new(ExtractTOMResolution(Input=self.tom_proxy, Resolution=0.25))
        expected = fetch(extract)
        # DataMode: the XML writer's default (Appended) is not readable by
        # this system's VTK 9.2 XML parser at all (see appended_xml_readable);
        # Binary (inline base64) and Ascii are checked.
        for mode in ("Binary", "Ascii"):
            with self.subTest(mode=mode):
                path = os.path.join(folder, "%s-%s.vtp" % (type(self).__name__, mode))
                SaveData(path, proxy=self.tom_proxy, DataMode=mode)
                self.assertTrue(os.path.getsize(path) > 0)
                reader = self.new(XMLPolyDataReader(FileName=[path]))
                back = fetch(reader)
                self.assertEqual(back.GetNumberOfPoints(), self.tom.GetNumberOfPoints())
                self.assertEqual(back.GetNumberOfPolys(), self.tom.GetNumberOfPolys())
                got = arrays(back)
                for name, value in self.tom_arrays.items():
                    self.assertIn(name, got)
                    self.assertEqual(got[name].dtype, value.dtype, name)
                    np.testing.assert_array_equal(got[name], value, err_msg=name)
                # The reloaded file is still a TOM and extracts the same.
                again = self.new(ExtractTOMResolution(Input=reader, Resolution=0.25))
                result = fetch(again)
                self.assertEqual(result.GetNumberOfPoints(), expected.GetNumberOfPoints())
                self.assertEqual(result.GetNumberOfPolys(), expected.GetNumberOfPolys())
                np.testing.assert_array_equal(arrays(result)["triangles"],
                                              arrays(expected)["triangles"])


class SpherePlugin(PluginChecks, unittest.TestCase):
    @staticmethod
    def make_source():
        return Sphere(ThetaResolution=128, PhiResolution=128)


@unittest.skipUnless(os.path.isfile(COW), "no %s (shared test data)" % COW)
class CowPlugin(PluginChecks, unittest.TestCase):
    @staticmethod
    def make_source():
        return OpenDataFile(COW)


class FeatureEdgeProperties(unittest.TestCase):
    """Lock Feature Edges and Feature Weight reach the filter and change the TOM
    of a cube with bumpy faces (the C++ and wrapped tests check the same)."""

    def setUp(self):
        from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
        path = os.path.join(output_dir("TestTOMPlugin"), "noisy-cube.vtp")
        writer = vtkXMLPolyDataWriter()
        writer.SetFileName(path)
        writer.SetInputData(noisy_cube())
        writer.SetDataModeToBinary()  # appended mode: see test_save_and_reload
        self.assertEqual(writer.Write(), 1)
        self.reader = XMLPolyDataReader(FileName=[path])
        self.tom_proxy = BuildTotallyOrderedMesh(Input=self.reader)

    def tearDown(self):
        Delete(self.tom_proxy)
        Delete(self.reader)

    def tom(self, **properties):
        for name, value in properties.items():
            setattr(self.tom_proxy, name, value)
        data = fetch(self.tom_proxy)
        self.assertEqual(data.GetNumberOfPolys(), 12 * 8 * 8)
        a = arrays(data)
        return a["points"], a["triangles"], a["TOMSubstitution"]

    @staticmethod
    def same(a, b):
        return all(np.array_equal(x, y) for x, y in zip(a, b))

    def test_properties_change_the_tom(self):
        self.assertEqual(self.tom_proxy.LockFeatureEdges, 0)
        self.assertEqual(self.tom_proxy.FeatureWeight, 10.0)
        weighted = self.tom()
        unweighted = self.tom(FeatureWeight=0.0)
        self.assertFalse(self.same(weighted, unweighted), "FeatureWeight not forwarded")
        # Weight 0 leaves the creases to the face quadrics: the TOM of unpreserved creases.
        self.assertTrue(self.same(unweighted, self.tom(PreserveFeatureEdges=0, FeatureWeight=10.0)))
        locked = self.tom(PreserveFeatureEdges=1, LockFeatureEdges=1)
        self.assertFalse(self.same(weighted, locked), "LockFeatureEdges not forwarded")
        # A lock does not use the weight.
        self.assertTrue(self.same(locked, self.tom(FeatureWeight=0.0)))
        self.assertTrue(self.same(weighted, self.tom(LockFeatureEdges=0, FeatureWeight=10.0)))

    def test_out_of_range_weight_is_clamped_by_the_filter(self):
        # The proxy passes any value; the filter clamps it to [0, 1000].
        heaviest = self.tom(FeatureWeight=1000.0)
        self.assertFalse(self.same(heaviest, self.tom(FeatureWeight=10.0)))
        self.assertTrue(self.same(heaviest, self.tom(FeatureWeight=5000.0)))
        self.assertTrue(self.same(self.tom(FeatureWeight=0.0), self.tom(FeatureWeight=-3.0)))


class PairContractionProperty(unittest.TestCase):
    """Pair Contraction Distance reaches the filter: 27 separate spheres join
    at the coarsest resolution (the C++ tests check the same on the filter)."""

    def setUp(self):
        from vtkmodules.vtkFiltersCore import vtkAppendPolyData
        from vtkmodules.vtkFiltersSources import vtkSphereSource
        from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
        append = vtkAppendPolyData()
        for i in range(27):
            sphere = vtkSphereSource()
            sphere.SetThetaResolution(8)
            sphere.SetPhiResolution(8)
            sphere.SetCenter(1.5 * (i % 3), 1.5 * (i // 3 % 3), 1.5 * (i // 9))
            append.AddInputConnection(sphere.GetOutputPort())
        append.Update()
        path = os.path.join(output_dir("TestTOMPlugin"), "spheres.vtp")
        writer = vtkXMLPolyDataWriter()
        writer.SetFileName(path)
        writer.SetInputData(append.GetOutput())
        writer.SetDataModeToBinary()  # appended mode: see test_save_and_reload
        self.assertEqual(writer.Write(), 1)
        self.reader = XMLPolyDataReader(FileName=[path])
        self.tom_proxy = BuildTotallyOrderedMesh(Input=self.reader)

    def tearDown(self):
        Delete(self.tom_proxy)
        Delete(self.reader)

    def counts(self):
        """(base vertices, base triangles) of the TOM."""
        _, _, base_n, base_t = (int(v) for v in arrays(fetch(self.tom_proxy))["TOMCounts"])
        return base_n, base_t

    def test_property_reaches_the_filter(self):
        self.assertEqual(self.tom_proxy.PairContractionDistance, 0.0)
        self.assertEqual(self.counts(), (27 * 4, 27 * 4), "off: a tetrahedron per sphere")
        self.tom_proxy.PairContractionDistance = 0.5
        base_n, base_t = self.counts()
        self.assertEqual(base_n, 4)
        self.assertLessEqual(base_t, 4)
        if not servermanager.ActiveConnection.IsRemote():
            # The filter's own PrintSelf (the object may be wrapped as its base class).
            state = str(self.tom_proxy.GetClientSideObject())
            self.assertIn("PairContractionDistance: 0.5\n", state)
            self.assertIn("NumberOfJoinedParts: 26\n", state)
        self.tom_proxy.PairContractionDistance = 0.0
        self.assertEqual(self.counts(), (27 * 4, 27 * 4))


class NotATOM(unittest.TestCase):
    def test_extract_non_tom_gives_empty_output(self):
        source = Sphere()
        extract = ExtractTOMResolution(Input=source)
        sys.stderr.write("\n(an error about a missing TOMSubstitution array is expected here)\n")
        data = fetch(extract)
        self.assertEqual(data.GetNumberOfPoints(), 0)
        self.assertEqual(data.GetNumberOfCells(), 0)
        Delete(extract)
        Delete(source)


if __name__ == "__main__":
    load_plugin(globals(), ('BuildTotallyOrderedMesh', 'ExtractTOMResolution'))
    result = unittest.main(argv=[sys.argv[0]], verbosity=2, exit=False).result
    sys.exit(0 if result.wasSuccessful() else 1)
