# SPDX-License-Identifier: BSD-3-Clause
"""W5: the Time-Critical Render View on a multiblock unlike W1 (run by pvbatch).

The scene: --blocks blocks (default 300) of mixed shapes and sizes, about
--triangles triangles in all (default 3.5M): spheres, superquadrics, tori and
capped cylinders from a few hundred to ~150K triangles each, scattered in a
40 x 40 x 8 box, a few leaves also holding vertex and line cells. It is
written once as a .vtm (binary, not appended) and read back by ParaView's
reader, as a user would open it.

The flight: --frames interactive frames (default 60) at --target-ms (default
100): from a view of the whole scene in close to the largest object, past it,
a sudden turn of 150 degrees in one frame, and out again. Every frame is an
interactive render of the view (view.InteractiveRender(), as a drag in the GUI
gives); its wall time is what the user waits. The same scene and path are
then drawn at VTK level (vtkMultiresolutionHierarchyBuilder,
vtkMultiresolutionPolyDataMapper, vtkTimeCriticalRenderer) for comparison,
unless --skip-vtk.

Writes <output>/w5.json (per frame: wall and renderer-measured times,
predicted time, triangles, objects drawn) and prints the share of frames
within 110% of the target for each, with the goal (>= 99%).

Usage: pvbatch --force-offscreen-rendering scripts/w5_benchmark.py
           --plugin <build>/lib/paraview-plugins/TimeCritical/TimeCritical.so
           [--output w5-output] [--runs 1] [--quick]
PYTHONPATH must reach the build's lib/python3/dist-packages (the timecritical
package); scripts/run-w5.sh sets it up.
"""

import argparse
import json
import math
import os
import random
import statistics
import sys
import time


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--plugin", required=True, help="TimeCritical.so of the build")
    parser.add_argument("--output", default="w5-output")
    parser.add_argument("--blocks", type=int, default=300)
    parser.add_argument("--triangles", type=float, default=3.5e6)
    parser.add_argument("--frames", type=int, default=60)
    parser.add_argument("--target-ms", type=float, default=100.0)
    parser.add_argument("--size", default="800x600")
    parser.add_argument("--runs", type=int, default=1, help="flights per renderer")
    parser.add_argument("--skip-vtk", action="store_true", help="the view only")
    parser.add_argument("--quick", action="store_true",
                        help="30 blocks, 150K triangles, 20 frames (a smoke test)")
    args = parser.parse_args()
    if args.quick:
        args.blocks, args.triangles, args.frames = 30, 1.5e5, 20
    args.width, args.height = (int(v) for v in args.size.split("x"))
    return args


# ---------------------------------------------------------------------------
# The scene

