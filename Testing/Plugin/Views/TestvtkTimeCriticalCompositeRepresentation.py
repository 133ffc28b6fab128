#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""vtkTimeCriticalCompositeRepresentation, the default representation of
polygonal data in the Time-Critical Render View, through paraview.simple: its
representation types, the time-critical surface behind the surface types, and
the fall-back to ParaView's own representation for other data.

Runs under pvbatch (`pvbatch --force-offscreen-rendering TestvtkTimeCriticalCompositeRepresentation.py`).

Environment: TIMECRITICAL_PLUGIN (the built TimeCritical.so), PYTHONPATH with
the build tree's Python package (for the wrapped classes the test inspects)
and Testing/Python (timecritical_testing), TIMECRITICAL_TEST_OUTPUT_DIR for
scratch files.
"""

import sys
import unittest

from paraview.simple import *  # noqa: F401,F403

import timecritical  # noqa: F401  (wraps the renderer and mapper the view returns)
from timecritical import TimeCriticalViews  # noqa: F401  (the view and representation classes)

from timecritical_testing import ViewTests, leaf_mapper, load_plugin, sphere  # noqa: E402

load_plugin(globals(), ["BuildTotallyOrderedMesh"])


def address(vtk_object):
    """The identity of a VTK object (one C++ object may get several Python wrappers)."""
    return vtk_object.GetAddressAsString("vtkObject") if vtk_object is not None else None


class vtkTimeCriticalCompositeRepresentationTests(ViewTests, unittest.TestCase):
    def setUp(self):
        self.created = []

    def test_surfaces_get_the_time_critical_representation(self):
        view = self.view()
        source = self.new(sphere(100))
        rep = self.new(Show(source, view))
        self.assertEqual(rep.GetXMLName(), "TimeCriticalGeometryRepresentation")
        self.assertEqual(rep.Representation, "Surface")
        Render(view)
        renderer = view.GetClientSideObject().GetRenderer()
        self.assertEqual(renderer.GetNumberOfObjects(), 1)
        mapper = leaf_mapper(view)
        self.assertTrue(mapper.IsA("vtkMultiresolutionPolyDataMapper"))
        self.assertTrue(mapper.GetObjectIsTOM(0))
        # The representation's types are ParaView's, and the surface ones stay
        # time-critical (Wireframe is drawn by the same mapper).
        types = rep.GetProperty("RepresentationTypesInfo")[::1]
        for name in ("Outline", "Points", "Wireframe", "Surface", "Surface With Edges"):
            self.assertIn(name, types)
        rep.Representation = "Wireframe"
        Render(view)
        self.assertEqual(renderer.GetNumberOfObjects(), 1)
        self.assertEqual(leaf_mapper(view).GetClassName(), "vtkMultiresolutionPolyDataMapper")
        rep.Representation = "Outline"
        Render(view)
        self.assertEqual(renderer.GetNumberOfObjects(), 0)  # ParaView's outline: no objects

    def test_non_surface_data_falls_back_to_the_standard_representation(self):
        view = self.view()
        wavelet = self.new(Wavelet())
        rep = self.new(Show(wavelet, view))
        self.assertNotEqual(rep.GetXMLName(), "TimeCriticalGeometryRepresentation")
        Render(view)  # draws, as a fixed cost, without objects
        self.assertEqual(view.GetClientSideObject().GetRenderer().GetNumberOfObjects(), 0)

    def test_surface_types_select_the_time_critical_surface(self):
        view = self.view()
        source = self.new(sphere(40))
        rep = self.new(Show(source, view))
        Render(view)
        composite = rep.GetClientSideObject()
        self.assertTrue(composite.IsA("vtkTimeCriticalCompositeRepresentation"))
        surface = composite.GetTimeCriticalSurface()
        self.assertIsNotNone(surface)
        self.assertTrue(surface.IsA("vtkTimeCriticalSurfaceRepresentation"))
        # Each surface key makes the one time-critical surface active, with its type.
        for key, kind in (("Points", 0), ("Wireframe", 1), ("Surface", 2), ("Surface With Edges", 3)):
            rep.Representation = key
            Render(view)
            self.assertEqual(address(composite.GetActiveRepresentation()), address(surface), key)
            self.assertEqual(surface.GetRepresentation(), kind, key)
        rep.Representation = "Outline"
        Render(view)
        self.assertNotEqual(address(composite.GetActiveRepresentation()), address(surface))
        self.assertEqual(surface.GetRepresentation(), 3)  # untouched by other types


if __name__ == "__main__":
    result = unittest.main(argv=[sys.argv[0]], exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
