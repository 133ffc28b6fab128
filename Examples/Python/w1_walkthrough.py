# SPDX-License-Identifier: BSD-3-Clause
"""The W1 walkthrough in ParaView's Time-Critical Render View (pvbatch or pvpython).

Opens the W1 scene (529 cows, 3,070,316 triangles; written by
scripts/make_w1_scene.py, generated here when missing), shows it in a
TimeCriticalRenderView (512x512, target 100 ms, statistics overlay on, every
frame of the path budgeted), flies the W1 camera path (A -> B -> sudden turn ->
C, 240 frames), prints per-frame statistics and a summary, and writes them to
JSON with the key frames as PNG. At the end it renders the last camera once
more budgeted and once at full resolution (a still render) and compares them.

    export TIMECRITICAL_PLUGIN=$PWD/build/lib/paraview-plugins/TimeCritical/TimeCritical.so
    xvfb-run -a pvbatch --force-offscreen-rendering Examples/Python/w1_walkthrough.py
    pvpython Examples/Python/w1_walkthrough.py --objects 16 --frames 10   # a quick look

Options: see --help. --full-resolution-pass flies the path a second time at
full resolution for each frame's full-resolution time and the PSNR of the
budgeted frame against it (as the C++ WalkthroughBenchmark does); --check
makes the exit status fail when a frame breaks the view's contract (used as
a smoke test).

The plugin is found from --plugin, TIMECRITICAL_PLUGIN or the build folder
($TIMECRITICAL_BUILD_DIR, default <repository>/build); the
`timecritical` Python package (for the renderer's statistics) from PYTHONPATH
or next to the plugin in the same build or install tree. Frame times are
wall-clock around the view's render (glFinish included, image capture
excluded); the renderer's own measurement and prediction are printed next to
them. Run it on a quiet machine: a shared CPU makes frame times noisy.
"""

import argparse
import json
import math
import os
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPOSITORY = os.path.normpath(os.path.join(HERE, "..", ".."))


def parse_arguments():
    parser = argparse.ArgumentParser(
        description="Fly the W1 walkthrough (Gobbetti & Bouvier's 529 cows) in the "
                    "TimeCritical plugin's Time-Critical Render View and report frame times.")
    parser.add_argument("--plugin", default=os.environ.get("TIMECRITICAL_PLUGIN"),
                        help="TimeCritical.so (default: $TIMECRITICAL_PLUGIN, else "
                             "./build/lib/paraview-plugins/TimeCritical/TimeCritical.so)")
    parser.add_argument("--output", default="w1-output",
                        help="folder for w1_walkthrough.json and the PNG images "
                             "(default: %(default)s)")
    parser.add_argument("--scene", default=None,
                        help="scene folder of make_w1_scene.py (default: OUTPUT/scene); "
                             "written there when missing or made for other --objects/--seed")
    parser.add_argument("--objects", type=int, default=529, help="cows (default: %(default)s)")
    parser.add_argument("--frames", type=int, default=240,
                        help="frames of the camera path (default: %(default)s)")
    parser.add_argument("--seed", type=int, default=20001,
                        help="placement seed (default: %(default)s, the C++ benchmark's)")
    parser.add_argument("--mesh", default=None,
                        help="the object's OBJ file (default: ../shared/data/cow.obj)")
    parser.add_argument("--target", type=float, default=100.0,
                        help="target frame time in ms (default: %(default)s)")
    parser.add_argument("--policy", default="Active-Set Optimization",
                        help="the view's Policy (default: %(default)s)")
    parser.add_argument("--warmup", type=int, default=3,
                        help="untimed renders at the first camera after the first render "
                             "(default: %(default)s, as the C++ benchmark)")
    parser.add_argument("--interactive", action="store_true",
                        help="render each frame with view.InteractiveRender() instead of "
                             "StillRender() with FullResolutionAtRest off")
    parser.add_argument("--full-resolution-pass", action="store_true",
                        help="fly the path again at full resolution: each frame's "
                             "full-resolution time and the budgeted frame's PSNR against it")
    parser.add_argument("--no-statistics", action="store_true",
                        help="hide the view's statistics overlay")
    parser.add_argument("--no-images", action="store_true", help="write no PNG images")
    parser.add_argument("--quiet", action="store_true", help="no per-frame lines")
    parser.add_argument("--check", action="store_true",
                        help="exit 1 when a frame breaks the view's contract (smoke test)")
    args = parser.parse_args()
    if args.objects < 1 or args.frames < 4 or args.target <= 0:
        parser.error("--objects >= 1, --frames >= 4 and --target > 0 are required")
    return args


