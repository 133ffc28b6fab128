#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""TimeCriticalStatisticsText, the statistics overlay of the Time-Critical
Render View: the text of a view's renderer after known frames (an
interactive one, a still one, one with nothing in view), line by line,
against the renderer's own figures formatted as the overlay documents them
(one decimal for the times and the share, thousands separators for counts,
two decimals for the optimizer's time). The rank summary, a sixth line shown
only when several ranks rendered the frame, is absent here (one process).

Runs under pvbatch (`pvbatch --force-offscreen-rendering
TestTimeCriticalStatisticsText.py`).

Environment: TIMECRITICAL_PLUGIN (the built TimeCritical.so), PYTHONPATH with
the build tree's Python package and Testing/Python (timecritical_testing).
"""

import math
import sys
import unittest

from paraview.simple import *  # noqa: F401,F403

import timecritical  # noqa: F401  (wraps the renderer the view returns)
from timecritical import TimeCriticalViews  # noqa: F401  (wraps the view)

from timecritical_testing import ViewTests, load_plugin, sphere  # noqa: E402

load_plugin(globals(), ["BuildTotallyOrderedMesh"])


def full_triangles(renderer):
    """Triangles of all the renderer's objects at full resolution."""
    return sum(renderer.GetObjectActor(i).GetMapper().GetObjectNumberOfTriangles(renderer.GetObjectIndex(i))
               for i in range(renderer.GetNumberOfObjects()))


def expected_lines(renderer):
    """The overlay's lines for the renderer's last frame, from its figures."""
    if renderer.GetLastRenderWasStill():
        first = "Last frame: still, full resolution"
    else:
        first = "Last frame: target %.1f ms, predicted %.1f ms" % (
            renderer.GetLastTargetFrameTime() * 1000.0, renderer.GetPredictedFrameTime() * 1000.0)
    measured = renderer.GetMeasuredFrameTime()
    total = full_triangles(renderer)
    drawn = renderer.GetObjectTrianglesDrawn()
    culled = renderer.GetNumberOfCulledObjects()
    triangles = "Triangles: {:,} of {:,}".format(drawn, total)
    if total > 0:
        triangles += " (%.1f%%)" % (100.0 * drawn / total)
    return [
        first,
        "Measured: %.1f ms" % (measured * 1000.0) if math.isfinite(measured) else "Measured: -",
        triangles,
        "Objects: {:,} drawn, {:,} culled".format(renderer.GetNumberOfObjects() - culled, culled),
        "Optimizer: %.2f ms, %d iterations" % (renderer.GetOptimizationTime() * 1000.0,
                                               renderer.GetOptimizationIterations()),
    ]


class TimeCriticalStatisticsTextTests(ViewTests, unittest.TestCase):
    def setUp(self):
        self.created = []

    def view_of(self, *sources, **properties):
        view = self.view(ShowStatistics=1, **properties)
        for source in sources:
            self.new(Show(self.new(source), view))
        return view

    def lines(self, view):
        text = view.GetClientSideObject().GetLocalStatisticsText()
        self.assertEqual(text, view.GetClientSideObject().GetStatisticsText())
        return text.split("\n")

    def test_interactive_frame(self):
        view = self.view_of(sphere(100), TargetFrameTime=50)
        view.InteractiveRender()
        view.InteractiveRender()
        renderer = view.GetClientSideObject().GetRenderer()
        lines = self.lines(view)
        self.assertEqual(lines, expected_lines(renderer))
        self.assertEqual(len(lines), 5)  # one process: no rank summary
        self.assertTrue(lines[0].startswith("Last frame: target 50.0 ms, predicted "))
        self.assertTrue(lines[1].startswith("Measured: "))
        self.assertRegex(lines[2], r"^Triangles: [0-9,]+ of 19,600 \([0-9]+\.[0-9]%\)$")
        self.assertEqual(lines[3], "Objects: 1 drawn, 0 culled")
        self.assertRegex(lines[4], r"^Optimizer: [0-9]+\.[0-9]{2} ms, [0-9]+ iterations$")
        self.assertGreater(renderer.GetObjectTrianglesDrawn(), 0)

    def test_still_frame_is_full_resolution(self):
        view = self.view_of(sphere(100), TargetFrameTime=50)
        view.StillRender()
        renderer = view.GetClientSideObject().GetRenderer()
        self.assertTrue(renderer.GetLastRenderWasStill())
        lines = self.lines(view)
        self.assertEqual(lines, expected_lines(renderer))
        self.assertEqual(lines[0], "Last frame: still, full resolution")
        self.assertEqual(lines[2], "Triangles: 19,600 of 19,600 (100.0%)")

    def test_nothing_in_view(self):
        view = self.view_of(sphere(100), TargetFrameTime=50)
        view.InteractiveRender()
        view.CameraPosition = [0, 0, -5]  # looking away from the sphere
        view.CameraFocalPoint = [0, 0, -10]
        view.CameraViewUp = [0, 1, 0]
        view.InteractiveRender()
        view.InteractiveRender()
        renderer = view.GetClientSideObject().GetRenderer()
        lines = self.lines(view)
        self.assertEqual(lines, expected_lines(renderer))
        self.assertTrue(lines[0].startswith("Last frame: target 50.0 ms, predicted "))
        self.assertEqual(lines[2:], ["Triangles: 0 of 0",  # no share of nothing
                                     "Objects: 0 drawn, 0 culled",
                                     "Optimizer: 0.00 ms, 0 iterations"])


if __name__ == "__main__":
    result = unittest.main(argv=[sys.argv[0]], exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
