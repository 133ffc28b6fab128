#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""vtkTimeCriticalRenderer driven from a plain VTK Python pipeline.

sphere -> vtkTOMBuilder -> copies in a vtkMultiBlockDataSet ->
vtkMultiresolutionPolyDataMapper in a vtkTimeCriticalRenderer, with the
settings made from Python and the statistics read back after each frame.

Environment: PYTHONPATH must reach the `timecritical` package; rendering
needs an X display (run under xvfb-run -a).
"""

import math
import sys
import unittest

try:
    from timecritical import (vtkMultiresolutionPolyDataMapper, vtkTOMBuilder,
                              vtkTimeCriticalRenderer)
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


def sphere_grid(k):
    """k x k TOM spheres, 3 units apart."""
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(32)
    builder = vtkTOMBuilder()
    builder.SetInputConnection(sphere.GetOutputPort())
    builder.Update()
    tom = builder.GetOutput()
    blocks = vtkMultiBlockDataSet()
    for j in range(k):
        for i in range(k):
            copy = vtkPolyData()
            copy.DeepCopy(tom)
            points = copy.GetPoints()
            for p in range(points.GetNumberOfPoints()):
                x, y, z = points.GetPoint(p)
                points.SetPoint(p, x + 3.0 * i, y + 3.0 * j, z)
            blocks.SetBlock(j * k + i, copy)
    return blocks


class TimeCriticalRendererTest(unittest.TestCase):
    def setUp(self):
        self.mapper = vtkMultiresolutionPolyDataMapper()
        self.mapper.SetInputDataObject(sphere_grid(3))
        actor = vtkActor()
        actor.SetMapper(self.mapper)
        self.renderer = vtkTimeCriticalRenderer()
        self.renderer.AddActor(actor)
        self.window = vtkRenderWindow()
        self.window.SetOffScreenRendering(1)
        self.window.SetSize(200, 200)
        self.window.AddRenderer(self.renderer)
        self.renderer.ResetCamera()
        self.mapper.UpdateObjects()
        self.total = sum(self.mapper.GetObjectNumberOfTriangles(i)
                         for i in range(self.mapper.GetNumberOfObjects()))

    def test_settings_and_statistics(self):
        r = self.renderer
        r.AutomaticCalibrationOff()
        r.OnlineCalibrationOff()
        r.SetCostCoefficients(1e-3, 0.0, 1e-6, 0.0)
        r.SetTargetFrameTime(1e-3 + 0.25 * self.total * 1e-6)
        r.SetOptimizationTimeLimit(0.002)
        r.SetPolicyToActiveSet()
        r.SetFocusPoint(0.5, 0.5)
        r.SetDisplayResolution(1920, 1080)
        self.window.Render()
        self.window.Render()
        self.assertEqual(r.GetPolicyAsString(), "active-set")
        self.assertEqual(r.GetNumberOfObjects(), 9)
        self.assertEqual(r.GetNumberOfCulledObjects(), 0)
        self.assertLessEqual(r.GetPredictedFrameTime(), r.GetTargetFrameTime() * (1 + 1e-9))
        drawn = r.GetObjectTrianglesDrawn()
        self.assertGreater(drawn, 0.2 * self.total)
        self.assertLess(drawn, 0.3 * self.total)
        self.assertEqual(drawn, sum(r.GetObjectTriangles(i) for i in range(9)))
        self.assertEqual(r.GetTrianglesDrawn(), drawn)
        self.assertTrue(all(0.0 < r.GetObjectResolution(i) <= 1.0 for i in range(9)))
        self.assertGreater(r.GetMeasuredFrameTime(), 0.0)
        self.assertGreaterEqual(r.GetOptimizationTime(), 0.0)
        self.assertGreater(r.GetOptimizationIterations(), 0)
        self.assertEqual(self.mapper.GetNumberOfDrawCalls(), 1)

        r.StillRender()
        self.assertTrue(r.GetLastRenderWasStill())
        self.assertEqual(r.GetObjectTrianglesDrawn(), self.total)
        self.assertEqual(r.GetLastTargetFrameTime(), math.inf)

        # With the interactors' rates, the target is 1 / DesiredUpdateRate;
        # GetTargetFrameTime() stays the setting.
        r.UseDesiredUpdateRateOn()
        self.window.SetDesiredUpdateRate(30.0)
        self.assertAlmostEqual(r.GetEffectiveTargetFrameTime(), 1.0 / 30.0, delta=1e-15)
        self.window.Render()
        self.assertAlmostEqual(r.GetLastTargetFrameTime(), 1.0 / 30.0, delta=1e-15)
        self.assertNotEqual(r.GetTargetFrameTime(), r.GetEffectiveTargetFrameTime())
        self.window.SetDesiredUpdateRate(0.0001)
        self.assertEqual(r.GetEffectiveTargetFrameTime(), math.inf)

        # No optimization time: a closed-form allocation, not the coarsest one.
        r.UseDesiredUpdateRateOff()
        r.SetOptimizationTimeLimit(0.0)
        self.window.Render()
        self.assertEqual(r.GetOptimizationIterations(), 0)
        self.assertGreater(r.GetObjectTrianglesDrawn(), 0.2 * self.total)

    def test_bad_settings_raise_errors_not_crashes(self):
        errors = []
        self.renderer.AddObserver(vtkCommand.ErrorEvent, lambda *args: errors.append(args))
        self.renderer.SetTargetFrameTime(float("nan"))
        self.renderer.SetTargetFrameTime(-1.0)
        self.renderer.SetPolicy(99)
        self.assertEqual(len(errors), 3)
        self.assertEqual(self.renderer.GetTargetFrameTime(), 0.1)
        self.assertEqual(self.renderer.GetPolicy(), vtkTimeCriticalRenderer.ACTIVE_SET)

    def test_calibration_from_python(self):
        self.assertTrue(self.renderer.Calibrate())
        self.assertTrue(self.renderer.GetCalibrated())
        cost = self.renderer.GetTriangleCost()
        self.assertTrue(math.isfinite(cost) and 0.0 < cost < 1e-3)
        self.assertGreater(self.renderer.GetCalibrationRenders(), 0)
        self.assertGreater(self.renderer.GetCalibrationTime(), 0.0)


if __name__ == "__main__":
    unittest.main(verbosity=2)