# ---------------------------------------------------------------------------
# Finding the plugin, its Python package and the scene generator

def find_plugin(args):
    candidates = [args.plugin] if args.plugin else [
        os.path.join(os.environ.get("TIMECRITICAL_BUILD_DIR", os.path.join(REPOSITORY, "build")),
                     "lib", "paraview-plugins", "TimeCritical", "TimeCritical.so")]
    for path in candidates:
        if path and os.path.isfile(path):
            return os.path.abspath(path)
    sys.exit("w1_walkthrough: the TimeCritical plugin was not found (%s): pass --plugin or set "
             "TIMECRITICAL_PLUGIN to <build>/lib/paraview-plugins/TimeCritical/TimeCritical.so"
             % ", ".join(str(c) for c in candidates))


def import_timecritical(plugin):
    """Imports the timecritical package (it wraps the renderer whose statistics
    the script reads), from PYTHONPATH or from the build (or install) tree the
    plugin belongs to: <tree>/lib/python3/dist-packages."""
    try:
        import timecritical  # noqa: F401
    except ImportError:
        lib = os.path.dirname(os.path.dirname(os.path.dirname(plugin)))
        sys.path.insert(0, os.path.join(lib, "python3", "dist-packages"))
        try:
            import timecritical  # noqa: F401
        except ImportError:
            sys.exit("w1_walkthrough: cannot import the timecritical Python package: set "
                     "PYTHONPATH to <build>/lib/python3/dist-packages")
    from timecritical import TimeCriticalViews  # noqa: F401  (wraps the view's classes)


def import_scene_generator():
    sys.path.insert(0, os.path.join(REPOSITORY, "scripts"))
    import make_w1_scene
    return make_w1_scene


# ---------------------------------------------------------------------------
# Images and statistics

