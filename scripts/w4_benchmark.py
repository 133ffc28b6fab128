# SPDX-License-Identifier: BSD-3-Clause
"""W4, changing data (issue 20): a time series and an upstream edit played in
ParaView's Render View and in the Time-Critical Render View (pvbatch).

For each variant of the series of scripts/make_w4_series.py (`surface`: one
~1M-triangle isosurface per step; `blocks`: the same surface in 200 leaves)
and each view, it plays the series LOOPS times (default 2) with ORBIT
interactive orbit frames at every step (default 5) at a TARGET ms target
(default 100), then (variant `surface`) an upstream edit: a Contour filter on
the volume of step 0, its value changed 10 times and back.

Per change (a time step or a contour value) it records: the reader's (or the
contour filter's) own time, measured apart by updating it alone first; the
time from the change to the first frame, that time excluded; the frames until
every object of the view has its hierarchy (TOMs against plain leaves, read
from the representation's mapper) and after; builds done and cache hits (the
representation's vtkMultiresolutionHierarchyBuilder, and any counters the
mapper or a cache expose, see HOOKS below); the process's RSS. It writes
w4.json, PNG key frames, prints the issue's goals with PASS/MISS and figures,
and scripts/plot_w4.py plots w4.json.

    export TIMECRITICAL_PLUGIN=$PWD/build/lib/paraview-plugins/TimeCritical/TimeCritical.so
    xvfb-run -a pvbatch --force-offscreen-rendering scripts/w4_benchmark.py --data w4-data --output w4-output
    scripts/run-w4.sh [OUTPUT] [options]     # generates the data when missing, runs, plots

The first change of each loop's phase list is the initial show of the data
(a newly opened file: the view's first render, with the Time-Critical view's
start-up calibration); it is recorded but left out of the goals, which are
about changes to data already shown. Frame times are wall-clock around the
view's render with the render window's WaitForCompletion (image capture
excluded). Run it on a quiet machine.
"""

import argparse
import json
import math
import os
import re
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPOSITORY = os.path.normpath(os.path.join(HERE, ".."))

VIEWS = {"render": ("RenderView", "ParaView's Render View"),
         "timecritical": ("TimeCriticalRenderView", "Time-Critical Render View")}
VARIANTS = ("surface", "blocks")

# HOOKS for what issue 20 adds around the builds (background builds, a shared
# cache): each name is used where the object has it, and recorded as null
# (or left out) where it does not, so this script runs before and after.
# - a view property that turns background builds on or off (--background);
BACKGROUND_PROPERTY = "BackgroundHierarchyBuilds"
# - the number of leaves still waiting for their hierarchy (mapper, then renderer);
PENDING_HOOKS = ("GetNumberOfPendingHierarchies",)
# - cumulative counts of builds done outside the representation's builder (the mapper's);
BUILD_COUNT_HOOKS = ("GetNumberOfHierarchyBuilds", "GetNumberOfBackgroundBuilds",
                     "GetNumberOfCompletedBuilds")
