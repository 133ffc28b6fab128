#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""vtkTimeCriticalSurfaceRepresentation, the surface of the Time-Critical Render
View, through paraview.simple: multiblock and partitioned input as objects,
TOM input reused, visibility and opacity, build progress, hierarchies built
once and rebuilt on change, merge trees on request.

Runs under pvbatch (`pvbatch --force-offscreen-rendering TestvtkTimeCriticalSurfaceRepresentation.py`).

Environment: TIMECRITICAL_PLUGIN (the built TimeCritical.so), PYTHONPATH with
the build tree's Python package (for the wrapped classes the test inspects)
and Testing/Python (timecritical_testing), TIMECRITICAL_TEST_OUTPUT_DIR for
scratch files.
"""

import sys
import unittest

import numpy as np

from paraview.simple import *  # noqa: F401,F403

import timecritical  # noqa: F401  (wraps the renderer and mapper the view returns)
from timecritical import TimeCriticalViews  # noqa: F401  (the view and representation classes)

from timecritical_testing import (ViewTests, leaf_mapper, load_plugin, output_dir,  # noqa: E402
                                  screenshot, sphere)

load_plugin(globals(), ["BuildTotallyOrderedMesh"])
OUT = output_dir("TestvtkTimeCriticalSurfaceRepresentation")


class vtkTimeCriticalSurfaceRepresentationTests(ViewTests, unittest.TestCase):
    def setUp(self):
        self.created = []

    def test_multiblock_leaves_are_objects_and_tom_input_is_reused(self):
        view = self.view()
        spheres = [self.new(sphere(60, (3 * i, 0, 0))) for i in range(4)]
        group = self.new(GroupDatasets(Input=spheres))
        self.new(Show(group, view))
        Render(view)
        renderer = view.GetClientSideObject().GetRenderer()
        self.assertEqual(renderer.GetNumberOfObjects(), 4)

        # Input that already carries a TOM is drawn as it is, not built again.
        view2 = self.view()
        tom = self.new(BuildTotallyOrderedMesh(Input=spheres[0]))
        rep = self.new(Show(tom, view2))
        Render(view2)
        built = rep.GetClientSideObject().GetActiveRepresentation()
        self.assertTrue(built.IsA("vtkTimeCriticalSurfaceRepresentation"))
        builder = built.GetHierarchyBuilder()
        self.assertEqual(builder.GetNumberOfBuiltLeaves(), 0)
        self.assertEqual(builder.GetNumberOfPassedLeaves(), 1)

    def test_partitioned_input_visibility_and_opacity(self):
        view = self.view()
        spheres = [self.new(sphere(40, (3 * i, 0, 0))) for i in range(3)]
        group = self.new(GroupDatasets(Input=spheres))
        partitioned = self.new(ConvertToPartitionedDataSetCollection(Input=group))
        rep = self.new(Show(partitioned, view))
        self.assertEqual(rep.GetXMLName(), "TimeCriticalGeometryRepresentation")
        view.ResetCamera()
        Render(view)
        renderer = view.GetClientSideObject().GetRenderer()
        self.assertEqual(renderer.GetNumberOfObjects(), 3)
        opaque = screenshot(view, OUT, "partitioned.png")
        rep.Opacity = 0.4
        translucent = screenshot(view, OUT, "partitioned-translucent.png")
        self.assertGreater(np.count_nonzero(opaque != translucent), 1000)
        self.assertEqual(renderer.GetNumberOfObjects(), 3)
        Hide(partitioned, view)
        Render(view)
        self.assertEqual(renderer.GetNumberOfObjects(), 0)
        Show(partitioned, view)
        Render(view)
        self.assertEqual(renderer.GetNumberOfObjects(), 3)

    def test_builds_report_progress(self):
        """ParaView's progress bar follows the representation's progress events."""
        view = self.view()
        spheres = [self.new(sphere(120, (3 * i, 0, 0))) for i in range(4)]
        group = self.new(GroupDatasets(Input=spheres))
        rep = self.new(Show(group, view))
        surface = rep.GetClientSideObject().GetActiveRepresentation()
        progress = []
        surface.AddObserver("ProgressEvent", lambda caller, event: progress.append(caller.GetProgress()))
        Render(view)
        inside = [p for p in progress if 0.0 < p < 1.0]
        self.assertGreaterEqual(len(inside), 4, progress)  # at least one per leaf built
        self.assertEqual(inside, sorted(inside))

    def test_hierarchy_is_built_once_and_rebuilt_on_change(self):
        view = self.view()
        source = self.new(sphere(80))
        rep = self.new(Show(source, view))
        Render(view)
        builder = rep.GetClientSideObject().GetActiveRepresentation().GetHierarchyBuilder()
        self.assertEqual(builder.GetNumberOfBuilds(), 1)
        # Colouring, opacity and a re-execution of ParaView's geometry filter
        # (new arrays, same content) build nothing.
        ColorBy(rep, ("POINTS", "Normals", "Y"))
        rep.Opacity = 0.5
        rep.NonlinearSubdivisionLevel = 2
        Render(view)
        self.assertEqual(builder.GetNumberOfReusedLeaves(), 1)
        self.assertEqual(builder.GetNumberOfBuilds(), 1)
        # A changed input is built again.
        source.ThetaResolution = 90
        Render(view)
        self.assertEqual(builder.GetNumberOfBuilds(), 2)
        self.assertEqual(leaf_mapper(view).GetObjectNumberOfTriangles(0), 2 * 90 * 78)
        # Merge trees on request: view-dependent objects.
        rep.Hierarchy = "Merge Tree (view-dependent)"
        Render(view)
        self.assertEqual(builder.GetNumberOfBuilds(), 3)
        self.assertTrue(view.GetClientSideObject().GetRenderer().GetObjectIsViewDependent(0))


if __name__ == "__main__":
    result = unittest.main(argv=[sys.argv[0]], exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
