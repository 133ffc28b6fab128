#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""vtkTimeCriticalSurfaceRepresentation, the surface of the Time-Critical Render
View, through paraview.simple: multiblock and partitioned input as objects,
TOM input reused, visibility and opacity, build progress, hierarchies built
once and rebuilt on change, merge trees on request, block colours, opacities
and visibilities against a Render View.

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

    def block_images(self, name, scalars):
        """Screenshots of four spheres with a hidden, a coloured and a
        translucent block (the Multiblock Inspector's properties) in the
        Time-Critical Render View at rest and in a Render View; the
        Time-Critical view's representation."""
        spheres = [self.new(sphere(60, (2.5 * i, 0, 0))) for i in range(4)]
        group = self.new(GroupDatasets(Input=spheres))
        images = []
        reps = []
        views = [self.view(), self.new_view("RenderView")]
        for view in views:
            rep = self.new(Show(group, view))
            reps.append(rep)
            if scalars:
                ColorBy(rep, ("POINTS", "Normals", "X"))
            else:
                rep.ColorArrayName = ["POINTS", ""]
            rep.DiffuseColor = rep.AmbientColor = [0.85, 0.7, 0.45]
            rep.BlockSelectors = ["/Root/Sphere2", "/Root/Sphere3", "/Root/Sphere4"]
            rep.BlockColors = ["/Root/Sphere2", "1", "0.2", "0.2"]
            rep.BlockOpacities = ["/Root/Sphere3", "0.5"]
            Render(view)  # the first render resets the camera
            view.CameraPosition = [3.75, 2.0, 14.0]
            view.CameraFocalPoint = [3.75, 0.0, 0.0]
            view.CameraViewUp = [0.0, 1.0, 0.0]
            images.append(screenshot(view, OUT, "%s-%s.png" % (name, view.GetXMLName())))
        return images, reps[0], views[0]

    def assert_same_image(self, image, expected):
        # The still-render comparison's tolerance (TestvtkPVTimeCriticalRenderView).
        differing = np.count_nonzero(np.abs(image.astype(int) - expected.astype(int)).max(axis=2) > 8)
        self.assertLess(differing, 0.002 * image.shape[0] * image.shape[1])

    def test_block_colours_opacities_and_visibility_equal_a_render_view(self):
        (image, expected), rep, view = self.block_images("blocks", scalars=False)
        self.assert_same_image(image, expected)
        renderer = view.GetClientSideObject().GetRenderer()
        self.assertTrue(renderer.GetLastRenderWasStill())
        self.assertEqual(renderer.GetNumberOfObjects(), 4)
        self.assertEqual(renderer.GetNumberOfCulledObjects(), 1)  # the hidden block
        mapper = rep.GetClientSideObject().GetActiveRepresentation().GetMultiresolutionMapper()
        self.assertFalse(mapper.GetObjectVisibility(0))
        self.assertTrue(all(mapper.GetObjectVisibility(i) for i in range(1, 4)))
        self.assertEqual(mapper.GetObjectRenderedTriangles(0), 0)
        self.assertTrue(mapper.HasOpaqueGeometry())
        self.assertTrue(mapper.HasTranslucentPolygonalGeometry())
        # A new block colour rewrites that block's vertex colours: no build,
        # no vertex buffer rebuilt.
        surface = rep.GetClientSideObject().GetActiveRepresentation()
        builds = surface.GetHierarchyBuilder().GetNumberOfBuilds()
        vertex_builds = mapper.GetVertexBufferBuildCount()
        rep.BlockColors = ["/Root/Sphere2", "0.2", "1", "0.2"]
        view.StillRender()
        self.assertEqual(surface.GetHierarchyBuilder().GetNumberOfBuilds(), builds)
        self.assertEqual(mapper.GetVertexBufferBuildCount(), vertex_builds)
        greener = screenshot(view, OUT, "blocks-green.png")
        self.assertGreater(np.count_nonzero(greener[:, :, 1].astype(int) - image[:, :, 1] > 60), 500)
        # The attributes made the difference: without them, another image.
        rep.BlockSelectors = ["/"]
        rep.BlockColors = []
        rep.BlockOpacities = []
        plain = screenshot(view, OUT, "blocks-none.png")
        differing = np.count_nonzero(np.abs(image.astype(int) - plain.astype(int)).max(axis=2) > 8)
        self.assertGreater(differing, 0.02 * image.shape[0] * image.shape[1])
        self.assertTrue(mapper.GetObjectVisibility(0))
        self.assertFalse(mapper.HasTranslucentPolygonalGeometry())

    def test_block_colours_over_scalar_colouring_equal_a_render_view(self):
        (image, expected), _, _ = self.block_images("blocks-scalars", scalars=True)
        self.assert_same_image(image, expected)


if __name__ == "__main__":
    result = unittest.main(argv=[sys.argv[0]], exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
