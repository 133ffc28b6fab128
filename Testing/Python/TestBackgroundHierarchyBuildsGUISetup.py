# SPDX-License-Identifier: BSD-3-Clause
"""Runs inside the real `paraview` through --script for
TestBackgroundHierarchyBuildsGUI.py: loads the plugin, puts a Time-Critical
Render View in the layout (BackgroundHierarchyBuilds is on by default in the
GUI: logged, then checked by the driver), shows a sphere
and renders once (drawn in full while its hierarchy builds), then logs every
frame the view's render window completes, with whether the sphere is drawn
from its hierarchy (one JSON object a line, with its time, flushed at once).
Nothing renders the view afterwards but the view itself. The first frame
drawn from the hierarchy ends the process (status 0); without one the
driver's time-out ends it.

Environment: TIMECRITICAL_PLUGIN, TIMECRITICAL_BACKGROUND_LOG (the log file).
"""

import json
import os
import time
import traceback

_background_log = open(os.environ["TIMECRITICAL_BACKGROUND_LOG"], "w")


def _background_write(record):
    record["t"] = time.monotonic()
    _background_log.write(json.dumps(record) + "\n")
    _background_log.flush()
    os.fsync(_background_log.fileno())


def _background_setup():
    from paraview.simple import AssignViewToLayout, CreateView, GetLayout, LoadPlugin, Render, Show, Sphere
    import timecritical  # noqa: F401  (wraps the renderer and mapper the view returns)

    LoadPlugin(os.environ["TIMECRITICAL_PLUGIN"], remote=False, ns=globals())
    view = CreateView("TimeCriticalRenderView")
    AssignViewToLayout(view=view, layout=GetLayout(), hint=0)
    view.OrientationAxesVisibility = 0
    # The GUI's default (vtkSMTimeCriticalRenderViewProxy): on, not set here.
    _background_write({"default": int(view.BackgroundHierarchyBuilds)})
    # Large enough that its build outlasts the renders the GUI makes by itself
    # after a script (about 2 s here), so that only the view can show it.
    Show(Sphere(ThetaResolution=1000, PhiResolution=1000), view)
    Render(view)
    renderer = view.GetClientSideObject().GetRenderer()
    mapper = renderer.GetObjectActor(0).GetMapper()

    def state():
        return {"tom": bool(mapper.GetObjectIsTOM(0)),
                "pending": int(mapper.GetNumberOfPendingHierarchies()),
                "swapped": int(mapper.GetNumberOfSwappedHierarchies())}

    def on_frame(caller, event):
        on_frame.count += 1
        record = {"frame": on_frame.count}
        record.update(state())
        _background_write(record)
        if record["tom"]:
            os._exit(0)  # the GUI has no exit-code channel for --script

    on_frame.count = 0
    view.GetClientSideObject().GetRenderWindow().AddObserver("EndEvent", on_frame, -1.0)
    record = {"setup": "done"}
    record.update(state())
    _background_write(record)
    globals()["_background_on_frame"] = on_frame  # alive for the session


try:
    _background_setup()
except Exception:  # noqa: BLE001 (reported in the log for the verdict)
    _background_write({"error": traceback.format_exc()})
    os._exit(1)