# - accessors of a cache object on the builder or the mapper, whose counters are recorded;
CACHE_HOOKS = ("GetCache", "GetHierarchyCache", "GetBuildCache")
# - the mapper's background build queue, where wrapped: its GetNumberOfBuilds() counts
#   builds and its GetNumberOfStoreHits() cache hits;
QUEUE_HOOKS = ("GetBuildQueue",)
# - every counter of the builder, the mapper, the cache and the queue recorded per change.
COUNTER_PATTERN = re.compile(
    r"^GetNumberOf\w*(Build|Built|Reused|Loaded|Passed|Hit|Miss|Evict|Pending|Cancel|Hierarch"
    r"|Swapped|Finished|Rejected|Written|Entries)\w*$")


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--data", default="w4-data",
                        help="folder of make_w4_series.py, written when missing or made with "
                             "other settings (default: %(default)s)")
    parser.add_argument("--output", default="w4-output", help="results (default: %(default)s)")
    parser.add_argument("--plugin", default=os.environ.get("TIMECRITICAL_PLUGIN"),
                        help="TimeCritical.so (default: $TIMECRITICAL_PLUGIN, else "
                             "$TIMECRITICAL_BUILD_DIR or ./build)")
    parser.add_argument("--steps", type=int, default=20, help="series steps (generation)")
    parser.add_argument("--resolution", type=int, default=432, help="grid resolution (generation)")
    parser.add_argument("--blocks", type=int, default=200, help="leaves per step (generation)")
    parser.add_argument("--tiny", action="store_true",
                        help="smoke-test size: a tiny series (make_w4_series.py --tiny), 2 orbit "
                             "frames, 4 contour changes, 256x256")
    parser.add_argument("--variants", default=",".join(VARIANTS),
                        help="comma-separated subset of %s (default: all)" % ",".join(VARIANTS))
    parser.add_argument("--views", default="render,timecritical",
                        help="comma-separated subset of render,timecritical (default: both)")
    parser.add_argument("--loops", type=int, default=2, help="plays of the series (default: 2)")
    parser.add_argument("--orbit", type=int, default=5,
                        help="interactive orbit frames per change, the first one included "
                             "(default: %(default)s)")
    parser.add_argument("--target", type=float, default=100.0, help="target ms (default: 100)")
    parser.add_argument("--size", type=int, nargs=2, default=[512, 512], help="view size")
    parser.add_argument("--edit-changes", type=int, default=None,
                        help="contour values away from the start before going back "
                             "(default: all of the series' edit, 10)")
    parser.add_argument("--no-edit", action="store_true", help="skip the contour edit")
    parser.add_argument("--first-frame", choices=("interactive", "still"), default="interactive",
                        help="how the first frame after a change is rendered (default: %(default)s)")
    parser.add_argument("--hierarchy-wait", type=float, default=30.0,
                        help="seconds of extra orbit frames after a change's orbit while "
                             "hierarchies are pending (default: %(default)s)")
    parser.add_argument("--background", choices=("default", "on", "off"), default="default",
                        help="the view's %s property, where it exists" % BACKGROUND_PROPERTY)
    parser.add_argument("--no-images", action="store_true", help="no key frames")
    parser.add_argument("--quiet", action="store_true", help="no line per change")
    args = parser.parse_args()
    args.variants = [v for v in args.variants.split(",") if v]
    args.views = [v for v in args.views.split(",") if v]
    if args.tiny:
        args.orbit = min(args.orbit, 2)
        args.size = [256, 256]
        args.edit_changes = args.edit_changes or 2
    bad = [v for v in args.variants if v not in VARIANTS] + [v for v in args.views if v not in VIEWS]
    if bad or args.loops < 1 or args.orbit < 1 or args.target <= 0:
        parser.error("bad --variants/--views (%s), or --loops/--orbit < 1, or --target <= 0"
                     % ", ".join(bad))
    return args


# ---------------------------------------------------------------------------
# Set-up: plugin, data

def find_plugin(args):
    path = args.plugin or os.path.join(
        os.environ.get("TIMECRITICAL_BUILD_DIR", os.path.join(REPOSITORY, "build")),
        "lib", "paraview-plugins", "TimeCritical", "TimeCritical.so")
    if not os.path.isfile(path):
        raise SystemExit("w4_benchmark: TimeCritical.so not found (%s): pass --plugin or set "
                         "TIMECRITICAL_PLUGIN" % path)
    return os.path.abspath(path)


def import_timecritical(plugin):
    """The timecritical package (wraps the view's classes), from PYTHONPATH or
    the build tree of the plugin."""
    try:
        import timecritical  # noqa: F401
    except ImportError:
        lib = os.path.dirname(os.path.dirname(os.path.dirname(plugin)))
        sys.path.insert(0, os.path.join(lib, "python3", "dist-packages"))
        import timecritical  # noqa: F401
    from timecritical import TimeCriticalViews  # noqa: F401


def ensure_data(args):
    sys.path.insert(0, HERE)
    import make_w4_series
    argv = ["--output", args.data]
    if args.tiny:
        argv.append("--tiny")
    else:
        argv += ["--steps", str(args.steps), "--resolution", str(args.resolution),
                 "--blocks", str(args.blocks)]
    return make_w4_series.ensure_series(make_w4_series.parse_arguments(argv))


