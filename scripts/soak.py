#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Soak test of vtkTimeCriticalRenderer: many frames of a many-object scene
with the camera moving while actors are added, removed and given new data.

Every --cycle frames one actor is removed, a new one is added (new mapper, new
data) and one mapper gets a new composite input (other leaves, other count), so
the renderer and the mappers keep releasing and reallocating what they hold.
The scene mixes TOM leaves (uniform prefixes) and merge-tree leaves (view-dependent
fronts); the time-critical budget drives both.

Records per frame the wall time of Render(), the renderer's measured and
predicted frame times, the triangles drawn, the process's resident set size
and glibc's heap bytes in use, and writes them as JSON. It fails (exit 1) on any
VTK error or warning from the renderer, the window or a mapper, and when memory
grows: over the cycle boundaries after the warm-up (the first two cycles, or
10% of the frames if more), the least-squares trend of glibc's heap in use
must add up to at most --max-growth-mb (the content, and so the memory, of
the scene changes by design from cycle to cycle; a leak shows as a slope).
The RSS trend is reported too; it also holds the allocator's fragmentation,
which the trend of the free bytes glibc holds in its arenas shows.

Usage: xvfb-run -a /usr/bin/python3 scripts/soak.py [--frames 10000]
           [--cycle 250] [--json soak.json]
