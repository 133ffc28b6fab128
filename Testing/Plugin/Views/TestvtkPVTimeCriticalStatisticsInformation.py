#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""vtkPVTimeCriticalStatisticsInformation, the statistics of a
vtkPVTimeCriticalRenderView gathered for the client: what it copies from a
view (and from anything else), the objects an overloaded frame dropped,
which text it keeps when ranks' information is added, and the same text gathered through the session. The client-server
transfer (CopyToStream, CopyFromStream) is exercised by
Testing/Python/TestTimeCriticalViewClientServer.py.

Runs under pvbatch (`pvbatch --force-offscreen-rendering
TestvtkPVTimeCriticalStatisticsInformation.py`).

Environment: TIMECRITICAL_PLUGIN (the built TimeCritical.so), PYTHONPATH with
the build tree's Python package and Testing/Python (timecritical_testing).
"""

import sys
import unittest

from paraview import servermanager
from paraview.modules.vtkRemotingCore import vtkPVDataInformation
from paraview.simple import *  # noqa: F401,F403

import timecritical  # noqa: F401  (wraps the renderer the view returns)
from timecritical import TimeCriticalViews

from timecritical_testing import ViewTests, load_plugin, sphere  # noqa: E402

load_plugin(globals(), ["BuildTotallyOrderedMesh"])


def statistics_information():
    return TimeCriticalViews.vtkPVTimeCriticalStatisticsInformation()


class PVTimeCriticalStatisticsInformationTests(ViewTests, unittest.TestCase):
    def setUp(self):
        self.created = []

    def rendered_view(self, target_ms):
        """A view with statistics on, after two interactive renders of a sphere."""
        view = self.view(ShowStatistics=1, TargetFrameTime=target_ms)
        source = self.new(sphere(60))
        self.new(Show(source, view))
        view.InteractiveRender()
        view.InteractiveRender()
        return view

    def test_new_information_is_empty_and_root_only(self):
        info = statistics_information()
        self.assertEqual(info.GetText(), "")
        # Rank 0's text holds the ranks' summary: only the root is asked.
        self.assertTrue(info.GetRootOnly())

    def test_copies_the_local_statistics_of_a_view(self):
        server = self.rendered_view(50).GetClientSideObject()
        info = statistics_information()
        info.CopyFromObject(server)
        self.assertEqual(info.GetText(), server.GetLocalStatisticsText())
        self.assertIn("Last frame: target 50.0 ms", info.GetText())
        self.assertIn("Objects: 1 drawn, 0 culled", info.GetText())
        # Anything but a view gives no text, replacing the last one.
        info.CopyFromObject(server.GetRenderer())
        self.assertEqual(info.GetText(), "")
        info.CopyFromObject(server)
        info.CopyFromObject(None)
        self.assertEqual(info.GetText(), "")

    def test_counts_the_objects_an_overloaded_frame_dropped(self):
        # Six spheres in view, each one object; ten milliseconds per triangle
        # make even their coarsest levels cost several times the 100 ms target.
        view = self.view(ShowStatistics=1, TargetFrameTime=100)
        spheres = [self.new(sphere(16 + 4 * i, center=(3 * i, 0, 0))) for i in range(6)]
        group = self.new(GroupDatasets(Input=spheres))
        self.new(Show(group, view))
        view.ResetCamera()
        server = view.GetClientSideObject()
        renderer = server.GetRenderer()
        renderer.AutomaticCalibrationOff()
        renderer.OnlineCalibrationOff()
        renderer.SetCostCoefficients(0.002, 0.0, 1e-2, 0.0)
        renderer.SetNewObjectCostFactor(1.0)
        view.InteractiveRender()
        view.InteractiveRender()
        self.assertEqual(renderer.GetNumberOfObjects(), 6)
        dropped = renderer.GetNumberOfDroppedObjects()
        self.assertGreater(dropped, 0)
        self.assertLess(dropped, 6)
        self.assertLessEqual(renderer.GetPredictedFrameTime(), 0.100 * (1 + 1e-9))
        info = statistics_information()
        self.assertEqual(info.GetNumberOfDroppedObjects(), 0)
        info.CopyFromObject(server)
        self.assertEqual(info.GetNumberOfDroppedObjects(), dropped)
        self.assertIn("Objects: %d drawn, %d dropped, 0 culled" % (6 - dropped, dropped),
                      info.GetText())
        # Added information keeps the first one's count with its text.
        gathered = statistics_information()
        gathered.AddInformation(info)
        self.assertEqual(gathered.GetNumberOfDroppedObjects(), dropped)
        # The setting off: nothing dropped, the text as before.
        view.DropObjectsWhenOverloaded = 0
        view.InteractiveRender()
        info.CopyFromObject(server)
        self.assertEqual(info.GetNumberOfDroppedObjects(), 0)
        self.assertIn("Objects: 6 drawn, 0 culled", info.GetText())
        info.CopyFromObject(None)
        self.assertEqual(info.GetNumberOfDroppedObjects(), 0)

    def test_adding_keeps_the_first_text(self):
        first = statistics_information()
        first.CopyFromObject(self.rendered_view(50).GetClientSideObject())
        second = statistics_information()
        second.CopyFromObject(self.rendered_view(70).GetClientSideObject())
        self.assertIn("target 50.0 ms", first.GetText())
        self.assertIn("target 70.0 ms", second.GetText())
        gathered = statistics_information()
        gathered.AddInformation(statistics_information())  # an empty one: still empty
        self.assertEqual(gathered.GetText(), "")
        gathered.AddInformation(first)
        self.assertEqual(gathered.GetText(), first.GetText())
        gathered.AddInformation(second)
        self.assertEqual(gathered.GetText(), first.GetText())
        # Other information is ignored.
        other = statistics_information()
        other.AddInformation(vtkPVDataInformation())
        other.AddInformation(None)
        self.assertEqual(other.GetText(), "")

    def test_gathered_through_the_session(self):
        view = self.rendered_view(50)
        session = servermanager.ActiveConnection.Session
        info = statistics_information()
        session.GatherInformation(session.RENDER_SERVER, info, view.GetGlobalID())
        self.assertIn("Last frame: target 50.0 ms", info.GetText())
        self.assertEqual(info.GetText(), view.GetClientSideObject().GetLocalStatisticsText())


if __name__ == "__main__":
    result = unittest.main(argv=[sys.argv[0]], exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
