# SPDX-License-Identifier: BSD-3-Clause
"""GUI test: a mouse drag in the real `paraview`, in the Time-Critical Render View.

    python3 TestTimeCriticalGUIDrag.py <xvfb-run> <paraview> [--control]

Runs, under xvfb-run, `paraview --dr --script=TestTimeCriticalGUIDragSetup.py
--test-script=TestTimeCriticalGUIDrag.xml --exit`: the set-up script puts the
view alone in the layout with a scene of about a million triangles and logs
every frame; ParaView's own test player (QtTesting) then sends the XML's
mouse events to the view's widget (frame 0's Viewport): a left-button press,
twelve moves across the view, a release; --exit quits the GUI after them.
The verdict is drawn here, from the log, after paraview has exited:

* the set-up ran (a Time-Critical Render View with its 16 objects) and the
  GUI played the events (paraview's exit status is the player's verdict);
* at least MIN_INTERACTIVE frames of the drag were interactive (budgeted),
  each planned for the view's Target Frame Time and drawing fewer triangles
  than the scene has;
* every one of them whose fixed part left room for the objects was planned
  within the target (predicted, not measured: the plan is what is checked);
* the drag turned the camera;
* the last frame, after the release, was a still frame at full resolution.

The XML's last event calls the set-up's _drag_finish() through the GUI's
Python shell: it marks the end of the drag in the log (later frames are not
the drag's) and saves a screenshot of the view, TimeCriticalGUIDrag.png.

--control runs the same drag in a plain Render View and passes only if the
verdict rejects it because no frame was budgeted (while the drag did reach
the view: frames were drawn and the camera turned), which shows the checks
can fail.

Environment: TIMECRITICAL_PLUGIN, TIMECRITICAL_TEST_OUTPUT_DIR (the log
TimeCriticalGUIDrag[Control].jsonl and .png go there), XDG_RUNTIME_DIR.
"""

import json
import math
import os
import subprocess
import sys

MIN_INTERACTIVE = 6   # of the XML's 12 moves
TARGET_MS = 60.0      # the full scene takes 3-5 times as long here (llvmpipe)
TIMEOUT_S = 50


