#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""vtkSMExtractViewDependentMeshProxy, the proxy of Extract View-Dependent
Mesh: state files and scripts written before the filter took the
common numbering of the refinement modes (0 = budget, 1 = fixed accuracy) still
load in the mode they were saved in.

Testing/Data/State holds two ParaView 5.11 state files written with the former
numbering (a sphere, Build Merge Tree, Extract View-Dependent Mesh with
PixelThreshold 2 and TriangleBudget 200): RefinementMode = 0 was Fixed Accuracy,
RefinementMode = 1 the Triangle Budget. Loading each must give the filter that
mode, and its output must be the output of that mode. Run under pvbatch, with
PYTHONPATH holding the build tree's package and TIMECRITICAL_PLUGIN the plugin.
"""

import os
import sys
import unittest

# Star import: LoadPlugin(ns=globals()) adds the plugin's filters to this namespace.
from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

import timecritical  # noqa: F401  (wraps the filter's client-side object)
from timecritical import vtkExtractViewDependentMesh

from timecritical_testing import load_plugin, output_dir  # noqa: E402

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir, "Data", "State")
FIXED = vtkExtractViewDependentMesh.FIXED_ACCURACY
BUDGET = vtkExtractViewDependentMesh.BUDGET

load_plugin(globals(), ["ExtractViewDependentMesh", "BuildMergeTree"])


def triangles(proxy):
    proxy.UpdatePipeline()
    return servermanager.Fetch(proxy).GetNumberOfPolys()


class LegacyRefinementModeStateTests(unittest.TestCase):
    def setUp(self):
        ResetSession()

    def load(self, name):
        LoadState(os.path.join(DATA, name))
        extract = FindSource("ExtractViewDependentMesh1")
        self.assertIsNotNone(extract)
        return extract

    def reference(self, mode):
        """Triangles of the same pipeline built now, in `mode`."""
        sphere = Sphere(ThetaResolution=24, PhiResolution=24)
        tree = BuildMergeTree(Input=sphere)
        extract = ExtractViewDependentMesh(Input=tree, PixelThreshold=2.0, TriangleBudget=200)
        extract.RefinementMode = mode
        count = triangles(extract)
        for proxy in (extract, tree, sphere):
            Delete(proxy)
        return count

    def check(self, name, mode, text):
        extract = self.load(name)
        count = triangles(extract)
        self.assertEqual(extract.GetClientSideObject().GetRefinementMode(), mode)
        self.assertEqual(extract.RefinementMode, text)
        self.assertEqual(count, self.reference(text))
        return count

    def test_old_fixed_accuracy_loads_as_fixed_accuracy(self):
        count = self.check("ViewDependentMeshOldFixedAccuracy.pvsm", FIXED, "Fixed Accuracy")
        self.assertGreater(count, 200)

    def test_old_triangle_budget_loads_as_budget(self):
        count = self.check("ViewDependentMeshOldTriangleBudget.pvsm", BUDGET, "Triangle Budget")
        self.assertLessEqual(count, 200 + 16)
        self.assertGreater(count, 150)

    def test_new_state_saves_the_new_property_only(self):
        extract = self.load("ViewDependentMeshOldTriangleBudget.pvsm")
        path = os.path.join(output_dir("TestvtkSMExtractViewDependentMeshProxy"), "resaved.pvsm")
        SaveState(path)
        with open(path) as state:
            text = state.read()
        self.assertIn('name="Mode"', text)
        self.assertNotIn('name="RefinementMode"', text)
        count = triangles(extract)
        ResetSession()
        reloaded = self.load_path(path)
        self.assertEqual(reloaded.GetClientSideObject().GetRefinementMode(), BUDGET)
        self.assertEqual(triangles(reloaded), count)

    def load_path(self, path):
        LoadState(path)
        return FindSource("ExtractViewDependentMesh1")

    def test_old_scripts_set_the_mode_by_its_text(self):
        # A script traced before the change sets the mode by its text.
        sphere = Sphere()
        extract = ExtractViewDependentMesh(Input=BuildMergeTree(Input=sphere))
        extract.RefinementMode = "Triangle Budget"
        extract.UpdatePipeline()
        self.assertEqual(extract.GetClientSideObject().GetRefinementMode(), BUDGET)
        extract.RefinementMode = "Fixed Accuracy"
        extract.UpdatePipeline()
        self.assertEqual(extract.GetClientSideObject().GetRefinementMode(), FIXED)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]])
