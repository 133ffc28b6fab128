# SPDX-License-Identifier: BSD-3-Clause
"""GUI smoke test: the real `paraview` executable with the TimeCritical plugin.

Run as `paraview --dr --script=TestTimeCriticalGUI.py` (under xvfb-run). The
script runs inside the GUI's Python: it loads the plugin, opens a dataset (the
cow of the shared data, else a sphere) in a Time-Critical Render View placed
in the GUI's layout, changes properties the way the Properties panel does,
renders, and compares a screenshot with the baseline
Testing/Data/Baseline/TimeCriticalGUI.png. The GUI has no exit-code channel
for --script, so the script ends the process itself: exit status 0 when
every check passed, 1 otherwise (with the reason on stderr).

Environment: TIMECRITICAL_PLUGIN (the built TimeCritical.so),
TIMECRITICAL_BASELINE_DIR, TIMECRITICAL_TEST_OUTPUT_DIR, TIMECRITICAL_SHARED_DATA_DIR;
TIMECRITICAL_UPDATE_BASELINES=1 writes the baseline instead of comparing.
"""

import os
import shutil
import traceback


def run():
    from paraview.simple import (AssignViewToLayout, CreateView, GetLayout, GetViews, LoadPlugin,
                                 OpenDataFile, Render, SaveScreenshot, Show, Sphere)
    import numpy as np
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader

    import timecritical  # noqa: F401  (wraps the renderer the view returns)

    plugin = os.environ["TIMECRITICAL_PLUGIN"]
    out = os.environ.get("TIMECRITICAL_TEST_OUTPUT_DIR", ".")
    baseline_dir = os.environ["TIMECRITICAL_BASELINE_DIR"]
    os.makedirs(out, exist_ok=True)
    LoadPlugin(plugin, remote=False, ns=globals())

    layout = GetLayout()
    view = CreateView("TimeCriticalRenderView")
    AssignViewToLayout(view=view, layout=layout, hint=0)
    view.OrientationAxesVisibility = 0
    cow = os.path.join(os.environ.get("TIMECRITICAL_SHARED_DATA_DIR", ""), "cow.obj")
    source = OpenDataFile(cow) if os.path.isfile(cow) else Sphere(ThetaResolution=120,
                                                                   PhiResolution=120)
    rep = Show(source, view)
    if rep.GetXMLName() != "TimeCriticalGeometryRepresentation":
        raise AssertionError("representation is %s" % rep.GetXMLName())
    # What the Properties panel sets.
    view.TargetFrameTime = 40
    view.CameraPosition = [3.0, 2.0, 4.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.ResetCamera()
    rep.DiffuseColor = [0.9, 0.75, 0.5]
    Render(view)

    # The GUI gave the view a widget of its own: its size is the widget's,
    # beside the Render View the GUI opened at start-up.
    others = [v for v in GetViews() if v.GetXMLName() == "RenderView"]
    if not others or list(view.ViewSize) != list(others[0].ViewSize) or view.ViewSize[0] < 200:
        raise AssertionError("no GUI widget for the view: size %s, other views %s"
                             % (list(view.ViewSize), [list(v.ViewSize) for v in others]))

    renderer = view.GetClientSideObject().GetRenderer()
    if not renderer.IsA("vtkTimeCriticalRenderer") or renderer.GetNumberOfObjects() != 1:
        raise AssertionError("the GUI's view does not render time-critically")

    size = [400, 300]
    path = os.path.join(out, "TimeCriticalGUI.png")
    SaveScreenshot(path, view, ImageResolution=size)
    # With the statistics on, for the README (timings vary: not compared).
    view.ShowStatistics = 1
    view.InteractiveRender()
    SaveScreenshot(os.path.join(out, "TimeCriticalGUI_statistics.png"), view,
                   ImageResolution=[640, 480])
    view.ColorByResolution = 1
    view.ShowStatistics = 0
    view.InteractiveRender()
    SaveScreenshot(os.path.join(out, "TimeCriticalGUI_resolution_map.png"), view,
                   ImageResolution=[640, 480])

    baseline = os.path.join(baseline_dir, "TimeCriticalGUI.png")
    if os.environ.get("TIMECRITICAL_UPDATE_BASELINES") == "1":
        shutil.copyfile(path, baseline)
        return

    def pixels(name):
        reader = vtkPNGReader()
        reader.SetFileName(name)
        reader.Update()
        image = reader.GetOutput()
        dims = image.GetDimensions()
        return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(dims[1], dims[0], -1)[:, :, :3]

    image, expected = pixels(path), pixels(baseline)
    if image.shape != expected.shape:
        raise AssertionError("screenshot %s, baseline %s" % (image.shape, expected.shape))
    differing = np.count_nonzero(np.abs(image.astype(int) - expected.astype(int)).max(axis=2) > 24)
    if differing > 0.005 * image.shape[0] * image.shape[1]:
        raise AssertionError("%d pixels differ from %s (see %s)" % (differing, baseline, path))
    if not any(v.GetXMLName() == "TimeCriticalRenderView" for v in GetViews()):
        raise AssertionError("the view is not among the GUI's views")


# The GUI sends Python's sys.stdout and sys.stderr to its Output Messages
# window: the verdict goes to the process's own descriptors.
try:
    run()
    os.write(1, b"TimeCritical GUI smoke test passed\n")
    status = 0
except Exception:  # noqa: BLE001  (any failure fails the test)
    os.write(2, traceback.format_exc().encode())
    status = 1
# The GUI would keep running after --script: end the process with the verdict.
os._exit(status)