# ---------------------------------------------------------------------------
# Measurements

def rss_mb():
    """Resident and peak resident memory of this process, MiB."""
    values = {}
    try:
        with open("/proc/self/status") as stream:
            for line in stream:
                if line.startswith(("VmRSS:", "VmHWM:")):
                    values[line.split(":")[0]] = int(line.split()[1]) / 1024.0
    except OSError:
        pass
    return values.get("VmRSS"), values.get("VmHWM")


def load_average():
    try:
        with open("/proc/loadavg") as stream:
            return [float(x) for x in stream.read().split()[:3]]
    except OSError:
        return None


def first_hook(objects, names):
    """(object, method name) of the first object that has one of names."""
    for obj in objects:
        for name in names:
            if obj is not None and hasattr(obj, name):
                return obj, name
    return None, None


def counters(obj, prefix):
    """Every counter of obj matching COUNTER_PATTERN, by prefixed name."""
    found = {}
    if obj is None:
        return found
    for name in dir(obj):
        if COUNTER_PATTERN.match(name):
            try:
                value = getattr(obj, name)()
            except TypeError:  # needs arguments: not a counter
                continue
            if isinstance(value, (int, float)):
                found[prefix + name[len("GetNumberOf"):]] = value
    return found


class Probe:
    """What the Time-Critical view's representation tells about its
    hierarchies (nothing for ParaView's Render View)."""

    def __init__(self, view, rep):
        self.renderer = None
        self.builder = self.mapper = self.cache = None
        if view.GetXMLName() != "TimeCriticalRenderView":
            return
        self.renderer = view.GetClientSideObject().GetRenderer()
        surface = rep.GetClientSideObject().GetTimeCriticalSurface()
        self.builder = surface.GetHierarchyBuilder()
        self.mapper = surface.GetMultiresolutionMapper()
        owner, name = first_hook([self.builder, self.mapper], CACHE_HOOKS)
        self.cache = getattr(owner, name)() if owner is not None else None
        owner, name = first_hook([self.mapper], QUEUE_HOOKS)
        self.queue = getattr(owner, name)() if owner is not None else None
        self.pending_hook = first_hook([self.mapper, self.renderer], PENDING_HOOKS)
        self.build_hook = first_hook([self.mapper], BUILD_COUNT_HOOKS)

    def active(self):
        return self.mapper is not None

    def hierarchies(self):
        """(objects, TOM objects, pending builds or None)."""
        m = self.mapper
        n = m.GetNumberOfObjects()
        toms = sum(1 for i in range(n) if m.GetObjectIsTOM(i))
        owner, name = self.pending_hook
        return n, toms, getattr(owner, name)() if owner is not None else None

    def queue_count(self, name):
        """A counter of the mapper's build queue (created with its first
        background build), 0 without one."""
        if self.queue is None:
            owner, hook = first_hook([self.mapper], QUEUE_HOOKS)
            self.queue = getattr(owner, hook)() if owner is not None else None
        return getattr(self.queue, name)() if self.queue is not None else 0

    def builds_total(self):
        """Leaves built so far: the builder's, and the background builds."""
        total = self.builder.GetNumberOfBuilds() + self.queue_count("GetNumberOfBuilds")
        owner, name = self.build_hook
        return total + (getattr(owner, name)() if owner is not None else 0)

    def swapped(self):
        """Hierarchies the mapper swapped in after background builds (None
        without background builds in the mapper)."""
        m = self.mapper
        return m.GetNumberOfSwappedHierarchies() if hasattr(m, "GetNumberOfSwappedHierarchies") \
            else None

    def builds_countable(self):
        """False when the mapper builds in the background and no counter of
        its builds is reachable from Python (its queue is not wrapped)."""
        background = hasattr(self.mapper, "GetBackgroundBuilds") and self.mapper.GetBackgroundBuilds()
        self.queue_count("GetNumberOfBuilds")  # finds the queue once it exists
        return not background or self.queue is not None or self.build_hook[0] is not None

    def hits(self, executed):
        """Leaves of the last execution reused or loaded by the builder, and
        the queue's store hits so far."""
        b = self.builder
        reused = b.GetNumberOfReusedLeaves() + (
            b.GetNumberOfLoadedLeaves() if hasattr(b, "GetNumberOfLoadedLeaves") else 0)
        m = self.mapper
        store = m.GetNumberOfBackgroundCacheHits() if hasattr(m, "GetNumberOfBackgroundCacheHits") \
            else self.queue_count("GetNumberOfStoreHits")
        return (reused if executed else 0), store

    def builder_stamp(self):
        """The modification time of the builder's output, 0 before any: read
        from the output information, which (unlike GetOutputDataObject) asks
        nothing of the pipeline."""
        from vtkmodules.vtkCommonDataModel import vtkDataObject
        output = self.builder.GetOutputInformation(0).Get(vtkDataObject.DATA_OBJECT())
        return output.GetMTime() if output is not None else 0

    def snapshot(self):
        found = counters(self.builder, "builder.")
        found.update(counters(self.mapper, "mapper."))
        found.update(counters(self.cache, "cache."))
        found.update(counters(self.queue, "queue."))
        return found

    def frame(self, record):
        r = self.renderer
        objects, toms, pending = self.hierarchies()
        record.update({"measured_ms": 1000.0 * r.GetMeasuredFrameTime(),
                       "predicted_ms": 1000.0 * r.GetPredictedFrameTime(),
                       "triangles": r.GetObjectTrianglesDrawn(),
                       "still": bool(r.GetLastRenderWasStill()),
                       "objects": objects, "toms": toms, "pending": pending})
        record["hierarchy_in_use"] = objects > 0 and toms == objects and not pending
        return record


