#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""One numbering of the refinement modes and one rule per setting everywhere.

vtkExtractViewDependentMesh, vtkMultiresolutionPolyDataMapper and
vtkTimeCriticalRenderer (the `timecritical` package), and the plugin's XML
files (Extract View-Dependent Mesh's Refinement Mode, the Time-Critical Render
View's Refinement Mode): 0 is the budget mode, 1 fixed accuracy, the defaults
of the XML are those of the classes, and the same bad values are rejected with
the same message by every class. Runs under the system Python, with PYTHONPATH
holding the build tree's package.
"""

import os
import sys
import unittest
import xml.etree.ElementTree as ElementTree

try:
    from timecritical import (vtkExtractViewDependentMesh, vtkMultiresolutionPolyDataMapper,
                              vtkTimeCriticalRenderer)
except ImportError as error:
    sys.stderr.write("Cannot import the timecritical package (%s).\n" % error)
    raise

from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand

PLUGIN_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir,
                          "Plugin")
CLASSES = (vtkExtractViewDependentMesh, vtkMultiresolutionPolyDataMapper, vtkTimeCriticalRenderer)


def proxy_property(xml_file, proxy_name, property_name):
    """The XML element of property_name in the proxy proxy_name of xml_file."""
    root = ElementTree.parse(os.path.join(PLUGIN_DIR, xml_file)).getroot()
    for proxy in root.iter():
        if proxy.get("name") == proxy_name and proxy.tag.endswith("Proxy"):
            for prop in proxy:
                if prop.get("name") == property_name:
                    return prop
    raise AssertionError("%s: no property %s in %s" % (xml_file, property_name, proxy_name))


def enumeration(prop):
    """{integer: text} of a property's EnumerationDomain."""
    domain = prop.find("EnumerationDomain")
    return {int(entry.get("value")): entry.get("text") for entry in domain.findall("Entry")}


class ErrorCounter:
    """The error messages an object reports."""

    def __init__(self, obj):
        self.messages = []

        @calldata_type(VTK_STRING)
        def on_error(caller, event, message):
            self.messages.append(message)

        self.observer = on_error
        obj.AddObserver(vtkCommand.ErrorEvent, on_error)


class TestRefinementSettingsAgree(unittest.TestCase):
    def test_classes_number_the_modes_alike(self):
        for cls in CLASSES:
            self.assertEqual(cls.BUDGET, 0, cls.__name__)
            self.assertEqual(cls.FIXED_ACCURACY, 1, cls.__name__)
            obj = cls()
            obj.SetRefinementModeToFixedAccuracy()
            self.assertEqual(obj.GetRefinementMode(), 1, cls.__name__)
            obj.SetRefinementModeToBudget()
            self.assertEqual(obj.GetRefinementMode(), 0, cls.__name__)
        # The filter's former names stay aliases of the budget mode.
        self.assertEqual(vtkExtractViewDependentMesh.TRIANGLE_BUDGET, 0)
        extract = vtkExtractViewDependentMesh()
        extract.SetRefinementModeToTriangleBudget()
        self.assertEqual(extract.GetRefinementMode(), 0)

    def test_xml_files_number_the_modes_alike(self):
        filter_mode = proxy_property("TimeCriticalFilters.xml", "ExtractViewDependentMesh", "Mode")
        view_mode = proxy_property("TimeCriticalViews.xml", "TimeCriticalRenderView",
                                   "RefinementMode")
        for prop in (filter_mode, view_mode):
            self.assertEqual(prop.get("command"), "SetRefinementMode")
            entries = enumeration(prop)
            self.assertEqual(sorted(entries), [0, 1])
            self.assertIn("Budget", entries[0])
            self.assertEqual(entries[1], "Fixed Accuracy")
        # The same label, so that Python and the GUI call both "Refinement Mode".
        self.assertEqual(filter_mode.get("label"), view_mode.get("label"))
        # XML defaults are the classes' defaults.
        self.assertEqual(int(filter_mode.get("default_values")),
                         vtkExtractViewDependentMesh().GetRefinementMode())
        self.assertEqual(int(view_mode.get("default_values")),
                         vtkTimeCriticalRenderer().GetRefinementMode())

    def test_filter_translates_the_former_numbering(self):
        # The XML has one property with one meaning per integer; old state
        # files are translated by the filter's proxy class.
        root = ElementTree.parse(os.path.join(PLUGIN_DIR, "TimeCriticalFilters.xml")).getroot()
        proxy = [p for p in root.iter() if p.get("name") == "ExtractViewDependentMesh"][0]
        self.assertEqual(proxy.tag, "ExtractViewDependentMeshProxy")
        self.assertEqual([p.get("name") for p in proxy if p.get("command") == "SetRefinementMode"],
                         ["Mode"])
        self.assertFalse([p for p in proxy if p.get("name") == "RefinementMode"])
        extract = vtkExtractViewDependentMesh()
        extract.SetLegacyRefinementMode(0)
        self.assertEqual(extract.GetRefinementMode(), vtkExtractViewDependentMesh.FIXED_ACCURACY)
        extract.SetLegacyRefinementMode(1)
        self.assertEqual(extract.GetRefinementMode(), vtkExtractViewDependentMesh.BUDGET)

    def test_bad_values_are_rejected_alike(self):
        bad = {"SetPixelThreshold": (-1.0, float("nan"), float("inf")),
               "SetSilhouetteFactor": (0.0, -0.5, 1.5, float("nan")),
               "SetHighlightFactor": (0.0, 2.0, float("nan"))}
        messages = {}
        for cls in CLASSES:
            obj = cls()
            errors = ErrorCounter(obj)
            before = (obj.GetPixelThreshold(), obj.GetSilhouetteFactor(), obj.GetHighlightFactor())
            count = 0
            for setter, values in bad.items():
                for value in values:
                    getattr(obj, setter)(value)
                    count += 1
                    self.assertEqual(len(errors.messages), count, (cls.__name__, setter, value))
                    text = errors.messages[-1]
                    messages.setdefault((setter, str(value)), set()).add(
                        text[text.index(setter[3:]):])
            after = (obj.GetPixelThreshold(), obj.GetSilhouetteFactor(), obj.GetHighlightFactor())
            self.assertEqual(before, after, cls.__name__)
            self.assertEqual(before, (1.0, 0.25, 0.5), cls.__name__)
            # Modes out of range are clamped, as VTK's other enumerations.
            obj.SetRefinementMode(5)
            self.assertEqual(obj.GetRefinementMode(), 1, cls.__name__)
            obj.SetRefinementMode(-5)
            self.assertEqual(obj.GetRefinementMode(), 0, cls.__name__)
        for key, texts in messages.items():
            self.assertEqual(len(texts), 1, (key, texts))
        self.assertIn("PixelThreshold must be a finite number >= 0, not -1; ignored.",
                      "".join(messages[("SetPixelThreshold", "-1.0")]))
        self.assertIn("SilhouetteFactor must be in (0, 1], not 0; ignored.",
                      "".join(messages[("SetSilhouetteFactor", "0.0")]))


if __name__ == "__main__":
    unittest.main()
