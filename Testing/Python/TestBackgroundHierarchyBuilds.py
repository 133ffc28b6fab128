#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Background hierarchy builds in the Time-Critical Render View, through
paraview.simple: the view property (off by default), the representation
skipping its synchronous builder, the surface drawn at once and its
hierarchy swapped in after the view's WaitForHierarchies command, an
upstream edit built again, and the image at rest equal to the synchronous
path's.

Runs under pvbatch (`pvbatch --force-offscreen-rendering TestBackgroundHierarchyBuilds.py`).
Environment as TestTimeCriticalView.py.
"""

import sys
import unittest

from paraview.simple import *  # noqa: F401,F403

import timecritical  # noqa: F401  (wraps the renderer and mapper the view returns)
from timecritical import TimeCriticalViews  # noqa: F401  (the view and representation classes)

from timecritical_testing import (ViewTests, leaf_mapper, load_plugin, output_dir,  # noqa: E402
                                  screenshot, sphere)

load_plugin(globals(), ["BuildTotallyOrderedMesh"])
OUT = output_dir("background")


def surface_representation(display):
    """The vtkTimeCriticalSurfaceRepresentation behind a Show() result."""
    return display.GetClientSideObject().GetTimeCriticalSurface()


def pending(view):
    view.UpdatePropertyInformation()
    return view.GetProperty("NumberOfPendingHierarchies").GetElement(0)


class BackgroundHierarchyBuildTests(ViewTests, unittest.TestCase):
    def setUp(self):
        self.created = []

    def test_off_by_default(self):
        view = self.view()
        self.assertEqual(view.BackgroundHierarchyBuilds, 0)
        display = self.new(Show(self.new(sphere(40)), view))
        Render(view)
        self.assertEqual(surface_representation(display).GetHierarchyBuilder().GetNumberOfBuilds(), 1)
        self.assertTrue(leaf_mapper(view).GetObjectIsTOM(0))
        self.assertEqual(pending(view), 0)

    def test_drawn_at_once_then_swapped_in(self):
        view = self.view(BackgroundHierarchyBuilds=1)
        source = self.new(sphere(300))
        display = self.new(Show(source, view))
        Render(view)
        representation = surface_representation(display)
        self.assertTrue(representation.GetBackgroundBuilds())
        # The synchronous builder was skipped: the surface was drawn as extracted.
        self.assertEqual(representation.GetHierarchyBuilder().GetNumberOfBuilds(), 0)
        mapper = leaf_mapper(view)
        self.assertTrue(mapper.GetBackgroundBuilds())
        triangles = mapper.GetObjectNumberOfTriangles(0)
        self.assertEqual(mapper.GetRenderedTriangles(), triangles)

        view.SMProxy.InvokeCommand("WaitForHierarchies")
        self.assertEqual(pending(view), 0)
        self.assertTrue(mapper.GetObjectIsTOM(0))
        self.assertEqual(mapper.GetNumberOfSwappedHierarchies(), 1)
        background = screenshot(view, OUT, "background.png")

        # An upstream edit: the new surface is drawn without a build in the
        # representation, and built in the background again.
        source.ThetaResolution = 200
        Render(view)
        self.assertEqual(representation.GetHierarchyBuilder().GetNumberOfBuilds(), 0)
        view.SMProxy.InvokeCommand("WaitForHierarchies")
        Render(view)
        self.assertTrue(mapper.GetObjectIsTOM(0))
        self.assertNotEqual(mapper.GetObjectNumberOfTriangles(0), triangles)
        self.assertEqual(mapper.GetNumberOfSwappedHierarchies(), 2)

        # At rest the image is the synchronous path's (full resolution either way).
        source.ThetaResolution = 300
        view.BackgroundHierarchyBuilds = 0
        Render(view)
        self.assertFalse(representation.GetBackgroundBuilds())
        self.assertFalse(mapper.GetBackgroundBuilds())
        self.assertTrue(mapper.GetObjectIsTOM(0))
        synchronous = screenshot(view, OUT, "synchronous.png")
        differing = (abs(background.astype(int) - synchronous.astype(int)).max(axis=2) > 12).mean()
        self.assertLess(differing, 0.002)


if __name__ == "__main__":
    result = unittest.main(argv=[sys.argv[0]], exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