# ---------------------------------------------------------------------------
# Playing changes

class Player:
    """Renders a view and times its frames along an orbit."""

    def __init__(self, args, view, rep, frames_per_turn):
        self.args = args
        self.view = view
        self.window = view.GetRenderWindow()
        self.probe = Probe(view, rep)
        self.angle = 0.0
        self.step_angle = 360.0 / max(1, frames_per_turn)
        self.images = {}

    def move(self):
        a = math.radians(self.angle)
        e = math.radians(25.0)
        distance = 4.2
        self.view.CameraFocalPoint = [0.0, 0.0, 0.0]
        self.view.CameraPosition = [distance * math.cos(e) * math.sin(a), distance * math.sin(e),
                                    distance * math.cos(e) * math.cos(a)]
        self.view.CameraViewUp = [0.0, 1.0, 0.0]
        self.view.CameraViewAngle = 30.0
        self.angle += self.step_angle

    def render(self, still=False):
        """One frame, the render and WaitForCompletion: (seconds, end time)."""
        start = time.perf_counter()
        if still:
            self.view.StillRender()
        else:
            self.view.InteractiveRender()
        self.window.WaitForCompletion()
        end = time.perf_counter()
        return end - start, end

    def frame_record(self, seconds):
        record = {"wall_ms": 1000.0 * seconds}
        return self.probe.frame(record) if self.probe.active() else record

    def play_change(self, change, apply, upstream, key=None):
        """One change: upstream() updated alone and timed, then apply() (the
        change seen by the view) and the first frame, then the orbit."""
        probe = self.probe
        before = ((probe.builds_total(), probe.hits(False)[1], probe.swapped())
                  if probe.active() else None)
        stamp = probe.builder_stamp() if probe.active() else None
        start = time.perf_counter()
        upstream()
        change["reader_s"] = time.perf_counter() - start
        self.move()
        start = time.perf_counter()
        apply()
        first, end = self.render(still=self.args.first_frame == "still")
        change["first_frame_s"] = end - start
        change["first_frame_total_s"] = change["reader_s"] + change["first_frame_s"]
        frames = [self.frame_record(first)]
        if key and not self.args.no_images:
            self.images[key + "-first"] = capture(self.view)
        # Change -> the end of the first frame drawn with every hierarchy.
        in_use_at = change["first_frame_s"] if frames[0].get("hierarchy_in_use") else None
        limit = time.perf_counter() + self.args.hierarchy_wait
        while len(frames) < self.args.orbit or (
                probe.active() and in_use_at is None and time.perf_counter() < limit):
            self.move()
            seconds, end = self.render()
            frames.append(self.frame_record(seconds))
            if in_use_at is None and frames[-1].get("hierarchy_in_use"):
                in_use_at = end - start
        if key and not self.args.no_images:
            self.images[key + "-orbit"] = capture(self.view)
        change["frames"] = frames
        self.close_change(change, before, stamp, in_use_at)
        return change

    def close_change(self, change, builds_before, stamp, in_use_at):
        change["rss_mb"], change["peak_rss_mb"] = rss_mb()
        if not self.probe.active():
            change.update({"hierarchy_in_use_s": None, "frames_until_hierarchy": None,
                           "builds": None, "hierarchies_swapped": None, "cache_hits": None,
                           "counters": {}})
            return
        probe, frames = self.probe, change["frames"]
        executed = probe.builder_stamp() != stamp
        until = next((i for i, f in enumerate(frames) if f["hierarchy_in_use"]), None)
        reused, store_hits = probe.hits(executed)
        swapped = probe.swapped()
        change.update({
            "hierarchy_in_use_s": in_use_at,
            "frames_until_hierarchy": until,
            # None: background builds that no counter reachable from Python counts.
            "builds": (probe.builds_total() - builds_before[0]) if probe.builds_countable()
            else None,
            "hierarchies_swapped": None if swapped is None else swapped - builds_before[2],
            "builder_executed": executed,
            "cache_hits": reused + store_hits - builds_before[1],
            "passed_leaves": probe.builder.GetNumberOfPassedLeaves() if executed else 0,
            "objects": frames[-1]["objects"],
            "counters": probe.snapshot()})


