# SPDX-License-Identifier: BSD-3-Clause
"""Set-up half of the GUI drag test (TestTimeCriticalGUIDrag.py runs it).

Runs inside the real `paraview` through --script, before the GUI plays the
QtTesting events of TestTimeCriticalGUIDrag.xml: it loads the plugin, puts a
Time-Critical Render View alone in the layout (the default Render View is
deleted, so the view takes frame 0, the frame the XML's mouse events are
sent to), shows a scene too heavy for the target (16 spheres of about 65,000
triangles each) and logs every frame the view's render window completes, one
JSON object a line, flushed and synced at once (the GUI may end abruptly).

It also defines _drag_finish(), which the XML's last event calls through the
GUI's Python shell: a mark in the log, then a screenshot of the view.

Unlike TestTimeCriticalGUI.py it does not end the process: the GUI goes on
to play the test events, then exits (--exit). Failures of the set-up are
logged as {"error": ...} lines, for the verdict to report.

Environment: TIMECRITICAL_PLUGIN, TIMECRITICAL_DRAG_LOG (the log file),
TIMECRITICAL_DRAG_VIEW (TimeCriticalRenderView by default; RenderView checks
that the verdict fails for a plain Render View), TIMECRITICAL_DRAG_TARGET_MS.
"""

import json
import os
import traceback

_drag_log = open(os.environ["TIMECRITICAL_DRAG_LOG"], "w")


def _drag_write(record):
    _drag_log.write(json.dumps(record) + "\n")
    _drag_log.flush()
    os.fsync(_drag_log.fileno())


def _drag_setup():
    from paraview.simple import (AssignViewToLayout, CreateView, Delete, GetLayout, GetViews,
                                 GroupDatasets, LoadPlugin, Render, Show, Sphere)
    import timecritical  # noqa: F401  (wraps the renderer the view returns)

    LoadPlugin(os.environ["TIMECRITICAL_PLUGIN"], remote=False, ns=globals())
    kind = os.environ.get("TIMECRITICAL_DRAG_VIEW", "TimeCriticalRenderView")
    target_ms = float(os.environ.get("TIMECRITICAL_DRAG_TARGET_MS", "60"))

    # The view alone in the layout: the drag must land on it.
    layout = GetLayout()
    for other in list(GetViews()):
        Delete(other)
    view = CreateView(kind)
    AssignViewToLayout(view=view, layout=layout, hint=0)
    view.OrientationAxesVisibility = 0
    if kind == "TimeCriticalRenderView":
        view.TargetFrameTime = target_ms
        # Every frame planned on the hierarchies: the drag checks the plans.
        view.BackgroundHierarchyBuilds = 0

    # 4 x 4 spheres, ~65K triangles each (2 x 256 x 127): ~1M triangles.
    spheres = []
    for i in range(16):
        spheres.append(Sphere(Center=[1.2 * (i % 4), 1.2 * (i // 4), 0.0], Radius=0.5,
                              ThetaResolution=256, PhiResolution=129))
    group = GroupDatasets(Input=spheres)
    rep = Show(group, view)
    view.CameraPosition = [1.8, 1.8, 8.0]
    view.CameraFocalPoint = [1.8, 1.8, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.ResetCamera()
    Render(view)  # builds the hierarchies; the renderer starts watching the window

    server_view = view.GetClientSideObject()
    renderer = server_view.GetRenderer()
    window = server_view.GetRenderWindow()
    time_critical = renderer.IsA("vtkTimeCriticalRenderer")
    total = group.GetDataInformation().GetNumberOfCells()

    def on_frame(caller, event):
        record = {"frame": on_frame.count, "view": kind, "size": list(window.GetSize()),
                  "camera": list(renderer.GetActiveCamera().GetPosition())}
        on_frame.count += 1
        if time_critical:
            record.update(
                still=bool(renderer.GetLastRenderWasStill()),
                triangles=int(renderer.GetObjectTrianglesDrawn()),
                predicted_ms=1000.0 * renderer.GetPredictedFrameTime(),
                fixed_ms=1000.0 * renderer.GetFixedFrameTime(),
                target_ms=1000.0 * renderer.GetLastTargetFrameTime(),
                measured_ms=1000.0 * renderer.GetMeasuredFrameTime())
        else:
            # A plain renderer: every frame draws the whole scene.
            record.update(still=None, triangles=total)
        _drag_write(record)

    on_frame.count = 0
    # The renderer's own window observer (frame timing) was added by the
    # render above; a lower priority runs this one after it, so the
    # measured time is this frame's.
    window.AddObserver("EndEvent", on_frame, -1.0)
    _drag_write({"setup": "done", "view": kind, "representation": rep.GetXMLName(),
                 "objects": renderer.GetNumberOfObjects() if time_critical else None,
                 "total_triangles": total, "target_ms": target_ms,
                 "size": list(view.ViewSize),
                 "camera": list(renderer.GetActiveCamera().GetPosition())})
    # Keep the callback alive for the session.
    globals()["_drag_on_frame"] = on_frame

    def finish():
        """Called by the XML's last event (through the Python shell): marks
        the end of the drag in the log, then saves a screenshot (its own
        still render comes after the mark)."""
        _drag_write({"drag": "done", "frames": on_frame.count})
        from paraview.simple import SaveScreenshot
        path = os.path.join(os.path.dirname(os.environ["TIMECRITICAL_DRAG_LOG"]),
                            os.path.basename(os.environ["TIMECRITICAL_DRAG_LOG"])[:-len(".jsonl")]
                            + ".png")
        SaveScreenshot(path, view)
        _drag_write({"screenshot": path})

    globals()["_drag_finish"] = finish


try:
    _drag_setup()
except Exception:  # noqa: BLE001  (reported by the verdict)
    _drag_write({"error": traceback.format_exc()})