PYTHONPATH must reach the `timecritical` package (the build tree's
lib/python3/dist-packages); scripts/run-soak.sh sets it up.
"""

import argparse
import ctypes
import json
import math
import os
import resource
import statistics
import sys
import time

from timecritical import (vtkMergeTreeBuilder, vtkMultiresolutionPolyDataMapper,
                          vtkTimeCriticalRenderer, vtkTOMBuilder)
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet, vtkPolyData
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderWindow
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL factory overrides)


class MallInfo2(ctypes.Structure):
    _fields_ = [(name, ctypes.c_size_t) for name in (
        "arena", "ordblks", "smblks", "hblks", "hblkhd", "usmblks", "fsmblks",
        "uordblks", "fordblks", "keepcost")]


def heap_in_use_function():
    """glibc's (bytes in use (small and mmapped blocks), free bytes it holds
    in its arenas), or None off glibc. RSS growth with a flat first figure
    and a growing second one is fragmentation, not a leak."""
    try:
        libc = ctypes.CDLL("libc.so.6")
        mallinfo2 = libc.mallinfo2
    except (OSError, AttributeError):
        return None
    mallinfo2.restype = MallInfo2

    def in_use():
        info = mallinfo2()
        return info.uordblks + info.hblkhd, info.fordblks
    return in_use


PAGE = resource.getpagesize()


def rss_bytes():
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * PAGE


class Messages:
    """Counts errors and warnings of the objects it watches."""

    def __init__(self):
        self.lines = []

    def watch(self, obj):
        for event in (vtkCommand.ErrorEvent, vtkCommand.WarningEvent):
            obj.AddObserver(event, self.record)

    def record(self, obj, event):
        self.lines.append("%s: %s" % (obj.GetClassName(), event))


def sphere_mesh(theta, phi):
    source = vtkSphereSource()
    source.SetThetaResolution(theta)
    source.SetPhiResolution(phi)
    source.Update()
    return source.GetOutput()


def built(builder_class, mesh):
    builder = builder_class()
    builder.SetInputData(mesh)
    builder.Update()
    out = vtkPolyData()
    out.ShallowCopy(builder.GetOutput())
    return out


def moved(mesh, dx, dy, dz):
    """A deep copy moved by (dx, dy, dz): new arrays, as new data would be."""
    copy = vtkPolyData()
    copy.DeepCopy(mesh)
    points = copy.GetPoints()
    for p in range(points.GetNumberOfPoints()):
        x, y, z = points.GetPoint(p)
        points.SetPoint(p, x + dx, y + dy, z + dz)
    return copy


class Scene:
    def __init__(self, args, messages):
        self.args = args
        self.messages = messages
        # A pool of TOMs of several sizes and one merge tree, built once.
        self.toms = [built(vtkTOMBuilder, sphere_mesh(t, p))
                     for t, p in ((16, 12), (32, 24), (64, 48), (96, 64))]
        self.tree = built(vtkMergeTreeBuilder, sphere_mesh(128, 96))
        self.renderer = vtkTimeCriticalRenderer()
        self.renderer.SetTargetFrameTime(args.target)
        self.renderer.ViewDependentRefinementOn()
        messages.watch(self.renderer)
        self.window = vtkRenderWindow()
        self.window.SetOffScreenRendering(1)
        self.window.SetSize(args.size, args.size)
        self.window.AddRenderer(self.renderer)
        messages.watch(self.window)
        self.actors = []
        self.generation = 0
        for slot in range(args.actors):
            self.add_actor(slot)
        self.renderer.ResetCamera()
        self.camera = self.renderer.GetActiveCamera()
        self.distance = self.camera.GetDistance()

    def blocks(self, slot):
        """The composite input of one actor: leaves vary with the generation."""
        self.generation += 1
        k = self.args.leaves + self.generation % 3
        grid = int(math.ceil(math.sqrt(self.args.actors)))
        x0, y0 = 9.0 * (slot % grid), 9.0 * (slot // grid)
        blocks = vtkMultiBlockDataSet()
        for leaf in range(k):
            if (self.generation + leaf) % 7 == 0:
                source = self.tree
            else:
                source = self.toms[(self.generation + leaf) % len(self.toms)]
            blocks.SetBlock(leaf, moved(source, x0 + 2.5 * (leaf % 3), y0 + 2.5 * (leaf // 3),
                                        0.0))
        return blocks

    def add_actor(self, slot):
        mapper = vtkMultiresolutionPolyDataMapper()
        self.messages.watch(mapper)
        mapper.SetInputDataObject(self.blocks(slot))
        actor = vtkActor()
        actor.SetMapper(mapper)
        self.renderer.AddActor(actor)
        self.actors.append((slot, actor))

    def churn(self):
        """Remove the oldest actor, add a new one in its place, replace one input."""
        slot, actor = self.actors.pop(0)
        self.renderer.RemoveActor(actor)
        self.add_actor(slot)
        slot, actor = self.actors[len(self.actors) // 2]
        actor.GetMapper().SetInputDataObject(self.blocks(slot))

    def move_camera(self, frame):
        angle = 2.0 * math.pi * frame / 600.0
        zoom = 0.75 + 0.35 * math.sin(2.0 * math.pi * frame / 1700.0)
        focal = self.camera.GetFocalPoint()
        d = self.distance * zoom
        self.camera.SetPosition(focal[0] + d * math.sin(angle), focal[1] - 0.3 * d,
                                focal[2] + d * math.cos(angle))
        self.renderer.ResetCameraClippingRange()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--frames", type=int, default=10000)
    parser.add_argument("--cycle", type=int, default=250,
                        help="frames between scene changes (default 250)")
    parser.add_argument("--actors", type=int, default=30)
    parser.add_argument("--leaves", type=int, default=6, help="objects per actor (about)")
    parser.add_argument("--target", type=float, default=0.05, help="target frame time (s)")
    parser.add_argument("--size", type=int, default=400, help="window size (pixels)")
    parser.add_argument("--max-growth-mb", type=float, default=16.0)
    parser.add_argument("--json", default="soak.json")
    args = parser.parse_args()
    if args.frames < 1 or args.cycle < 1:
        parser.error("--frames and --cycle must be positive")

    messages = Messages()
    heap_in_use = heap_in_use_function()
    scene = Scene(args, messages)
    series = {key: [] for key in ("wall", "measured", "predicted", "triangles", "objects",
                                  "rss", "heap", "heap_free")}
    start = time.perf_counter()
    for frame in range(args.frames):
        if frame > 0 and frame % args.cycle == 0:
            scene.churn()
        scene.move_camera(frame)
        t0 = time.perf_counter()
        scene.window.Render()
        series["wall"].append(time.perf_counter() - t0)
        r = scene.renderer
        series["measured"].append(r.GetMeasuredFrameTime())
        series["predicted"].append(r.GetPredictedFrameTime())
        series["triangles"].append(r.GetTrianglesDrawn())
        series["objects"].append(r.GetNumberOfObjects())
        series["rss"].append(rss_bytes())
        used, free = heap_in_use() if heap_in_use else (None, None)
        series["heap"].append(used)
        series["heap_free"].append(free)
        if (frame + 1) % 1000 == 0 or frame + 1 == args.frames:
            recent = series["wall"][-1000:]
            print("frame %6d  wall median %.1f ms  p99 %.1f ms  RSS %.1f MiB  heap %s  "
                  "objects %d" % (frame + 1, 1e3 * statistics.median(recent),
                                  1e3 * sorted(recent)[int(0.99 * (len(recent) - 1))],
                                  series["rss"][-1] / 2**20,
                                  "%.1f MiB (+%.1f free held)" % (series["heap"][-1] / 2**20,
                                                                 series["heap_free"][-1] / 2**20)
                                  if heap_in_use else "n/a", series["objects"][-1]),
                  flush=True)
    elapsed = time.perf_counter() - start

    # Memory after the warm-up, at the frame before each later scene change.
    warm = max(2 * args.cycle, args.frames // 10)
    checks = [f - 1 for f in range(warm, args.frames + 1, args.cycle) if f - 1 < args.frames]
    if not checks or checks[-1] != args.frames - 1:
        checks.append(args.frames - 1)
    failures = []
    growth = {}
    for key in ("heap", "heap_free", "rss"):
        if series[key][0] is None:
            continue
        # The trend, not the spread: the scene's content (and so its memory)
        # changes by design from cycle to cycle; a leak shows as a slope.
        xs = checks
        ys = [series[key][f] for f in xs]
        mean_x, mean_y = sum(xs) / len(xs), sum(ys) / len(ys)
        var_x = sum((x - mean_x) ** 2 for x in xs)
        slope = sum((x - mean_x) * (y - mean_y) for x, y in zip(xs, ys)) / var_x if var_x else 0.0
        growth[key] = slope * (xs[-1] - xs[0])
    # The heap in use decides (what our code allocates and keeps); RSS also
    # holds the allocator's fragmentation and is reported only.
    if "heap" in growth and growth["heap"] > args.max_growth_mb * 2**20:
        failures.append("heap in use grew by %.1f MiB (trend) after the warm-up (frame %d), "
                        "more than %.1f" % (growth["heap"] / 2**20, checks[0] + 1,
                                            args.max_growth_mb))
    if messages.lines:
        failures.append("%d VTK errors or warnings, first: %s"
                        % (len(messages.lines), messages.lines[0]))

    summary = {
        "frames": args.frames, "cycle": args.cycle, "actors": args.actors,
        "target_frame_time": args.target, "seconds": elapsed,
        "wall_median": statistics.median(series["wall"]),
        "wall_max": max(series["wall"]),
        "rss_start": series["rss"][0], "rss_end": series["rss"][-1],
        "rss_after_warmup": series["rss"][checks[0]],
        "trend_after_warmup": growth, "messages": messages.lines[:20],
        "failures": failures,
    }
    with open(args.json, "w") as out:
        json.dump({"summary": summary, "series": series}, out)
    print("soak: %d frames in %.0f s, Render() median %.1f ms, RSS %.1f -> %.1f MiB "
          "(%.1f after warm-up), trend after warm-up: %s; %s"
          % (args.frames, elapsed, 1e3 * summary["wall_median"], series["rss"][0] / 2**20,
             series["rss"][-1] / 2**20, series["rss"][checks[0]] / 2**20,
             ", ".join("%s %.2f MiB" % (k, v / 2**20) for k, v in growth.items()),
             args.json))
    for failure in failures:
        print("FAILED: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