def capture(view):
    """The view's last image as rows x columns x RGB (top row first)."""
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


def make_view(args, kind):
    from paraview import simple
    view = simple.CreateView(VIEWS[kind][0])
    view.ViewSize = args.size
    view.OrientationAxesVisibility = 0
    settings = {"view": VIEWS[kind][0]}
    if kind == "timecritical":
        view.TargetFrameTime = args.target
        view.FullResolutionAtRest = 1
        if BACKGROUND_PROPERTY in view.ListProperties():
            if args.background != "default":
                setattr(view, BACKGROUND_PROPERTY, 1 if args.background == "on" else 0)
            settings[BACKGROUND_PROPERTY] = getattr(view, BACKGROUND_PROPERTY)
        else:
            settings[BACKGROUND_PROPERTY] = None
    else:
        settings["LODThreshold"] = view.LODThreshold
    return view, settings


def print_change(kind, change):
    frames = change["frames"][1:]
    worst = max((f["wall_ms"] for f in frames), default=float("nan"))
    print("  %-12s %-6s %3d  read %6.3f s  first %6.3f s  hierarchy %s  frames %2d, max %6.1f ms"
          "  builds %s  hits %s  RSS %.0f MiB" % (
              kind, change["phase"], change["index"], change["reader_s"], change["first_frame_s"],
              "%6.3f s" % change["hierarchy_in_use_s"] if change["hierarchy_in_use_s"] is not None
              else "   -    ", len(frames), worst, change["builds"], change["cache_hits"],
              change["rss_mb"] or 0), flush=True)


