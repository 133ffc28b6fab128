#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The Time-Critical Render View of the ParaView plugin, through paraview.simple.

Runs under pvbatch (`pvbatch --force-offscreen-rendering TestTimeCriticalView.py`).

Environment: TIMECRITICAL_PLUGIN (the built TimeCritical.so), PYTHONPATH with
the build tree's Python package (for the wrapped classes the test inspects),
TIMECRITICAL_TEST_OUTPUT_DIR for scratch files (state files, screenshots).
"""

import os
import sys
import unittest

import numpy as np

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet, vtkPolyData

import timecritical  # noqa: F401  (wraps the renderer and mapper the view returns)
from timecritical import TimeCriticalViews  # noqa: F401  (the view and representation classes)

from timecritical_testing import ProxyTests, load_plugin, output_dir, read_png  # noqa: E402

load_plugin(globals(), ["BuildTotallyOrderedMesh"])
OUT = output_dir("view")

SIZE = [480, 360]


def sphere(resolution=200, center=(0, 0, 0)):
    return Sphere(ThetaResolution=resolution, PhiResolution=resolution, Center=list(center))


def screenshot(view, name):
    path = os.path.join(OUT, name)
    SaveScreenshot(path, view, ImageResolution=SIZE)
    return read_png(path)


def leaf_mapper(view):
    """The multiresolution mapper of the first object the view's renderer drew."""
    renderer = view.GetClientSideObject().GetRenderer()
    return renderer.GetObjectActor(0).GetMapper()


class TimeCriticalViewTests(ProxyTests, unittest.TestCase):
    def setUp(self):
        self.created = []

    def view(self, **properties):
        view = self.new(CreateView("TimeCriticalRenderView"))
        view.ViewSize = SIZE
        view.OrientationAxesVisibility = 0
        for key, value in properties.items():
            setattr(view, key, value)
        return view

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
        view.TargetFrameTime = 40
        view.OptimizationTimeLimit = 0.5
        view.Policy = "Greedy LOD"
        view.DegradationModel = "Funkhouser"
        view.UseVelocity = 0
        view.RefinementTimeLimit = 5
        view.PixelThreshold = 2.5
        renderer = view.GetClientSideObject().GetRenderer()
        self.assertAlmostEqual(renderer.GetTargetFrameTime(), 0.040)
        self.assertAlmostEqual(renderer.GetOptimizationTimeLimit(), 0.0005)
        self.assertEqual(renderer.GetPolicy(), renderer.GREEDY_LOD)
        self.assertEqual(renderer.GetDegradationFamily(), renderer.FUNKHOUSER)
        self.assertFalse(renderer.GetUseVelocity())
        self.assertAlmostEqual(renderer.GetRefinementTimeLimit(), 0.005)
        self.assertAlmostEqual(renderer.GetPixelThreshold(), 2.5)
        # ParaView's LOD never switches on in this view.
        view.LODThreshold = 0.0
        self.assertGreater(view.GetClientSideObject().GetLODRenderingThreshold(), 1e300)

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
        image = screenshot(view, "still.png")

        reference = self.new(CreateView("RenderView"))
        reference.ViewSize = SIZE
        reference.OrientationAxesVisibility = 0
        ref_rep = self.new(Show(source, reference))
        ColorBy(ref_rep, ("POINTS", "Normals", "X"))
        reference.CameraPosition = view.CameraPosition
        reference.CameraFocalPoint = view.CameraFocalPoint
        reference.CameraViewUp = view.CameraViewUp
        reference.CameraParallelScale = view.CameraParallelScale
        expected = screenshot(reference, "still-reference.png")
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
                       ImageResolution=[2 * SIZE[0], 2 * SIZE[1]])
        self.assertEqual([mapper.GetObjectRenderedTriangles(i) for i in range(3)], planned)
        self.assertFalse(renderer.GetHoldResolutions())  # released after the capture
        Render(view)  # and planned again
        self.assertFalse(renderer.GetLastRenderWasStill())

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

        reference = self.new(CreateView("RenderView"))
        reference.ViewSize = SIZE
        reference.OrientationAxesVisibility = 0
        expected = selected(reference)
        got = selected(self.view())
        self.assertGreater(len(expected), 20)
        self.assertEqual(got, expected)

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
        image = screenshot(view, "statistics.png")
        view.ShowStatistics = 0
        plain = screenshot(view, "no-statistics.png")
        # The text is drawn in the upper left corner.
        corner = (slice(0, SIZE[1] // 5), slice(0, SIZE[0] // 2))
        self.assertGreater(np.count_nonzero(image[corner] != plain[corner]), 100)

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
        opaque = screenshot(view, "partitioned.png")
        rep.Opacity = 0.4
        translucent = screenshot(view, "partitioned-translucent.png")
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

    def test_color_by_resolution(self):
        view = self.view(TargetFrameTime=5, FullResolutionAtRest=0)
        source = self.new(sphere(300))
        self.new(Show(source, view))
        view.ResetCamera()
        colored = screenshot(view, "colored.png")
        view.ColorByResolution = 1
        grey = screenshot(view, "resolution-map.png")
        self.assertTrue(leaf_mapper(view).GetColorByResolution())
        self.assertGreater(np.count_nonzero(colored != grey), 1000)

    def test_state_file_round_trip(self):
        view = self.view(TargetFrameTime=42, ShowStatistics=1, Policy="Feedback")
        source = self.new(sphere(50))
        self.new(Show(source, view))
        Render(view)
        state = os.path.join(OUT, "view.pvsm")
        SaveState(state)
        ResetSession()  # the plugin stays loaded: the new session knows its proxies
        self.created = []
        LoadState(state)
        views = [v for v in GetViews() if v.GetXMLName() == "TimeCriticalRenderView"]
        self.assertEqual(len(views), 1)
        restored = views[0]
        self.created.append(restored)
        self.assertEqual(restored.TargetFrameTime, 42.0)
        self.assertEqual(restored.ShowStatistics, 1)
        self.assertEqual(restored.Policy, "Feedback")
        reps = [r for r in GetRepresentations().values() if r.GetXMLName() ==
                "TimeCriticalGeometryRepresentation"]
        self.assertEqual(len(reps), 1)
        Render(restored)
        self.assertEqual(restored.GetClientSideObject().GetRenderer().GetNumberOfObjects(), 1)

    def test_bad_values_are_rejected_with_a_message(self):
        view = self.view()
        renderer = view.GetClientSideObject().GetRenderer()
        view.TargetFrameTime = -5  # the renderer reports it and keeps 100 ms
        self.assertAlmostEqual(renderer.GetTargetFrameTime(), 0.1)


if __name__ == "__main__":
    result = unittest.main(argv=[sys.argv[0]], exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