class Rejected(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Rejected(message)


def verdict(records, status):
    """Raises Rejected with the first check that fails; returns a summary."""
    errors = [r["error"] for r in records if "error" in r]
    check(not errors, "the set-up script failed:\n" + "".join(errors))
    setups = [r for r in records if r.get("setup") == "done"]
    check(len(setups) == 1, "the set-up script did not finish (see the GUI's output)")
    setup = setups[0]
    check(status == 0, "paraview exited with status %d (event playback failed?)" % status)
    marks = [i for i, r in enumerate(records) if r.get("drag") == "done"]
    check(marks, "the XML's last event (the Python shell's call marking the end of the "
          "drag) did not run")
    # The frames of the drag: those before the mark (the screenshot renders after it).
    frames = [r for r in records[:marks[0]] if "frame" in r]
    check(frames, "no frame was rendered after the set-up")
    check(any(r["camera"] != setup["camera"] for r in frames),
          "the camera never moved: the drag did not reach the view")

    interactive = [r for r in frames if r["still"] is False]
    check(len(interactive) >= MIN_INTERACTIVE,
          "%d interactive (budgeted) frames during the drag, expected at least %d"
          % (len(interactive), MIN_INTERACTIVE))
    check(setup["representation"] == "TimeCriticalGeometryRepresentation"
          and setup["objects"] == 16,
          "representation %s with %s objects" % (setup["representation"], setup["objects"]))
    total = setup["total_triangles"]
    with_room = 0
    for r in interactive:
        check(abs(r["target_ms"] - setup["target_ms"]) < 1e-6,
              "frame %d was planned for %g ms, not the view's %g ms"
              % (r["frame"], r["target_ms"], setup["target_ms"]))
        check(0 < r["triangles"] < total,
              "interactive frame %d drew %d of the scene's %d triangles"
              % (r["frame"], r["triangles"], total))
        if r["fixed_ms"] < 0.95 * r["target_ms"]:
            with_room += 1
            check(r["predicted_ms"] <= 1.0001 * r["target_ms"],
                  "interactive frame %d was planned for %.1f ms, over the %.1f ms target"
                  % (r["frame"], r["predicted_ms"], r["target_ms"]))
    check(with_room >= MIN_INTERACTIVE // 2,
          "only %d interactive frames had room for the objects (fixed part near the target: "
          "machine overloaded?)" % with_room)

    last = frames[-1]
    check(last["still"] is True and math.isinf(last["target_ms"]),
          "the last frame (%d, after the release) was not a still frame" % last["frame"])
    check(last["triangles"] == total,
          "the last frame drew %d of %d triangles, not full resolution"
          % (last["triangles"], total))
    check(frames.index(last) > frames.index(interactive[-1]),
          "no still frame after the drag")
    shots = [r["screenshot"] for r in records if "screenshot" in r]
    check(shots and os.path.getsize(shots[0]) > 0, "no screenshot after the drag")
    return ("%d frames after the set-up: %d interactive (triangles %d-%d of %d, predicted "
            "%.1f-%.1f ms for %.0f ms), last frame still with %d triangles; screenshot %s"
            % (len(frames), len(interactive), min(r["triangles"] for r in interactive),
               max(r["triangles"] for r in interactive), total,
               min(r["predicted_ms"] for r in interactive),
               max(r["predicted_ms"] for r in interactive), setup["target_ms"],
               last["triangles"], shots[0]))


def main(argv):
    control = "--control" in argv
    args = [a for a in argv if a != "--control"]
    if len(args) != 2:
        sys.exit(__doc__)
    xvfb_run, paraview = args
    here = os.path.dirname(os.path.abspath(__file__))
    out = os.environ.get("TIMECRITICAL_TEST_OUTPUT_DIR", ".")
    os.makedirs(out, exist_ok=True)
    log = os.path.join(out, "TimeCriticalGUIDrag%s.jsonl" % ("Control" if control else ""))
    if os.path.exists(log):
        os.remove(log)
    env = dict(os.environ, TIMECRITICAL_DRAG_LOG=log, TIMECRITICAL_DRAG_TARGET_MS=str(TARGET_MS),
               TIMECRITICAL_DRAG_VIEW="RenderView" if control else "TimeCriticalRenderView")
    command = [xvfb_run, "-a", "-s", "-screen 0 1280x1024x24 -noreset", paraview, "--dr",
               "--script=" + os.path.join(here, "TestTimeCriticalGUIDragSetup.py"),
               "--test-script=" + os.path.join(here, "TestTimeCriticalGUIDrag.xml"), "--exit"]
    try:
        run = subprocess.run(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             timeout=TIMEOUT_S)
        status, output = run.returncode, run.stdout.decode(errors="replace")
    except subprocess.TimeoutExpired as e:
        status, output = "timeout", (e.stdout or b"").decode(errors="replace")
    records = []
    if os.path.exists(log):
        with open(log) as f:
            for line in f:
                try:
                    records.append(json.loads(line))
                except ValueError:
                    break  # a line cut short by an abrupt end
    for r in records:
        if "frame" in r:
            print("frame %(frame)d: still %(still)s, %(triangles)d triangles" % r
                  + (", predicted %.1f ms (fixed %.1f) for %g, measured %.1f ms"
                     % (r["predicted_ms"], r["fixed_ms"], r["target_ms"], r["measured_ms"])
                     if r["still"] is not None else ""))
    if status == "timeout":
        print(output[-4000:])
        print("FAILED: paraview did not exit within %d s" % TIMEOUT_S)
        return 1
    try:
        summary = verdict(records, status)
    except Rejected as e:
        if control:
            drew = [r for r in records if "frame" in r]
            setup = [r for r in records if r.get("setup") == "done"]
            reached = setup and any(r["camera"] != setup[0]["camera"] for r in drew)
            if str(e).startswith("0 interactive") and status == 0 and reached:
                print("control: %d frames drawn in a plain Render View, rejected as expected: %s"
                      % (len(drew), e))
                print("TimeCritical GUI drag control passed")
                return 0
            print(output[-4000:])
            print("FAILED: the control was rejected for another reason: %s" % e)
            return 1
        print(output[-4000:])
        print("FAILED: %s (log: %s)" % (e, log))
        return 1
    if control:
        print("FAILED: the verdict accepted a plain Render View: " + summary)
        return 1
    print(summary)
    print("TimeCritical GUI drag test passed")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