def play_series(args, variant, kind, manifest, result):
    """The series of one variant, LOOPS times, in a new view of the kind."""
    from paraview import simple
    path = os.path.join(args.data, manifest["surface" if variant == "surface" else "blocks"])
    reader = simple.OpenDataFile(path)
    times = list(reader.TimestepValues)
    view, settings = make_view(args, kind)
    rep = simple.Show(reader, view)
    player = Player(args, view, rep, len(times) * args.orbit)
    changes = []
    for loop in range(args.loops):
        for index, t in enumerate(times):
            change = {"phase": "loop%d" % (loop + 1), "index": index, "time": t,
                      "initial": loop == 0 and index == 0}
            key = ("%s-%s-step%d" % (variant, kind, index)
                   if loop == 0 and index == len(times) // 2 else None)

            def apply(t=t):
                view.ViewTime = t

            player.play_change(change, apply, lambda t=t: reader.UpdatePipeline(t), key)
            changes.append(change)
            if not args.quiet:
                print_change(kind, change)
    result["images"].update(player.images)
    for proxy in (rep, view, reader):
        simple.Delete(proxy)
    return {"variant": variant, "view": kind, "label": VIEWS[kind][1], "settings": settings,
            "changes": changes}


def play_edit(args, kind, manifest, result):
    """The contour edit: the volume of step 0, its isosurface shown, then the
    contour value changed away and back."""
    from paraview import simple
    volume = simple.XMLImageDataReader(FileName=[os.path.join(args.data, manifest["volume"])])
    contour = simple.Contour(Input=volume, ContourBy=["POINTS", manifest["field"]],
                             Isosurfaces=[manifest["edit"]["start"]], ComputeScalars=0)
    view, settings = make_view(args, kind)
    rep = simple.Show(contour, view)
    edit = manifest["edit"]
    values = edit["changes"]
    away = edit["back_from_change"]
    if args.edit_changes is not None and args.edit_changes < away:
        away = max(1, args.edit_changes)
        forth = values[:away]
        values = forth + forth[-2::-1] + [edit["start"]]
    player = Player(args, view, rep, (len(values) + 1) * args.orbit)
    changes = []
    for index, value in enumerate([edit["start"]] + values):
        change = {"phase": "edit" if index <= away else "back", "index": index,
                  "contour_value": value, "initial": index == 0}
        key = "surface-%s-edit%d" % (kind, index) if index == away else None

        def apply(value=value):
            contour.Isosurfaces = [value]

        def upstream(value=value):
            contour.Isosurfaces = [value]
            contour.UpdatePipeline()

        player.play_change(change, apply, upstream, key)
        changes.append(change)
        if not args.quiet:
            print_change(kind, change)
    result["images"].update(player.images)
    for proxy in (rep, view, contour, volume):
        simple.Delete(proxy)
    return {"variant": "edit", "view": kind, "label": VIEWS[kind][1], "settings": settings,
            "changes": changes}


# ---------------------------------------------------------------------------
# Summary and goals

def summarize(values):
    values = [v for v in values if v is not None and math.isfinite(v)]
    if not values:
        return {"n": 0, "mean": None, "median": None, "max": None, "min": None}
    return {"n": len(values), "mean": statistics.fmean(values),
            "median": statistics.median(values), "min": min(values), "max": max(values)}


def summarize_run(run, target_ms):
    """Per phase of a run: medians and maxima of the change's times and frames."""
    phases = {}
    for phase in sorted({c["phase"] for c in run["changes"]}):
        changes = [c for c in run["changes"] if c["phase"] == phase and not c["initial"]]
        frames = [f["wall_ms"] for c in changes for f in c["frames"][1:]]
        before = [f["wall_ms"] for c in changes for f in c["frames"][1:]
                  if "hierarchy_in_use" in f and not f["hierarchy_in_use"]]
        after = [f["wall_ms"] for c in changes for f in c["frames"][1:]
                 if f.get("hierarchy_in_use", True)]
        builds = [c["builds"] for c in changes if c["builds"] is not None]
        phases[phase] = {
            "changes": len(changes),
            "reader_s": summarize([c["reader_s"] for c in changes]),
            "first_frame_s": summarize([c["first_frame_s"] for c in changes]),
            "hierarchy_in_use_s": summarize([c["hierarchy_in_use_s"] for c in changes]),
            "interactive_ms": summarize(frames),
            "interactive_within_110_percent": (100.0 * sum(v <= 1.1 * target_ms for v in frames)
                                               / len(frames)) if frames else None,
            "frames_before_hierarchy_ms": summarize(before),
            "frames_after_hierarchy_ms": summarize(after),
            "builds": sum(builds) if builds else None,
            "cache_hits": sum(c["cache_hits"] or 0 for c in changes) if builds else None,
            "rss_mb_max": max((c["rss_mb"] or 0 for c in changes), default=None)}
    return phases


def goal(name, scope, passed, text):
    return {"goal": name, "scope": scope, "passed": bool(passed), "text": text}


def evaluate_goals(runs, target_ms):
    """The issue's four goals, per variant (and the edit) of the Time-Critical view."""
    goals = []
    tc = {r["variant"]: r for r in runs if r["view"] == "timecritical"}
    rv = {r["variant"]: r for r in runs if r["view"] == "render"}
    for variant, run in tc.items():
        changes = [c for c in run["changes"] if not c["initial"]]
        firsts = [1000.0 * c["first_frame_s"] for c in changes]
        over = [v for v in firsts if v > 2 * target_ms]
        goals.append(goal("first frame after a change <= 2x target", variant, not over and firsts,
                          "median %.0f ms, max %.0f ms, %d of %d over %.0f ms" % (
                              statistics.median(firsts), max(firsts), len(over), len(firsts),
                              2 * target_ms) if firsts else "no change"))
        if variant in rv and variant != "edit":
            goals.append(hierarchy_goal(variant, run, rv[variant]))
        no_build = [c for c in changes if c["phase"] in ("loop2", "back")]
        if no_build:
            goals.append(no_build_goal(variant, no_build))
    frames = [f["wall_ms"] for r in tc.values() for c in r["changes"] if not c["initial"]
              for f in c["frames"][1:]]
    if frames:
        within = 100.0 * sum(v <= 1.1 * target_ms for v in frames) / len(frames)
        goals.append(goal("interactive frames after the first <= 110% target in >= 99%", "all",
                          within >= 99.0, "%.1f%% of %d frames, median %.0f ms, max %.0f ms" % (
                              within, len(frames), statistics.median(frames), max(frames))))
    return goals


def no_build_goal(variant, changes):
    """Goal 3 over the second loop's or the way back's changes."""
    phases = ", ".join(sorted({c["phase"] for c in changes}))
    if all(c["builds"] is not None for c in changes):
        builds = sum(c["builds"] for c in changes)
        return goal("second loop / edit-and-back build nothing", variant, builds == 0,
                    "%d builds over %d changes (%s)" % (builds, len(changes), phases))
    # Background builds not countable: a hierarchy swapped in is a build or a store hit.
    swapped = sum(c["hierarchies_swapped"] or 0 for c in changes)
    return goal("second loop / edit-and-back build nothing", variant, swapped == 0,
                "builds not countable from Python (background builds; the mapper's build queue "
                "is not wrapped): %d hierarchies swapped in over %d changes (%s), each a build "
                "or a store hit" % (swapped, len(changes), phases))


def hierarchy_goal(variant, tc_run, rv_run):
    """Loop 1: change -> hierarchy in use (TC) against change -> first frame (RV)."""
    rv_first = {c["index"]: c["first_frame_s"] for c in rv_run["changes"]
                if c["phase"] == "loop1" and not c["initial"]}
    pairs = [(c["hierarchy_in_use_s"], rv_first[c["index"]]) for c in tc_run["changes"]
             if c["phase"] == "loop1" and not c["initial"] and c["index"] in rv_first]
    missing = sum(1 for tc, _ in pairs if tc is None)
    known = [(tc, r) for tc, r in pairs if tc is not None]
    late = [tc / r for tc, r in known if tc > r]
    ok = pairs and not missing and not late
    text = ("hierarchy median %.3f s vs Render View first frame median %.3f s; %d of %d steps "
            "later (worst %.1fx)%s" % (
                statistics.median(tc for tc, _ in known) if known else float("nan"),
                statistics.median(r for _, r in pairs) if pairs else float("nan"),
                len(late), len(pairs), max(late) if late else 1.0,
                ", %d never in use" % missing if missing else ""))
    return goal("loop 1: change -> hierarchy in use <= Render View's change -> first frame",
                variant, ok, text)


def print_summary(runs, goals, target_ms):
    print("\nW4 summary (target %.0f ms; seconds: median / max over the changes, initial show "
          "excluded):" % target_ms)
    print("  %-8s %-26s %-6s %15s %15s %15s %17s %7s %6s" % (
        "variant", "view", "phase", "reading", "first frame", "hierarchy", "interactive ms",
        "builds", "hits"))
    for run in runs:
        for phase, s in run["summary"].items():
            def pair(d, scale=1.0):
                return ("%.3f / %.3f" % (d["median"] * scale, d["max"] * scale)
                        if d["n"] else "-")
            print("  %-8s %-26s %-6s %15s %15s %15s %17s %7s %6s" % (
                run["variant"], run["label"], phase, pair(s["reader_s"]), pair(s["first_frame_s"]),
                pair(s["hierarchy_in_use_s"]),
                ("%.0f / %.0f" % (s["interactive_ms"]["median"], s["interactive_ms"]["max"])
                 if s["interactive_ms"]["n"] else "-"),
                s["builds"] if s["builds"] is not None else "-",
                s["cache_hits"] if s["cache_hits"] is not None else "-"))
    print("\nGoals (Time-Critical Render View):")
    for g in goals:
        print("  %s  %-75s [%s] %s" % ("PASS" if g["passed"] else "MISS", g["goal"], g["scope"],
                                       g["text"]))


# ---------------------------------------------------------------------------

def main():
    args = parse_arguments()
    plugin = find_plugin(args)
    os.makedirs(args.output, exist_ok=True)
    load_start = load_average()
    manifest = ensure_data(args)
    import_timecritical(plugin)
    from paraview import simple
    simple.LoadPlugin(plugin, remote=False, ns={})
    target = args.target
    result = {"images": {}}
    runs = []
    started = time.perf_counter()
    print("W4: %d steps of %s-%s triangles, %d blocks; target %.0f ms, %d orbit frames, "
          "%d loops" % (len(manifest["triangles"]), format(min(manifest["triangles"]), ","),
                        format(max(manifest["triangles"]), ","), manifest["settings"]["blocks"],
                        target, args.orbit, args.loops), flush=True)
    for variant in args.variants:
        for kind in args.views:
            runs.append(play_series(args, variant, kind, manifest, result))
    if not args.no_edit and "surface" in args.variants:
        for kind in args.views:
            runs.append(play_edit(args, kind, manifest, result))
    for run in runs:
        run["summary"] = summarize_run(run, target)
    goals = evaluate_goals(runs, target)
    print_summary(runs, goals, target)
    images = write_images(args, result["images"])
    output = {
        "benchmark": "W4 changing data (issue 20)", "script": "scripts/w4_benchmark.py",
        "settings": {"target_ms": target, "loops": args.loops, "orbit_frames": args.orbit,
                     "view_size": args.size, "first_frame": args.first_frame,
                     "hierarchy_wait_s": args.hierarchy_wait, "background": args.background,
                     "tiny": args.tiny, "variants": args.variants, "views": args.views,
                     "plugin": plugin},
        "machine": {"cpus": os.cpu_count(), "load_average_start": load_start,
                    "load_average_end": load_average(), "quiet_flag": os.path.exists("/tmp/QUIET"),
                    "duration_s": time.perf_counter() - started},
        "series": manifest, "runs": runs, "goals": goals, "key_frames": images}
    path = os.path.join(args.output, "w4.json")
    with open(path, "w") as stream:
        json.dump(output, stream, indent=1)
    print("wrote %s" % path, flush=True)


def write_images(args, images):
    written = []
    for key, pixels in sorted(images.items()):
        path = os.path.join(args.output, "w4_%s.png" % key)
        write_png(pixels, path)
        written.append(os.path.basename(path))
    return written


if __name__ == "__main__":
    try:
        main()
    except SystemExit as stop:  # pvbatch must not leave through sys.exit(): X errors
        code = stop.code if isinstance(stop.code, int) else (0 if stop.code is None else 1)
        if not isinstance(stop.code, int) and stop.code is not None:
            print(stop.code, file=sys.stderr)
        sys.stderr.flush()
        sys.stdout.flush()
        os._exit(code)
