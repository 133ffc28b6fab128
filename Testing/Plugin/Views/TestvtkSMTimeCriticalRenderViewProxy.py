#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""vtkSMTimeCriticalRenderViewProxy, the proxy of the Time-Critical Render
View: the view's defaults in the ParaView GUI (BackgroundHierarchyBuilds on),
given through vtkSMSettings below the site and user settings, and only there.

Under pvbatch the GUI defaults are off: a new view keeps the XML default. The
test then adds them as the GUI does (AddGUIDefaults, once per process) and
checks that new views take them, that the server object gets the value,
that higher-priority settings (a site or user default) win, that a script's
own value and a state file's value win, and that views made before keep
theirs. The GUI itself is tested by ParaViewGUI.BackgroundHierarchyBuilds
(Testing/Python/TestBackgroundHierarchyBuildsGUI.py).

Runs under pvbatch; environment as TestvtkPVTimeCriticalRenderView.py.
"""

import os
import sys
import unittest

from paraview.simple import *  # noqa: F401,F403
from paraview.modules.vtkRemotingServerManager import vtkSMSettings

import timecritical  # noqa: F401
from timecritical import TimeCriticalViews

from timecritical_testing import ViewTests, load_plugin, output_dir  # noqa: E402

load_plugin(globals(), [])
OUT = output_dir("TestvtkSMTimeCriticalRenderViewProxy")
Proxy = TimeCriticalViews.vtkSMTimeCriticalRenderViewProxy


class vtkSMTimeCriticalRenderViewProxyTests(ViewTests, unittest.TestCase):
    def setUp(self):
        self.created = []

    def test_gui_defaults_only_where_added(self):
        # pvbatch is not the GUI: no GUI defaults, the XML default (off).
        self.assertFalse(Proxy.IsGUIApplication())
        before = self.view()
        self.assertTrue(before.SMProxy.IsA("vtkSMTimeCriticalRenderViewProxy"))
        self.assertTrue(before.SMProxy.IsA("vtkSMRenderViewProxy"))
        self.assertEqual(before.BackgroundHierarchyBuilds, 0)
        self.assertFalse(before.GetClientSideObject().GetBackgroundHierarchyBuilds())
        self.assertEqual(Proxy.GetGUIDefaultsPriority(), 0.0)

        # What the GUI's first view proxy does: once per process.
        self.assertTrue(Proxy.AddGUIDefaults())
        self.assertFalse(Proxy.AddGUIDefaults())
        view = self.view()
        self.assertEqual(view.BackgroundHierarchyBuilds, 1)
        self.assertTrue(view.GetClientSideObject().GetBackgroundHierarchyBuilds())
        # A view made before keeps its value; a script's own value wins.
        self.assertEqual(before.BackgroundHierarchyBuilds, 0)
        self.assertEqual(self.new(CreateView("TimeCriticalRenderView",
                                             BackgroundHierarchyBuilds=0)).BackgroundHierarchyBuilds, 0)
        # Only this view: ParaView's Render View has no such property.
        render_view = self.new(CreateView("RenderView"))
        self.assertIsNone(render_view.GetProperty("BackgroundHierarchyBuilds"))

        # A state file's value wins over the defaults.
        view.BackgroundHierarchyBuilds = 0
        state = os.path.join(OUT, "background-off.pvsm")
        SaveState(state)
        ResetSession()
        self.created = []
        LoadState(state)
        loaded = [v for v in GetViews() if v.GetXMLName() == "TimeCriticalRenderView"]
        self.assertTrue(loaded)
        self.assertEqual([v.BackgroundHierarchyBuilds for v in loaded], [0] * len(loaded))
        ResetSession()

        # Settings of a higher priority (site: 1, user: highest) win.
        settings = vtkSMSettings.GetInstance()
        self.assertTrue(settings.AddCollectionFromString(
            '{ "views" : { "TimeCriticalRenderView" : { "BackgroundHierarchyBuilds" : 0 } } }', 1.0))
        self.assertEqual(self.view().BackgroundHierarchyBuilds, 0)


if __name__ == "__main__":
    result = unittest.main(argv=[sys.argv[0]], exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
