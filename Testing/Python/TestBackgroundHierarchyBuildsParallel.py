# SPDX-License-Identifier: BSD-3-Clause
"""Background hierarchy builds in the Time-Critical Render View under MPI:
`mpirun -np 2 pvbatch TestBackgroundHierarchyBuildsParallel.py`.

Every rank builds the hierarchies of its own pieces on its own workers and
swaps them in at its own pace; compositing must not notice (every rank takes
the same render path whether its builds are done or not). Budgeted frames
are rendered while the builds run, then the view's WaitForHierarchies
command runs on every rank; afterwards every rank draws its pieces as TOMs,
and the full-resolution image equals the synchronous path's.
"""

import os
import sys

import numpy as np

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403

import timecritical  # noqa: F401
from timecritical import TimeCriticalViews  # noqa: F401

from timecritical_testing import load_plugin, read_png

load_plugin(globals(), ["BuildTotallyOrderedMesh"])
OUT = os.environ.get("TIMECRITICAL_TEST_OUTPUT_DIR", ".")
SIZE = [400, 300]


def finish(status):
    # As TestTimeCriticalViewParallel.py: pvbatch 5.11 crashes at exit with a
    # live render view, and sys.exit() under MPI skips MPI_Finalize.
    for each in GetViews():
        Delete(each)
    if status:
        sys.stderr.flush()
        os._exit(status)


def fail(message):
    sys.stderr.write("FAILED: %s\n" % message)
    finish(1)


ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
view = CreateView("TimeCriticalRenderView")
view.ViewSize = SIZE
view.OrientationAxesVisibility = 0
view.BackgroundHierarchyBuilds = 1
view.FullResolutionAtRest = 0
spheres = [Sphere(ThetaResolution=160, PhiResolution=160, Radius=0.45,
                  Center=[i % 3, i // 3, 0.0]) for i in range(6)]
group = GroupDatasets(Input=spheres)
Show(group, view)
view.CameraPosition = [1.0, 0.5, 6.0]
view.CameraFocalPoint = [1.0, 0.5, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]

server = view.GetClientSideObject()
renderer = server.GetRenderer()
camera = GetActiveCamera()
for frame in range(6):  # while the builds run (or whatever has finished)
    camera.Azimuth(3.0)
    Render(view)
view.SMProxy.InvokeCommand("WaitForHierarchies")  # every rank waits for its own
Render(view)
if renderer.GetNumberOfPendingHierarchies() != 0:
    fail("%d hierarchies pending after the wait" % renderer.GetNumberOfPendingHierarchies())
objects = renderer.GetNumberOfObjects()
if objects == 0:
    fail("rank 0 has no object (the data is not distributed)")
for i in range(objects):
    mapper = renderer.GetObjectActor(i).GetMapper()
    if not mapper.GetObjectIsTOM(renderer.GetObjectIndex(i)):
        fail("object %d of rank 0 is not a TOM after the wait" % i)
full = [server.GetRankTrianglesDrawn(r) for r in range(server.GetNumberOfRanks())]
print("ranks: %d, objects on rank 0: %d, triangles per rank: %s" % (ranks, objects, full))

# At rest, full resolution: the synchronous path's picture.
view.FullResolutionAtRest = 1
background = os.path.join(OUT, "background-parallel-%d.png" % ranks)
SaveScreenshot(background, view, ImageResolution=SIZE)
view.BackgroundHierarchyBuilds = 0
Render(view)
synchronous = os.path.join(OUT, "synchronous-parallel-%d.png" % ranks)
SaveScreenshot(synchronous, view, ImageResolution=SIZE)
a, b = read_png(background), read_png(synchronous)
differing = np.count_nonzero(np.abs(a.astype(int) - b.astype(int)).max(axis=2) > 12)
print("pixels differing from the synchronous path: %d of %d" % (differing, a.shape[0] * a.shape[1]))
if differing > 0.002 * a.shape[0] * a.shape[1]:
    fail("background and synchronous images differ in %d pixels" % differing)
print("parallel background test passed")
finish(0)
