# SPDX-License-Identifier: BSD-3-Clause
"""The Time-Critical Render View in client-server mode: `pvpython TestTimeCriticalViewClientServer.py`.

Starts a `pvserver` (TIMECRITICAL_PVSERVER, on a free port), connects to it,
loads the plugin on the server and the client as docs/paraview.md says, shows a
surface in the view and renders it on the server (the view always renders
where the data is): the image must be the one the same scene gives in a
builtin session, and the client's statistics overlay shows the server's
figures.

Environment: TIMECRITICAL_PLUGIN, TIMECRITICAL_PVSERVER (the pvserver
executable), TIMECRITICAL_TEST_OUTPUT_DIR.
"""

import os
import socket
import subprocess
import sys
import time

import numpy as np

from paraview.simple import *  # noqa: F401,F403

import timecritical  # noqa: F401
from timecritical import TimeCriticalViews  # noqa: F401  (the client's view class)
from timecritical_testing import PLUGIN, output_dir, read_png

OUT = output_dir("client-server")
SIZE = [400, 300]
# The loopback address, not "localhost": a machine without /etc/hosts (a fresh
# chroot, a minimal container) is legitimate and cannot resolve the name.
LOOPBACK = "127.0.0.1"


def fail(message, server=None):
    sys.stderr.write("FAILED: %s\n" % message)
    if server:
        server.kill()
    sys.exit(1)


def free_port():
    with socket.socket() as probe:
        probe.bind((LOOPBACK, 0))
        return probe.getsockname()[1]


def start_server(port):
    command = [os.environ["TIMECRITICAL_PVSERVER"], "--sp=%d" % port, "--force-offscreen-rendering"]
    server = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    deadline = time.time() + 60
    for line in server.stdout:
        if "Accepting connection" in line:
            return server
        if time.time() > deadline:
            break
    fail("pvserver did not start (%s)" % " ".join(command), server)


def render_scene(name, statistics=None):
    """The same scene in a new view of the current session: its screenshot's
    pixels; with a list `statistics`, the view's statistics text is appended."""
    view = CreateView("TimeCriticalRenderView")
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    source = Sphere(ThetaResolution=150, PhiResolution=150)
    rep = Show(source, view)
    if rep.GetXMLName() != "TimeCriticalGeometryRepresentation":
        fail("%s: representation %s" % (name, rep.GetXMLName()))
    ColorBy(rep, ("POINTS", "Normals", "X"))
    Render(view)  # paraview.simple's first render resets the camera: before setting it
    view.CameraPosition = [0.0, 0.5, 3.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    Render(view)
    if statistics is not None:
        view.ShowStatistics = 1
        view.InteractiveRender()
        view.InteractiveRender()
        statistics.append(view.GetClientSideObject().GetStatisticsText())
        view.ShowStatistics = 0
        Render(view)
    path = os.path.join(OUT, name + ".png")
    SaveScreenshot(path, view, ImageResolution=SIZE)
    pixels = read_png(path)
    Delete(rep)
    Delete(view)
    Delete(source)
    return pixels


port = free_port()
server = start_server(port)
try:
    Connect(LOOPBACK, port)
    LoadPlugin(PLUGIN, remote=True, ns=globals())
    LoadPlugin(PLUGIN, remote=False, ns=globals())
    texts = []
    remote = render_scene("remote", texts)
    Disconnect()
finally:
    server.kill()
    server.wait()

# The client's overlay shows the server's figures (the client draws no objects).
print("statistics on the client:\n" + texts[0])
if "Objects: 1 drawn" not in texts[0] or "of 44,400" not in texts[0]:
    fail("the client's statistics are not the server's: %r" % texts[0])

Connect()  # builtin
builtin = render_scene("builtin")
if np.count_nonzero(builtin.max(axis=2) != builtin[0, 0].max()) < 1000:
    fail("the builtin image is empty")
differing = np.count_nonzero(np.abs(remote.astype(int) - builtin.astype(int)).max(axis=2) > 8)
print("pixels differing between the server's and the builtin render: %d" % differing)
if differing > 0.002 * remote.shape[0] * remote.shape[1]:
    fail("the server's image differs from the builtin one in %d pixels" % differing)
print("client-server view test passed")
