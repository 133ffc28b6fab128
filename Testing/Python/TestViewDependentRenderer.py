#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""View-dependent refinement in vtkTimeCriticalRenderer, driven from Python.

sphere -> vtkMergeTreeBuilder (one object) next to vtkTOMBuilder copies (three
objects) in a vtkMultiBlockDataSet -> vtkMultiresolutionPolyDataMapper in a
vtkTimeCriticalRenderer; the refinement settings are made on the renderer from
Python, and the statistics read back after each frame.

Environment: PYTHONPATH must reach the `timecritical` package; rendering
needs an X display (run under xvfb-run -a).
"""

import math
import sys
import unittest

try:
    from timecritical import (vtkMergeTreeBuilder, vtkMultiresolutionPolyDataMapper,
                              vtkTOMBuilder, vtkTimeCriticalRenderer)
except ImportError as error:  # pragma: no cover - environment problem
    sys.stderr.write(
        "Cannot import the timecritical package (%s).\nSet PYTHONPATH to the "
        "build tree's lib/python3/dist-packages folder.\n" % error)
    raise

from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet, vtkPolyData
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderWindow
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL factory overrides)


def moved(source, dx, dy):
    copy = vtkPolyData()
    copy.DeepCopy(source)
    points = copy.GetPoints()
    for p in range(points.GetNumberOfPoints()):
        x, y, z = points.GetPoint(p)
        points.SetPoint(p, x + dx, y + dy, z)
    return copy


def scene_blocks():
    """Block 0: a merge tree; blocks 1-3: TOMs."""
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(32)
    tree = vtkMergeTreeBuilder()
    tree.SetInputConnection(sphere.GetOutputPort())
    tree.Update()
    tom = vtkTOMBuilder()
    tom.SetInputConnection(sphere.GetOutputPort())
    tom.Update()
    blocks = vtkMultiBlockDataSet()
    blocks.SetBlock(0, moved(tree.GetOutput(), 0.0, 0.0))
    for i, (dx, dy) in enumerate(((-1.5, 0.0), (1.5, 0.0), (0.0, 1.5))):
        blocks.SetBlock(i + 1, moved(tom.GetOutput(), dx, dy))
    return blocks


class ViewDependentRendererTest(unittest.TestCase):
    def setUp(self):
        self.mapper = vtkMultiresolutionPolyDataMapper()
        self.mapper.SetInputDataObject(scene_blocks())
        actor = vtkActor()
        actor.SetMapper(self.mapper)
        self.renderer = vtkTimeCriticalRenderer()
        self.renderer.AddActor(actor)
        self.window = vtkRenderWindow()
        self.window.SetOffScreenRendering(1)
        self.window.SetSize(200, 200)
        self.window.AddRenderer(self.renderer)
        camera = self.renderer.GetActiveCamera()
        camera.SetPosition(0.3, 0.4, 4.0)
        camera.SetFocalPoint(0.0, 0.3, 0.0)
        self.renderer.ResetCameraClippingRange()
        # Deterministic choices: pinned costs, nothing measured feeds back.
        r = self.renderer
        r.AutomaticCalibrationOff()
        r.OnlineCalibrationOff()
        r.SetCostCoefficients(2e-3, 0.0, 1e-6, 0.0)
        r.SetNewObjectCostFactor(1.0)
        r.UseVelocityOff()
        self.mapper.UpdateObjects()
        self.total = sum(self.mapper.GetObjectNumberOfTriangles(i)
                         for i in range(self.mapper.GetNumberOfObjects()))

    def test_settings_reach_the_mapper(self):
        r = self.renderer
        self.assertEqual(r.GetRefinementMode(), vtkTimeCriticalRenderer.BUDGET)
        r.SetRefinementModeToFixedAccuracy()
        r.SetPixelThreshold(3.0)
        r.BackFaceSimplificationOff()
        r.SilhouetteRefinementOn()
        r.SetSilhouetteFactor(0.4)
        r.HighlightRefinementOff()
        r.SetHighlightFactor(0.6)
        self.window.Render()
        m = self.mapper
        self.assertEqual(m.GetRefinementMode(), vtkMultiresolutionPolyDataMapper.FIXED_ACCURACY)
        self.assertEqual(m.GetPixelThreshold(), 3.0)
        self.assertFalse(m.GetBackFaceSimplification())
        self.assertTrue(m.GetSilhouetteRefinement())
        self.assertAlmostEqual(m.GetSilhouetteFactor(), 0.4)
        self.assertFalse(m.GetHighlightRefinement())
        self.assertAlmostEqual(m.GetHighlightFactor(), 0.6)
        self.assertTrue(r.GetObjectIsViewDependent(0))

        r.ViewDependentRefinementOff()
        self.window.Render()
        self.assertFalse(m.GetViewDependentRefinement())
        self.assertFalse(r.GetObjectIsViewDependent(0))
        self.assertEqual(r.GetRefinementTime(), 0.0)

    def test_statistics(self):
        r = self.renderer
        r.SetTargetFrameTime(10.0)
        self.window.Render()
        self.assertEqual(r.GetNumberOfObjects(), 4)
        self.assertTrue(r.GetObjectIsViewDependent(0))
        self.assertGreater(r.GetObjectSplits(0), 0)
        self.assertGreater(r.GetObjectRefinementTime(0), 0.0)
        self.assertGreater(r.GetRefinementTime(), 0.0)
        for o in range(4):
            self.assertEqual(r.GetObjectVertices(o), self.mapper.GetObjectRenderedVertices(o))
            self.assertEqual(r.GetObjectTriangles(o), self.mapper.GetObjectRenderedTriangles(o))
        for o in range(1, 4):
            self.assertFalse(r.GetObjectIsViewDependent(o))
            self.assertEqual(r.GetObjectSplits(o), 0)
        self.assertEqual(r.GetObjectSplits(4), -1)
        self.assertTrue(math.isnan(r.GetObjectRefinementTime(-1)))
        self.assertEqual(self.mapper.GetNumberOfDrawCalls(), 1)

        # Same view again: the front stays, and the refinement time, smoothed
        # (half the previous estimate + half the last frame's), is fixed cost.
        estimate = r.GetFixedFrameTime() - 2e-3
        refinement = r.GetRefinementTime()
        self.window.Render()
        self.assertEqual(r.GetObjectSplits(0) + r.GetObjectMerges(0), 0)
        self.assertAlmostEqual(r.GetFixedFrameTime(), 2e-3 + 0.5 * estimate + 0.5 * refinement,
                               delta=1e-12)

        # Moving closer (the sphere still whole in view) refines the front further.
        r.SetRefinementModeToFixedAccuracy()
        camera = self.renderer.GetActiveCamera()
        counts = []
        for distance in (12.0, 6.0):
            camera.SetPosition(0.0, 0.0, distance)
            camera.SetFocalPoint(0.0, 0.0, 0.0)
            self.renderer.ResetCameraClippingRange()
            self.window.Render()
            counts.append(r.GetObjectTriangles(0))
        self.assertGreater(counts[1], counts[0])

    def test_fixed_accuracy_ignores_the_target_budget_follows_it(self):
        r = self.renderer
        tight = 2e-3 + 1e-6 * 0.15 * self.total
        counts = {}
        for mode in (vtkTimeCriticalRenderer.FIXED_ACCURACY, vtkTimeCriticalRenderer.BUDGET):
            r.SetRefinementMode(mode)
            for target in (10.0, tight):
                r.SetTargetFrameTime(target)
                self.window.Render()
                self.window.Render()
                counts[(mode, target)] = r.GetObjectTriangles(0)
        fixed = vtkTimeCriticalRenderer.FIXED_ACCURACY
        budget = vtkTimeCriticalRenderer.BUDGET
        self.assertEqual(counts[(fixed, 10.0)], counts[(fixed, tight)])
        self.assertLess(counts[(budget, tight)], counts[(budget, 10.0)])
        self.assertLessEqual(r.GetPredictedFrameTime(), tight * (1 + 1e-9))

    def test_bad_settings_raise_errors_not_crashes(self):
        errors = []
        self.renderer.AddObserver(vtkCommand.ErrorEvent, lambda *args: errors.append(args))
        self.renderer.SetPixelThreshold(float("nan"))
        self.renderer.SetPixelThreshold(-1.0)
        self.renderer.SetPixelThreshold(float("inf"))
        self.renderer.SetSilhouetteFactor(0.0)
        self.renderer.SetHighlightFactor(1.5)
        self.assertEqual(len(errors), 5)
        self.assertEqual(self.renderer.GetPixelThreshold(), 1.0)
        self.assertEqual(self.renderer.GetSilhouetteFactor(), 0.25)
        self.assertEqual(self.renderer.GetHighlightFactor(), 0.5)

        mapper_errors = []
        self.mapper.AddObserver(vtkCommand.ErrorEvent, lambda *args: mapper_errors.append(args))
        self.mapper.SetPixelThreshold(float("nan"))
        self.mapper.SetSilhouetteFactor(-0.1)
        self.mapper.SetHighlightFactor(float("nan"))
        self.assertEqual(len(mapper_errors), 3)
        self.assertEqual(self.mapper.GetPixelThreshold(), 1.0)


if __name__ == "__main__":
    unittest.main(verbosity=2)
