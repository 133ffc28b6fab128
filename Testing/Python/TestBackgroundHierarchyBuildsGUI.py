# SPDX-License-Identifier: BSD-3-Clause
"""GUI test: with BackgroundHierarchyBuilds on, the Time-Critical Render View
of the real `paraview` shows a surface's hierarchy once built, by itself.

    python3 TestBackgroundHierarchyBuildsGUI.py <xvfb-run> <paraview>

Runs, under xvfb-run, `paraview --dr --script=TestBackgroundHierarchyBuildsGUISetup.py`:
the set-up shows a sphere (its first render draws it in full while its
hierarchy builds) and logs every frame, and nothing renders the view after
that but the view's own polling of the builds. The verdict, from the log:
the first render drew the sphere without its hierarchy (pending), and a
later frame drew it from its hierarchy, with nothing pending (the set-up
then ends paraview with status 0; without such a frame paraview is ended
after TIMEOUT_S). The sphere's build outlasts the renders the GUI makes by
itself after the script: with the view's polling disabled this test fails.
"""

import json
import os
import signal
import subprocess
import sys
import tempfile

TIMEOUT_S = 90


def main(argv):
    xvfb_run, paraview = argv
    here = os.path.dirname(os.path.abspath(__file__))
    out = os.environ.get("TIMECRITICAL_TEST_OUTPUT_DIR") or tempfile.mkdtemp()
    os.makedirs(out, exist_ok=True)
    log = os.path.join(out, "background-gui.jsonl")
    if os.path.exists(log):
        os.remove(log)
    env = dict(os.environ, TIMECRITICAL_BACKGROUND_LOG=log)
    command = [xvfb_run, "-a", "-s", "-screen 0 1280x1024x24 -noreset", paraview, "--dr",
               "--script=" + os.path.join(here, "TestBackgroundHierarchyBuildsGUISetup.py")]
    # A session of its own: on a time-out the whole group goes (xvfb-run,
    # Xvfb and paraview), not only xvfb-run.
    process = subprocess.Popen(command, env=env, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, start_new_session=True)
    try:
        output, _ = process.communicate(timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        output, _ = process.communicate()
    records = []
    if os.path.isfile(log):
        with open(log) as stream:
            records = [json.loads(line) for line in stream if line.strip()]
    failures = []

    def check(condition, message):
        if not condition:
            failures.append(message)

    check(process.returncode == 0, "paraview exited with status %d" % process.returncode)
    errors = [r for r in records if "error" in r]
    check(not errors, "set-up failed: %s" % errors)
    defaults = [r["default"] for r in records if "default" in r]
    check(defaults == [1], "a new view in the GUI has BackgroundHierarchyBuilds %s, not 1" % defaults)
    setup = [r for r in records if r.get("setup")]
    frames = [r for r in records if "frame" in r]
    check(setup and not setup[0]["tom"] and setup[0]["pending"] == 1,
          "the first render did not draw the sphere in full while building: %s" % setup)
    shown = [f for f in frames if f["tom"]]
    check(shown and shown[0]["pending"] == 0 and shown[0]["swapped"] == 1,
          "no frame drew the hierarchy by itself: %s" % frames)
    if failures:
        print(output.decode(errors="replace")[-4000:])
        for failure in failures:
            print("FAILED: " + failure)
        return 1
    print("frames logged: %s" % frames)
    print("TimeCritical GUI background test passed")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
