#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The Time-Critical Render View of the ParaView plugin in whole sessions,
through paraview.simple: a state file saved and loaded, with the view's
settings (DropObjectsWhenOverloaded among them). The view's and the
representations' own tests are in Testing/Plugin/Views/Test<Class>.py.

Runs under pvbatch (`pvbatch --force-offscreen-rendering TestTimeCriticalView.py`).

Environment: TIMECRITICAL_PLUGIN (the built TimeCritical.so), PYTHONPATH with
the build tree's Python package (for the wrapped classes the test inspects),
TIMECRITICAL_TEST_OUTPUT_DIR for scratch files (state files, screenshots).
"""

import os
import sys
import unittest

from paraview.simple import *  # noqa: F401,F403

import timecritical  # noqa: F401  (wraps the renderer and mapper the view returns)
from timecritical import TimeCriticalViews  # noqa: F401  (the view and representation classes)

from timecritical_testing import ViewTests, load_plugin, output_dir, sphere  # noqa: E402

load_plugin(globals(), ["BuildTotallyOrderedMesh"])
OUT = output_dir("view")


class TimeCriticalViewTests(ViewTests, unittest.TestCase):
    def setUp(self):
        self.created = []

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

    def test_drop_objects_when_overloaded_round_trips(self):
        view = self.view()
        renderer = view.GetClientSideObject().GetRenderer()
        self.assertEqual(view.DropObjectsWhenOverloaded, 1)  # on by default
        self.assertTrue(renderer.GetDropObjectsWhenOverloaded())
        view.DropObjectsWhenOverloaded = 0
        source = self.new(sphere(30))
        self.new(Show(source, view))
        Render(view)
        self.assertFalse(renderer.GetDropObjectsWhenOverloaded())  # forwarded to the renderer
        state = os.path.join(OUT, "drop.pvsm")
        SaveState(state)
        ResetSession()
        self.created = []
        LoadState(state)
        views = [v for v in GetViews() if v.GetXMLName() == "TimeCriticalRenderView"]
        self.assertEqual(len(views), 1)
        restored = views[0]
        self.created.append(restored)
        self.assertEqual(restored.DropObjectsWhenOverloaded, 0)
        restored_renderer = restored.GetClientSideObject().GetRenderer()
        self.assertFalse(restored_renderer.GetDropObjectsWhenOverloaded())
        restored.DropObjectsWhenOverloaded = 1
        Render(restored)
        self.assertTrue(restored_renderer.GetDropObjectsWhenOverloaded())


if __name__ == "__main__":
    result = unittest.main(argv=[sys.argv[0]], exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
