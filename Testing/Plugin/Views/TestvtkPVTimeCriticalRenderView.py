#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""vtkPVTimeCriticalRenderView, the Time-Critical Render View of the ParaView
plugin, through paraview.simple: its renderer, properties and their checks,
still and interactive renders, screenshots, cell selection against a Render
View, statistics and the resolution map.

Runs under pvbatch (`pvbatch --force-offscreen-rendering TestvtkPVTimeCriticalRenderView.py`).

Environment: TIMECRITICAL_PLUGIN (the built TimeCritical.so), PYTHONPATH with
the build tree's Python package (for the wrapped classes the test inspects)
and Testing/Python (timecritical_testing), TIMECRITICAL_TEST_OUTPUT_DIR for
scratch files.
"""

import os
import sys
import unittest

import numpy as np

from paraview.simple import *  # noqa: F401,F403

import timecritical  # noqa: F401  (wraps the renderer and mapper the view returns)
from timecritical import TimeCriticalViews  # noqa: F401  (the view and representation classes)

from timecritical_testing import (VIEW_SIZE, ViewTests, leaf_mapper, load_plugin,  # noqa: E402
                                  output_dir, screenshot, sphere)

load_plugin(globals(), ["BuildTotallyOrderedMesh"])
OUT = output_dir("TestvtkPVTimeCriticalRenderView")


class vtkPVTimeCriticalRenderViewTests(ViewTests, unittest.TestCase):
    def setUp(self):
        self.created = []

    def test_view_is_a_render_view_with_a_time_critical_renderer(self):
        view = self.view()
        server = view.GetClientSideObject()
        self.assertTrue(server.IsA("vtkPVTimeCriticalRenderView"))
        self.assertTrue(server.GetRenderer().IsA("vtkTimeCriticalRenderer"))
        # The other renderers of the view stay ordinary ones.
        self.assertFalse(server.GetNonCompositedRenderer().IsA("vtkTimeCriticalRenderer"))
        self.assertTrue(view.SMProxy.IsA("vtkSMRenderViewProxy"))

    def test_properties_defaults_and_forwarding(self):
        view = self.view()
        self.assertEqual(view.TargetFrameTime, 100.0)
        self.assertEqual(view.OptimizationTimeLimit, 1.0)
        self.assertEqual(view.Policy, "Active-Set Optimization")
        self.assertEqual(view.DegradationModel, "Hitchner")
        self.assertEqual(view.FullResolutionAtRest, 1)
        self.assertEqual(view.ShowStatistics, 0)
        self.assertEqual(view.DropObjectsWhenOverloaded, 1)
        view.TargetFrameTime = 40
        view.OptimizationTimeLimit = 0.5
        view.Policy = "Greedy LOD"
        view.DegradationModel = "Funkhouser"
        view.UseVelocity = 0
        view.RefinementTimeLimit = 5
        view.PixelThreshold = 2.5
        view.DropObjectsWhenOverloaded = 0
        renderer = view.GetClientSideObject().GetRenderer()
        self.assertAlmostEqual(renderer.GetTargetFrameTime(), 0.040)
        self.assertAlmostEqual(renderer.GetOptimizationTimeLimit(), 0.0005)
        self.assertEqual(renderer.GetPolicy(), renderer.GREEDY_LOD)
        self.assertEqual(renderer.GetDegradationFamily(), renderer.FUNKHOUSER)
        self.assertFalse(renderer.GetUseVelocity())
        self.assertAlmostEqual(renderer.GetRefinementTimeLimit(), 0.005)
        self.assertAlmostEqual(renderer.GetPixelThreshold(), 2.5)
        self.assertFalse(renderer.GetDropObjectsWhenOverloaded())
        self.assertFalse(view.GetClientSideObject().GetDropObjectsWhenOverloaded())
        # ParaView's LOD never switches on in this view.
        view.LODThreshold = 0.0
        self.assertGreater(view.GetClientSideObject().GetLODRenderingThreshold(), 1e300)

    def test_bad_values_are_rejected_with_a_message(self):
        view = self.view()
        renderer = view.GetClientSideObject().GetRenderer()
        view.TargetFrameTime = -5  # the renderer reports it and keeps 100 ms
        self.assertAlmostEqual(renderer.GetTargetFrameTime(), 0.1)

    def test_hysteresis_reaches_the_renderer_and_round_trips_a_state_file(self):
        view = self.view()
        renderer = view.GetClientSideObject().GetRenderer()
        self.assertEqual(view.Hysteresis, 0.0)
        self.assertEqual(renderer.GetHysteresis(), 0.0)
        view.Hysteresis = 0.35
        self.assertAlmostEqual(renderer.GetHysteresis(), 0.35)
        self.assertAlmostEqual(view.GetClientSideObject().GetHysteresis(), 0.35)
        view.Hysteresis = 1.5  # the renderer reports it and keeps 0.35
        self.assertAlmostEqual(renderer.GetHysteresis(), 0.35)
        view.Hysteresis = 0.35
        state = os.path.join(OUT, "hysteresis.pvsm")
        SaveState(state)
        ResetSession()
        self.created = []
        LoadState(state)
        loaded = [v for v in GetViews() if v.GetXMLName() == "TimeCriticalRenderView"]
        self.assertEqual(len(loaded), 1)
        self.assertAlmostEqual(loaded[0].Hysteresis, 0.35)
        self.assertAlmostEqual(loaded[0].GetClientSideObject().GetRenderer().GetHysteresis(), 0.35)
        ResetSession()

    def test_focus_properties_reach_the_renderer(self):
        view = self.view()
        renderer = view.GetClientSideObject().GetRenderer()
        self.assertEqual(view.FocusMode, "Fixed Point")
        self.assertEqual(view.FocusFalloff, "Degradation Model Default")
        view.FocusMode = "Cursor"
        view.FocusFalloff = "Linear"
        self.assertEqual(renderer.GetFocusMode(), renderer.CURSOR)
        self.assertEqual(renderer.GetFocusFalloff(), renderer.LINEAR)
        view.FocusMode = "Screen Center"
        view.FocusFalloff = "Reddy"
        self.assertEqual(renderer.GetFocusMode(), renderer.SCREEN_CENTER)
        self.assertEqual(renderer.GetFocusFalloff(), renderer.REDDY)
        self.assertEqual(view.GetClientSideObject().GetFocusMode(), renderer.SCREEN_CENTER)

    def test_hierarchy_cache_settings_apply_to_the_process_cache(self):
        view = self.view()
        server = view.GetClientSideObject()
        default_mib = server.GetHierarchyCacheMemoryLimitMiB()
        self.assertGreater(default_mib, 0)
        self.assertEqual(view.HierarchyCacheMemory, 0)  # 0: the process's limit, untouched
        self.assertEqual(view.HierarchyCacheDirectory, "")
        directory = os.path.join(OUT, "hierarchy-cache")
        try:
            view.HierarchyCacheMemory = 64
            self.assertEqual(server.GetHierarchyCacheMemoryLimitMiB(), 64)
            view.HierarchyCacheDirectory = directory
            self.assertEqual(server.GetHierarchyCacheDirectory(), directory)
            # A new view's defaults leave the process's settings as they are.
            other = self.view()
            self.assertEqual(other.GetClientSideObject().GetHierarchyCacheMemoryLimitMiB(), 64)
            self.assertEqual(other.GetClientSideObject().GetHierarchyCacheDirectory(), directory)
            source = self.new(sphere(61, (7, 0, 0)))  # content no other test shows
            self.new(Show(source, view))
            view.ResetCamera()
            Render(view)
            files = [name for name in os.listdir(directory) if name.endswith(".vtp")]
            self.assertEqual(len(files), 1)
            # The same surface in the other view is found in memory, not
            # built: a build would write its file again.
            os.remove(os.path.join(directory, files[0]))
            self.new(Show(source, other))
            other.ResetCamera()
            Render(other)
            self.assertEqual(os.listdir(directory), [])
            self.assertGreater(leaf_mapper(other).GetObjectNumberOfTriangles(0), 0)
        finally:
            view.HierarchyCacheDirectory = ""
            server.SetHierarchyCacheMemoryLimitMiB(default_mib)
        self.assertEqual(server.GetHierarchyCacheDirectory(), "")

    def test_still_render_is_full_resolution_and_equals_a_render_view(self):
        view = self.view(TargetFrameTime=1)
        source = self.new(sphere(150))
        rep = self.new(Show(source, view))
        ColorBy(rep, ("POINTS", "Normals", "X"))
        view.ResetCamera()
        Render(view)
        renderer = view.GetClientSideObject().GetRenderer()
        self.assertTrue(renderer.GetLastRenderWasStill())
        mapper = leaf_mapper(view)
        self.assertEqual(renderer.GetObjectTrianglesDrawn(), mapper.GetObjectNumberOfTriangles(0))
        image = screenshot(view, OUT, "still.png")

        reference = self.new_view("RenderView")
        ref_rep = self.new(Show(source, reference))
        ColorBy(ref_rep, ("POINTS", "Normals", "X"))
        reference.CameraPosition = view.CameraPosition
        reference.CameraFocalPoint = view.CameraFocalPoint
        reference.CameraViewUp = view.CameraViewUp
        reference.CameraParallelScale = view.CameraParallelScale
        expected = screenshot(reference, OUT, "still-reference.png")
        differing = np.count_nonzero(np.abs(image.astype(int) - expected.astype(int)).max(axis=2) > 8)
        # The TOM reorders the same triangles: the same image up to the
        # rasterizer's tie-breaking on shared edges.
        self.assertLess(differing, 0.002 * image.shape[0] * image.shape[1])

    def test_interactive_renders_are_budgeted(self):
        view = self.view(TargetFrameTime=30)
        source = self.new(sphere(400))  # 318K triangles: several times 30 ms here
        self.new(Show(source, view))
        view.ResetCamera()
        Render(view)
        renderer = view.GetClientSideObject().GetRenderer()
        full = renderer.GetObjectTrianglesDrawn()
        view.InteractiveRender()
        self.assertFalse(renderer.GetLastRenderWasStill())
        self.assertAlmostEqual(renderer.GetLastTargetFrameTime(), 0.030)
        self.assertLess(renderer.GetObjectTrianglesDrawn(), full)
        self.assertGreater(renderer.GetObjectTrianglesDrawn(), 0)
        self.assertLessEqual(renderer.GetPredictedFrameTime(), 0.030 * 1.0001)
        # With FullResolutionAtRest off, still renders are budgeted too.
        view.FullResolutionAtRest = 0
        Render(view)
        self.assertFalse(renderer.GetLastRenderWasStill())
        self.assertLess(renderer.GetObjectTrianglesDrawn(), full)

    def test_budgeted_screenshot_tiles_show_one_frame(self):
        view = self.view(TargetFrameTime=30, FullResolutionAtRest=0)
        spheres = [self.new(sphere(200, (2.5 * i, 0, 0))) for i in range(3)]
        group = self.new(GroupDatasets(Input=spheres))
        self.new(Show(group, view))
        view.ResetCamera()
        for _ in range(3):
            Render(view)
        renderer = view.GetClientSideObject().GetRenderer()
        mapper = leaf_mapper(view)
        planned = [mapper.GetObjectRenderedTriangles(i) for i in range(3)]
        self.assertLess(sum(planned), 3 * mapper.GetObjectNumberOfTriangles(0))
        # Twice the view's size: ParaView draws 2 x 2 tiles.
        SaveScreenshot(os.path.join(OUT, "tiles.png"), view,
                       ImageResolution=[2 * VIEW_SIZE[0], 2 * VIEW_SIZE[1]])
        self.assertEqual([mapper.GetObjectRenderedTriangles(i) for i in range(3)], planned)
        self.assertFalse(renderer.GetHoldResolutions())  # released after the capture
        Render(view)  # and planned again
        self.assertFalse(renderer.GetLastRenderWasStill())

    def test_statistics_text(self):
        view = self.view(ShowStatistics=1, TargetFrameTime=50)
        source = self.new(sphere(100))
        self.new(Show(source, view))
        view.InteractiveRender()
        view.InteractiveRender()
        text = view.GetClientSideObject().GetStatisticsText()
        self.assertIn("Last frame: target 50.0 ms", text)
        self.assertIn("Triangles:", text)
        self.assertIn("of 19,600", text)  # the sphere's triangles
        self.assertIn("Objects: 1 drawn, 0 culled", text)
        image = screenshot(view, OUT, "statistics.png")
        view.ShowStatistics = 0
        plain = screenshot(view, OUT, "no-statistics.png")
        # The text is drawn in the upper left corner.
        corner = (slice(0, VIEW_SIZE[1] // 5), slice(0, VIEW_SIZE[0] // 2))
        self.assertGreater(np.count_nonzero(image[corner] != plain[corner]), 100)

    def test_cell_selection_matches_a_render_view(self):
        """Area selection picks the same input cells as in a Render View."""
        source = self.new(sphere(60))

        def selected(view):
            self.new(Show(source, view))
            view.CameraPosition = [0.0, 0.0, 3.0]
            view.CameraFocalPoint = [0.0, 0.0, 0.0]
            view.CameraViewUp = [0.0, 1.0, 0.0]
            Render(view)
            SelectSurfaceCells(Rectangle=[200, 140, 280, 220], View=view, Modifier=None)
            extract = self.new(ExtractSelection(Input=source))
            cells = self.fetch(extract)
            ClearSelection(source)
            ids = cells.GetCellData().GetArray("vtkOriginalCellIds")
            self.assertIsNotNone(ids)
            return sorted(int(ids.GetValue(i)) for i in range(ids.GetNumberOfTuples()))

        reference = self.new_view("RenderView")
        expected = selected(reference)
        got = selected(self.view())
        self.assertGreater(len(expected), 20)
        self.assertEqual(got, expected)

    def test_color_by_resolution(self):
        # A target the sphere's coarsest level may exceed: drawn coarse, not
        # dropped (the map needs the object on screen).
        view = self.view(TargetFrameTime=5, FullResolutionAtRest=0, DropObjectsWhenOverloaded=0)
        source = self.new(sphere(300))
        self.new(Show(source, view))
        view.ResetCamera()
        colored = screenshot(view, OUT, "colored.png")
        view.ColorByResolution = 1
        grey = screenshot(view, OUT, "resolution-map.png")
        self.assertTrue(leaf_mapper(view).GetColorByResolution())
        self.assertGreater(np.count_nonzero(colored != grey), 1000)


if __name__ == "__main__":
    result = unittest.main(argv=[sys.argv[0]], exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
