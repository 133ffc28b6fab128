# SPDX-License-Identifier: BSD-3-Clause
"""GUI smoke test: the real `paraview` executable with the TimeCritical plugin.

Run as `paraview --dr --script=TestTimeCriticalGUI.py` (under xvfb-run). The
script runs inside the GUI's Python: it loads the plugin, opens a dataset (the
cow of the shared data, else a sphere) in a Time-Critical Render View placed
in the GUI's layout, changes properties the way the Properties panel does,
renders, and compares a screenshot with the baseline of that dataset:
Testing/Data/Baseline/TimeCriticalGUI.png (cow) or TimeCriticalGUISphere.png. The GUI has no exit-code channel
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

    from timecritical_testing import read_png  # Testing/Python, on PYTHONPATH

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
    have_cow = os.path.isfile(cow)
    source = OpenDataFile(cow) if have_cow else Sphere(ThetaResolution=120, PhiResolution=120)
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
    # A new view in the GUI builds hierarchies in the background: the first
    # frames may draw the stand-in. The screenshot compares the hierarchy's image.
    if view.BackgroundHierarchyBuilds != 1:
        raise AssertionError("a GUI view has BackgroundHierarchyBuilds %s, not 1"
                             % view.BackgroundHierarchyBuilds)
    view.SMProxy.InvokeCommand("WaitForHierarchies")
    Render(view)
    pending = view.GetClientSideObject().GetRenderer().GetNumberOfPendingHierarchies()
    if pending != 0:
        raise AssertionError("%d hierarchies pending after WaitForHierarchies" % pending)

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
    # Each dataset has its own baseline: without the shared data the test
    # still checks the GUI, against the sphere's image.
    baseline = os.path.join(baseline_dir,
                            "TimeCriticalGUI.png" if have_cow else "TimeCriticalGUISphere.png")
    if os.environ.get("TIMECRITICAL_UPDATE_BASELINES") == "1":
        shutil.copyfile(path, baseline)
        return

    image, expected = read_png(path), read_png(baseline)
    if image.shape != expected.shape:
        raise AssertionError("screenshot %s, baseline %s" % (image.shape, expected.shape))
    differing = np.count_nonzero(np.abs(image.astype(int) - expected.astype(int)).max(axis=2) > 24)
    if differing > 0.005 * image.shape[0] * image.shape[1]:
        raise AssertionError("%d pixels differ from %s (see %s)" % (differing, baseline, path))
    if not any(v.GetXMLName() == "TimeCriticalRenderView" for v in GetViews()):
        raise AssertionError("the view is not among the GUI's views")
    readme_screenshots(view, source, rep)


def readme_screenshots(view, source, rep):
    """A herd of 36 cows under a tight budget: the statistics and the
    resolution map (timings vary, so these are not compared)."""
    from paraview.simple import GroupDatasets, Hide, Render, SaveScreenshot, Show, Transform

    folder = os.environ.get("TIMECRITICAL_SCREENSHOT_DIR",
                            os.environ.get("TIMECRITICAL_TEST_OUTPUT_DIR", "."))
    os.makedirs(folder, exist_ok=True)
    Hide(source, view)
    b = source.GetDataInformation().GetBounds()
    step = 1.2 * max(b[1] - b[0], b[5] - b[4])
    center = [0.5 * (b[0] + b[1]), b[2], 0.5 * (b[4] + b[5])]
    herd = []
    for i in range(36):
        cow = Transform(Input=source)
        cow.Transform.Translate = [step * (i % 6) - center[0], -center[1],
                                   step * (i // 6) - center[2]]
        cow.Transform.Rotate = [0.0, 37.0 * i, 0.0]
        herd.append(cow)
    group = GroupDatasets(Input=herd)
    herd_rep = Show(group, view)
    herd_rep.DiffuseColor = [0.9, 0.75, 0.5]
    # Low over one corner, looking across the herd: near cows large, far ones small.
    view.CameraPosition = [-1.2 * step, 1.1 * step, -1.2 * step]
    view.CameraFocalPoint = [2.5 * step, 0.0, 2.5 * step]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraViewAngle = 40
    view.FullResolutionAtRest = 0
    view.TargetFrameTime = 60
    view.ShowStatistics = 1
    for _ in range(8):  # the cost model settles
        Render(view)
    SaveScreenshot(os.path.join(folder, "TimeCriticalGUI_statistics.png"), view,
                   ImageResolution=[800, 500])
    view.ColorByResolution = 1
    view.ShowStatistics = 0
    Render(view)
    SaveScreenshot(os.path.join(folder, "TimeCriticalGUI_resolution_map.png"), view,
                   ImageResolution=[800, 500])


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