def shape(kind, resolution, radius):
    """One closed surface of about the given resolution, centred at 0."""
    from vtkmodules.vtkCommonComputationalGeometry import vtkParametricTorus
    from vtkmodules.vtkFiltersCore import vtkPolyDataNormals, vtkTriangleFilter
    from vtkmodules.vtkFiltersSources import (vtkCylinderSource, vtkParametricFunctionSource,
                                              vtkSphereSource, vtkSuperquadricSource)
    if kind == "sphere":
        source = vtkSphereSource()
        source.SetThetaResolution(resolution)
        source.SetPhiResolution(resolution)
        source.SetRadius(radius)
    elif kind == "superquadric":
        source = vtkSuperquadricSource()
        source.SetThetaResolution(resolution)
        source.SetPhiResolution(resolution)
        source.SetSize(radius)
        source.SetThetaRoundness(0.4)
        source.SetPhiRoundness(0.7)
    elif kind == "torus":
        torus = vtkParametricTorus()
        torus.SetRingRadius(radius)
        torus.SetCrossSectionRadius(0.35 * radius)
        source = vtkParametricFunctionSource()
        source.SetParametricFunction(torus)
        source.SetUResolution(resolution)
        source.SetVResolution(max(8, resolution // 2))
    else:
        source = vtkCylinderSource()
        source.SetResolution(resolution)
        source.SetRadius(0.5 * radius)
        source.SetHeight(2.0 * radius)
        source.SetCapping(True)
    triangles = vtkTriangleFilter()
    triangles.SetInputConnection(source.GetOutputPort())
    normals = vtkPolyDataNormals()
    normals.SetSplitting(False)
    normals.SetInputConnection(triangles.GetOutputPort())
    normals.Update()
    return normals.GetOutput()


def triangles_of(kind, resolution):
    """Triangles shape() gives for a resolution (close enough to plan sizes)."""
    if kind in ("sphere", "superquadric"):
        return 2 * resolution * resolution
    if kind == "torus":
        return resolution * max(8, resolution // 2) * 2
    return 4 * resolution


def plan_blocks(args, rng):
    """Kinds, sizes and resolutions: a few large objects, many small ones."""
    kinds = ["sphere", "superquadric", "torus", "cylinder"]
    plans = []
    for b in range(args.blocks):
        kind = kinds[b % len(kinds)]
        weight = rng.paretovariate(1.2)  # heavy tail: a few objects hold most triangles
        plans.append({"kind": kind, "weight": weight,
                      "radius": 0.15 + 0.35 * min(weight, 6.0) * rng.uniform(0.6, 1.4),
                      "centre": [rng.uniform(0, 40), rng.uniform(0, 40), rng.uniform(0, 8)]})
    total_weight = sum(p["weight"] for p in plans)
    scale = 1.0  # raised until the clamped resolutions add up to the wanted total
    for _ in range(20):
        for p in plans:
            wanted = scale * args.triangles * p["weight"] / total_weight
            if p["kind"] in ("sphere", "superquadric"):
                resolution = math.sqrt(wanted / 2.0)
            elif p["kind"] == "torus":
                resolution = math.sqrt(wanted)
            else:
                resolution = wanted / 4.0
            p["resolution"] = int(min(450, max(8, resolution)))
        planned = sum(triangles_of(p["kind"], p["resolution"]) for p in plans)
        if planned >= 0.98 * args.triangles:
            break
        scale *= min(2.0, args.triangles / planned)
    return plans


def add_vertices_and_lines(poly):
    """A polyline along the first points and a vertex cell: a leaf with mixed cells."""
    from vtkmodules.vtkCommonDataModel import vtkCellArray
    lines, verts = vtkCellArray(), vtkCellArray()
    count = min(20, poly.GetNumberOfPoints())
    lines.InsertNextCell(count)
    for i in range(count):
        lines.InsertCellPoint(i)
    verts.InsertNextCell(1)
    verts.InsertCellPoint(0)
    poly.SetLines(lines)
    poly.SetVerts(verts)


def make_scene(args, path):
    from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet, vtkPolyData
    from vtkmodules.vtkCommonTransforms import vtkTransform
    from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
    from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataWriter
    rng = random.Random(5)
    plans = plan_blocks(args, rng)
    blocks = vtkMultiBlockDataSet()
    blocks.SetNumberOfBlocks(len(plans))
    total = 0
    for b, p in enumerate(plans):
        surface = shape(p["kind"], p["resolution"], p["radius"])
        transform = vtkTransform()
        transform.Translate(*p["centre"])
        transform.RotateWXYZ(rng.uniform(0, 180), rng.random(), rng.random(), rng.random())
        moved = vtkTransformPolyDataFilter()
        moved.SetTransform(transform)
        moved.SetInputData(surface)
        moved.Update()
        leaf = vtkPolyData()
        leaf.DeepCopy(moved.GetOutput())
        if b % 60 == 7:
            add_vertices_and_lines(leaf)
        total += leaf.GetNumberOfPolys()
        blocks.SetBlock(b, leaf)
    writer = vtkXMLMultiBlockDataWriter()
    writer.SetFileName(path)
    writer.SetDataModeToBinary()  # not appended: Debian's expat breaks appended reads
    writer.SetInputData(blocks)
    writer.Write()
    largest = max(range(len(plans)), key=lambda b: plans[b]["weight"])
    return {"blocks": len(plans), "triangles": total, "focus": plans[largest]["centre"],
            "focus_radius": plans[largest]["radius"]}


# ---------------------------------------------------------------------------
# The flight

def flight(scene, frames):
    """Camera positions, focal points: in, past, a sudden turn, out."""
    focus = scene["focus"]
    start = [20.0, -35.0, 30.0]
    centre = [20.0, 20.0, 4.0]
    near = [focus[0], focus[1] - 2.5 * scene["focus_radius"] - 0.5, focus[2] + 0.5]
    path = []
    inward = frames // 3
    past = frames // 6
    outward = frames - inward - past - 1
    for i in range(inward):  # whole scene -> close to the largest object
        t = (i + 1) / inward
        s = t * t * (3 - 2 * t)
        position = [a + s * (b - a) for a, b in zip(start, near)]
        focal = [a + s * (b - a) for a, b in zip(centre, focus)]
        path.append((position, focal))
    for i in range(past):  # sliding past it
        position = [near[0] + 0.15 * (i + 1), near[1], near[2]]
        path.append((position, [focus[0] + 0.15 * (i + 1), focus[1], focus[2]]))
    position, focal = path[-1]
    # A sudden turn: 150 degrees about the vertical in one frame.
    angle = math.radians(150.0)
    dx, dy = focal[0] - position[0], focal[1] - position[1]
    turned = [position[0] + dx * math.cos(angle) - dy * math.sin(angle),
              position[1] + dx * math.sin(angle) + dy * math.cos(angle), focal[2]]
    path.append((position, turned))
    for i in range(outward):  # back out over the scene
        t = (i + 1) / outward
        out = [position[0] + t * (start[0] - position[0]), position[1] + t * (start[1] - position[1]),
               position[2] + t * (start[2] + 10 - position[2])]
        look = [turned[0] + t * (centre[0] - turned[0]), turned[1] + t * (centre[1] - turned[1]),
                turned[2] + t * (centre[2] - turned[2])]
        path.append((out, look))
    return path


def summarize(frames, target_ms, key):
    times = [f[key] for f in frames if f[key] is not None]
    within = sum(t <= 1.1 * target_ms for t in times)
    return {"frames": len(times), "median_ms": statistics.median(times), "max_ms": max(times),
            "mean_ms": statistics.mean(times),
            "share_within_110_percent": within / len(times)}


def run_view(args, scene_path, scene):
    from paraview.simple import (CreateView, Delete, GetActiveCamera, Hide, OpenDataFile,
                                 Render, Show)
    reader = OpenDataFile(scene_path)
    view = CreateView("TimeCriticalRenderView")
    view.ViewSize = [args.width, args.height]
    view.OrientationAxesVisibility = 0
    view.TargetFrameTime = args.target_ms
    rep = Show(reader, view)
    start = time.perf_counter()
    Render(view)  # reads, builds the hierarchies, the still frame
    first_seconds = time.perf_counter() - start
    renderer = view.GetClientSideObject().GetTimeCriticalRenderer()
    camera = GetActiveCamera()
    runs = []
    for run in range(args.runs):
        frames = []
        for position, focal in flight(scene, args.frames):
            camera.SetPosition(*position)
            camera.SetFocalPoint(*focal)
            camera.SetViewUp(0.0, 0.0, 1.0)
            begin = time.perf_counter()
            view.InteractiveRender()
            wall = 1000.0 * (time.perf_counter() - begin)
            frames.append({"wall_ms": wall,
                           "measured_ms": 1000.0 * renderer.GetMeasuredFrameTime(),
                           "predicted_ms": 1000.0 * renderer.GetPredictedFrameTime(),
                           "fixed_ms": 1000.0 * renderer.GetFixedFrameTime(),
                           "triangles": renderer.GetObjectTrianglesDrawn(),
                           "objects": renderer.GetNumberOfObjects(),
                           "culled": renderer.GetNumberOfCulledObjects(),
                           "still": bool(renderer.GetLastRenderWasStill())})
        runs.append({"frames": frames, "wall": summarize(frames, args.target_ms, "wall_ms")})
    Hide(reader, view)
    Delete(view)
    return {"first_render_seconds": first_seconds, "runs": runs}


def run_vtk(args, scene_path, scene):
    from timecritical import (vtkMultiresolutionHierarchyBuilder,
                              vtkMultiresolutionPolyDataMapper, vtkTimeCriticalRenderer)
    from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataReader
    from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderWindow
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
    reader = vtkXMLMultiBlockDataReader()
    reader.SetFileName(scene_path)
    builder = vtkMultiresolutionHierarchyBuilder()
    builder.SetInputConnection(reader.GetOutputPort())
    builder.Update()
    mapper = vtkMultiresolutionPolyDataMapper()
    mapper.SetInputConnection(builder.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer = vtkTimeCriticalRenderer()
    renderer.AddActor(actor)
    renderer.SetTargetFrameTime(args.target_ms / 1000.0)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetSize(args.width, args.height)
    window.AddRenderer(renderer)
    renderer.ResetCamera()
    renderer.StillRender()
    camera = renderer.GetActiveCamera()
    runs = []
    for run in range(args.runs):
        frames = []
        for position, focal in flight(scene, args.frames):
            camera.SetPosition(*position)
            camera.SetFocalPoint(*focal)
            camera.SetViewUp(0.0, 0.0, 1.0)
            renderer.ResetCameraClippingRange()
            begin = time.perf_counter()
            window.Render()
            wall = 1000.0 * (time.perf_counter() - begin)
            frames.append({"wall_ms": wall,
                           "measured_ms": 1000.0 * renderer.GetMeasuredFrameTime(),
                           "predicted_ms": 1000.0 * renderer.GetPredictedFrameTime(),
                           "fixed_ms": 1000.0 * renderer.GetFixedFrameTime(),
                           "triangles": renderer.GetObjectTrianglesDrawn(),
                           "objects": renderer.GetNumberOfObjects(),
                           "culled": renderer.GetNumberOfCulledObjects(),
                           "still": bool(renderer.GetLastRenderWasStill())})
        runs.append({"frames": frames, "wall": summarize(frames, args.target_ms, "wall_ms")})
    return {"runs": runs}


def check_result(result, args):
    """Every flight has its frames, each drawn and timed: else the run is not a measurement."""
    for name in ("view", "vtk"):
        for run in result.get(name, {}).get("runs", []):
            frames = run["frames"]
            problems = []
            if len(frames) != args.frames:
                problems.append("%d frames, not %d" % (len(frames), args.frames))
            if any(not (f["wall_ms"] > 0.0) for f in frames):
                problems.append("a frame without a time")
            if not any(f["triangles"] > 0 for f in frames):
                problems.append("no frame drew a triangle")
            if any(f["still"] for f in frames):
                problems.append("a still frame in the flight (not budgeted)")
            if problems:
                print("W5 check FAILED (%s): %s" % (name, "; ".join(problems)))
                sys.stdout.flush()
                os._exit(1)
    print("W5 checks passed")


def main():
    args = parse_arguments()
    from paraview.simple import LoadPlugin
    LoadPlugin(args.plugin, remote=False, ns=globals())
    from timecritical import TimeCriticalViews  # noqa: F401  (the view's Python wrapping)
    os.makedirs(args.output, exist_ok=True)
    scene_path = os.path.join(args.output, "w5-scene-%d-%d.vtm" % (args.blocks, args.triangles))
    info_path = scene_path + ".json"
    if os.path.isfile(info_path):
        with open(info_path) as stream:
            scene = json.load(stream)
    else:
        scene = make_scene(args, scene_path)
        with open(info_path, "w") as stream:
            json.dump(scene, stream)
    print("scene: %d blocks, %d triangles" % (scene["blocks"], scene["triangles"]))
    result = {"scene": scene, "target_ms": args.target_ms, "frames": args.frames,
              "load_average": os.getloadavg()[0], "view": run_view(args, scene_path, scene)}
    if not args.skip_vtk:
        result["vtk"] = run_vtk(args, scene_path, scene)
    goal = 0.99
    met = True
    for name in ("view", "vtk"):
        if name not in result:
            continue
        for r, run in enumerate(result[name]["runs"]):
            s = run["wall"]
            ok = s["share_within_110_percent"] >= goal
            met = met and (ok or name != "view")
            print("%-4s run %d: median %.1f ms, mean %.1f ms, max %.1f ms, %.1f%% of frames within "
                  "%.0f ms (goal >= 99%%: %s)" % (name, r, s["median_ms"], s["mean_ms"], s["max_ms"],
                                                 100.0 * s["share_within_110_percent"],
                                                 1.1 * args.target_ms, "met" if ok else "MISSED"))
    result["goal_met"] = met
    check_result(result, args)
    path = os.path.join(args.output, "w5.json")
    with open(path, "w") as stream:
        json.dump(result, stream, indent=1)
    print("JSON: %s" % path)
    sys.stdout.flush()


main()