def capture(view):
    """The image the view's last render left in its window, as rows x columns
    x RGB uint8 (top row first), without rendering again."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
    grab = vtkWindowToImageFilter()
    grab.SetInput(view.GetRenderWindow())
    grab.ShouldRerenderOff()
    grab.ReadFrontBufferOff()
    grab.Update()
    image = grab.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())
    return pixels.reshape(height, width, -1)[::-1, :, :3].copy()


def write_png(pixels, path):
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonDataModel import vtkImageData
    from vtkmodules.vtkIOImage import vtkPNGWriter
    height, width, _ = pixels.shape
    image = vtkImageData()
    image.SetDimensions(width, height, 1)
    image.GetPointData().SetScalars(numpy_to_vtk(pixels[::-1].reshape(-1, 3), deep=True))
    writer = vtkPNGWriter()
    writer.SetInputData(image)
    writer.SetFileName(path)
    writer.Write()


# Rows at the top that hold the statistics overlay: left out of the PSNR when
# it is shown, since its text differs between a budgeted and a full frame.
OVERLAY_ROWS = 96


def psnr(image, reference, skip_rows=0):
    import numpy as np
    a = image[skip_rows:].astype(np.float64)
    b = reference[skip_rows:].astype(np.float64)
    mse = float(np.mean((a - b) ** 2))
    return 99.0 if mse == 0 else min(99.0, 10.0 * math.log10(255.0 ** 2 / mse))


def summarize(values):
    values = [v for v in values if v is not None and math.isfinite(v)]
    if not values:
        return {"n": 0}
    mean = statistics.fmean(values)
    return {"n": len(values), "mean": mean, "median": statistics.median(values),
            "min": min(values), "max": max(values),
            "cv": statistics.pstdev(values) / mean if mean > 0 else None}


def load_average():
    try:
        with open("/proc/loadavg") as stream:
            return [float(x) for x in stream.read().split()[:3]]
    except OSError:
        return None


# ---------------------------------------------------------------------------
# The walkthrough

class Walkthrough:
    def __init__(self, view, path, target_ms, interactive):
        self.view = view
        self.path = path
        self.target = target_ms / 1000.0
        self.interactive = interactive
        self.renderer = view.GetClientSideObject().GetRenderer()
        self.window = view.GetRenderWindow()

    def move_to(self, frame):
        view, path = self.view, self.path
        view.CameraPosition = path["position"][frame]
        view.CameraFocalPoint = path["focal_point"][frame]
        view.CameraViewUp = path["view_up"][frame]
        view.CameraViewAngle = path["view_angle"][frame]

    def render(self, full_resolution=False):
        """One frame, timed: wall-clock seconds around the render and glFinish."""
        self.view.FullResolutionAtRest = 1 if (full_resolution or self.interactive) else 0
        start = time.perf_counter()
        if self.interactive and not full_resolution:
            self.view.InteractiveRender()
        else:
            self.view.StillRender()
        self.window.WaitForCompletion()
        return time.perf_counter() - start

    def record(self, frame, wall):
        r = self.renderer
        return {"frame": frame, "wall_ms": 1000.0 * wall,
                "measured_ms": 1000.0 * r.GetMeasuredFrameTime(),
                "predicted_ms": 1000.0 * r.GetPredictedFrameTime(),
                "fixed_ms": 1000.0 * r.GetFixedFrameTime(),
                "target_ms": 1000.0 * r.GetLastTargetFrameTime()
                if math.isfinite(r.GetLastTargetFrameTime()) else None,
                "still": bool(r.GetLastRenderWasStill()),
                "triangles": r.GetObjectTrianglesDrawn(),
                "objects": r.GetNumberOfObjects(), "culled": r.GetNumberOfCulledObjects(),
                "optimizer_ms": 1000.0 * r.GetOptimizationTime(),
                "iterations": r.GetOptimizationIterations(),
                "safety_margin_ms": 1000.0 * r.GetSafetyMargin()}


def main():
    args = parse_arguments()
    plugin = find_plugin(args)
    os.makedirs(args.output, exist_ok=True)
    scene_folder = args.scene or os.path.join(args.output, "scene")
    load_start = load_average()

    import_timecritical(plugin)
    generator = import_scene_generator()
    scene, path = generator.ensure_scene(scene_folder, args.objects, args.seed, args.frames,
                                         args.mesh)
    keys = {frame: name for name, frame in path["key_frames"].items()}

    from paraview import simple
    simple.LoadPlugin(plugin, remote=False, ns={})

    # The scene, coloured by the cows' own RGB colours.
    reader = simple.OpenDataFile(os.path.join(scene_folder, "scene.vtm"))
    view = simple.CreateView("TimeCriticalRenderView")
    view.ViewSize = path["window"]
    view.OrientationAxesVisibility = 0
    if "UseColorPaletteForBackground" in view.ListProperties():
        view.UseColorPaletteForBackground = 0
    view.Background = path["background"]
    view.TargetFrameTime = args.target
    view.Policy = args.policy
    view.ShowStatistics = 0 if args.no_statistics else 1
    view.FullResolutionAtRest = 1 if args.interactive else 0
    rep = simple.Show(reader, view)
    simple.ColorBy(rep, ("POINTS", "Colors"))
    rep.MapScalars = 0
    walk = Walkthrough(view, path, args.target, args.interactive)
    renderer = walk.renderer
    if not renderer.IsA("vtkTimeCriticalRenderer"):
        sys.exit("w1_walkthrough: the view's renderer is a %s" % renderer.GetClassName())

    # First render: reads the scene, builds the hierarchy if the leaves are no
    # TOMs yet, uploads it, calibrates the cost model. Then warm-up frames.
    walk.move_to(0)
    first = walk.render()
    print("W1 in the Time-Critical Render View: %d cows x %d triangles = %s triangles, %d frames, "
          "target %.0f ms, policy %s, %s renders" % (
              scene["objects"], scene["triangles_per_object"], format(scene["triangles"], ","),
              args.frames, args.target, args.policy,
              "interactive" if args.interactive else "budgeted still"))
    print("first render (read, hierarchy, upload, calibration %.2f s): %.2f s; cost model: "
          "frame %.2f ms, draw call %.3f ms, triangle %.2f ns, pixel %.2f ns" % (
              renderer.GetCalibrationTime(), first, 1e3 * renderer.GetFrameCost(),
              1e3 * renderer.GetDrawCallCost(), 1e9 * renderer.GetTriangleCost(),
              1e9 * renderer.GetPixelCost()))
    for _ in range(args.warmup):
        walk.render()

    # The budgeted flight.
    frames, images = [], {}
    keep_all = args.full_resolution_pass
    budgeted_images = [None] * args.frames
    if not args.quiet:
        print("frame key    wall  measured predicted  triangles  drawn culled  opt.ms")
    for frame in range(args.frames):
        walk.move_to(frame)
        wall = walk.render()
        record = walk.record(frame, wall)
        frames.append(record)
        if keep_all or frame in keys:
            image = capture(view)
            if keep_all:
                budgeted_images[frame] = image
            if frame in keys:
                images[keys[frame]] = image
        if not args.quiet:
            print("%5d %-5s %7.1f %8.1f %8.1f %10s %6d %6d %7.3f" % (
                frame, keys.get(frame, ""), record["wall_ms"], record["measured_ms"],
                record["predicted_ms"], format(record["triangles"], ","),
                record["objects"] - record["culled"], record["culled"], record["optimizer_ms"]))
        if frame in keys and not args.quiet:
            print("      " + view.GetClientSideObject().GetStatisticsText().replace("\n", "\n      "))

    skip = 0 if args.no_statistics else OVERLAY_ROWS
    # The last camera once more, at rest: budgeted, then as a full-resolution still.
    last = args.frames - 1
    walk.move_to(last)
    budget_wall = walk.render()
    budget = walk.record(last, budget_wall)
    budget_image = capture(view)
    still_wall = walk.render(full_resolution=True)
    still = walk.record(last, still_wall)
    still_image = capture(view)
    comparison = {"frame": last, "budgeted": budget, "full_resolution": still,
                  "psnr": psnr(budget_image, still_image, skip)}
    # Optional second flight at full resolution (still renders).
    if args.full_resolution_pass:
        print("full-resolution pass...")
        for frame in range(args.frames):
            walk.move_to(frame)
            wall = walk.render(full_resolution=True)
            frames[frame]["full_wall_ms"] = 1000.0 * wall
            frames[frame]["full_triangles"] = renderer.GetObjectTrianglesDrawn()
            frames[frame]["psnr"] = psnr(budgeted_images[frame], capture(view), skip)
        budgeted_images = None

        # One budgeted frame after the pass: does the cost model come back from
        # 240 full-resolution frames at once?
        walk.move_to(last)
        comparison["budgeted_after_full_resolution_pass"] = walk.record(last, walk.render())
    load_end = load_average()

    # Summary.
    target = args.target
    walls = [f["wall_ms"] for f in frames]
    measured = [f["measured_ms"] for f in frames]
    within = lambda values: 100.0 * sum(v <= 1.1 * target for v in values) / len(values)  # noqa
    prediction_errors = [abs(f["predicted_ms"] - f["measured_ms"]) / f["measured_ms"]
                         for f in frames if f["measured_ms"] > 0]
    summary = {
        "frame_time_ms": summarize(walls), "within_110_percent": within(walls),
        "measured_ms": summarize(measured), "measured_within_110_percent": within(measured),
        "predicted_ms": summarize([f["predicted_ms"] for f in frames]),
        "prediction_error": statistics.fmean(prediction_errors) if prediction_errors else None,
        "triangles": summarize([f["triangles"] for f in frames]),
        "optimizer_ms": summarize([f["optimizer_ms"] for f in frames]),
        "still_frames_in_path": sum(f["still"] for f in frames),
    }
    if args.full_resolution_pass:
        over = [f for f in frames if f["full_wall_ms"] > target]
        summary["full_resolution_ms"] = summarize([f["full_wall_ms"] for f in frames])
        summary["full_resolution_within_110_percent"] = within([f["full_wall_ms"] for f in frames])
        summary["psnr"] = summarize([f["psnr"] for f in frames])
        summary["frames_full_resolution_over_target"] = len(over)
        if over:
            summary["over_target"] = {
                "frame_time_ms": summarize([f["wall_ms"] for f in over]),
                "within_110_percent": within([f["wall_ms"] for f in over]),
                "psnr": summarize([f["psnr"] for f in over])}

    total = scene["triangles"]
    ft = summary["frame_time_ms"]
    print("\nsummary (%d frames, target %.0f ms, load average %s -> %s):" % (
        len(frames), target, load_start and load_start[0], load_end and load_end[0]))
    print("  frame time (wall): mean %.1f, median %.1f, max %.1f ms, CV %.1f%%; %.1f%% of frames "
          "<= %.0f ms" % (ft["mean"], ft["median"], ft["max"], 100 * ft["cv"],
                          summary["within_110_percent"], 1.1 * target))
    m = summary["measured_ms"]
    print("  renderer's measurement: mean %.1f, median %.1f, max %.1f ms; %.1f%% <= %.0f ms; "
          "prediction error %.1f%%" % (m["mean"], m["median"], m["max"],
                                       summary["measured_within_110_percent"], 1.1 * target,
                                       100 * (summary["prediction_error"] or 0)))
    t = summary["triangles"]
    print("  triangles drawn: mean %s (%.1f%% of %s), min %s, max %s" % (
        format(int(t["mean"]), ","), 100.0 * t["mean"] / total, format(total, ","),
        format(int(t["min"]), ","), format(int(t["max"]), ",")))
    print("  optimizer: mean %.3f ms, max %.3f ms" % (summary["optimizer_ms"]["mean"],
                                                      summary["optimizer_ms"]["max"]))
    if args.full_resolution_pass:
        f = summary["full_resolution_ms"]
        print("  full resolution: mean %.1f, median %.1f, max %.1f ms; PSNR of the budgeted "
              "frames: median %.2f dB" % (f["mean"], f["median"], f["max"],
                                           summary["psnr"]["median"]))
        if "over_target" in summary:
            o = summary["over_target"]
            print("  over the %d frames whose full resolution exceeds %.0f ms: mean %.1f ms, CV "
                  "%.1f%%, %.1f%% <= %.0f ms, median PSNR %.2f dB" % (
                      summary["frames_full_resolution_over_target"], target,
                      o["frame_time_ms"]["mean"], 100 * o["frame_time_ms"]["cv"],
                      o["within_110_percent"], 1.1 * target, o["psnr"]["median"]))
    print("  last camera: budgeted %.1f ms, %s triangles; full-resolution still %.1f ms, %s "
          "triangles; PSNR %.2f dB" % (
              budget["wall_ms"], format(budget["triangles"], ","), still["wall_ms"],
              format(still["triangles"], ","), comparison["psnr"]))
    after = comparison.get("budgeted_after_full_resolution_pass")
    if after:
        print("  last camera after the full-resolution pass: budgeted %.1f ms (predicted %.1f, "
              "fixed part %.1f), %s triangles" % (after["wall_ms"], after["predicted_ms"],
                                                  after["fixed_ms"],
                                                  format(after["triangles"], ",")))

    if not args.no_images:
        for name, image in images.items():
            write_png(image, os.path.join(args.output, "w1_%s.png" % name))
        write_png(budget_image, os.path.join(args.output, "w1_last_budgeted.png"))
        write_png(still_image, os.path.join(args.output, "w1_last_full_resolution.png"))
    result = {"example": "Examples/Python/w1_walkthrough.py",
              "settings": {"objects": args.objects, "frames": args.frames, "seed": args.seed,
                           "target_ms": target, "policy": args.policy,
                           "interactive": args.interactive, "warmup": args.warmup,
                           "statistics_overlay": not args.no_statistics,
                           "psnr_skips_top_rows": skip, "plugin": plugin,
                           "paraview": simple.GetParaViewVersion().GetVersion()
                           if hasattr(simple, "GetParaViewVersion") else None,
                           "load_average_start": load_start, "load_average_end": load_end},
              "scene": {k: scene[k] for k in ("mesh", "substitute", "tom", "objects",
                                              "triangles_per_object", "triangles")},
              "key_frames": path["key_frames"], "first_render_s": first,
              "calibration_s": renderer.GetCalibrationTime(),
              "summary": summary, "last_camera": comparison, "frames": frames}
    json_path = os.path.join(args.output, "w1_walkthrough.json")
    with open(json_path, "w") as stream:
        json.dump(result, stream, indent=1)
    print("wrote %s" % json_path)

    status = 0
    if args.check:
        problems = []
        for f in frames:
            if f["still"] and not args.interactive:
                problems.append("frame %d was a full-resolution still" % f["frame"])
            visible = f["objects"] - f["culled"]
            if f["triangles"] > total or (visible > 0) != (f["triangles"] > 0):
                problems.append("frame %d drew %d triangles of %d visible objects"
                                % (f["frame"], f["triangles"], visible))
            if f["target_ms"] is None or abs(f["target_ms"] - target) > 1e-6 * target:
                problems.append("frame %d was planned for %s ms" % (f["frame"], f["target_ms"]))
        if not still["still"] or still["triangles"] < budget["triangles"]:
            problems.append("the full-resolution still drew %d triangles, the budgeted frame %d"
                            % (still["triangles"], budget["triangles"]))
        if float(budget_image.std()) < 1.0:
            problems.append("the last budgeted image is blank")
        for problem in problems:
            print("CHECK FAILED: " + problem)
        status = 1 if problems else 0

    # Proxies left to the interpreter's exit make pvbatch fail with an X error
    # (GLXBadContext) after sys.exit(): delete them here.
    del walk, renderer
    for proxy in (rep, view, reader):
        simple.Delete(proxy)
    return status


if __name__ == "__main__":
    sys.exit(main())
