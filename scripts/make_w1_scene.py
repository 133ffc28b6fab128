#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes the W1 walkthrough scene and camera path for ParaView and Python.

W1 is the walkthrough of Gobbetti & Bouvier's section 7.2.2 that the C++
benchmark Testing/Benchmarks/WalkthroughBenchmark.cxx flies (scene and path in
Testing/Benchmarks/Support/W1Scene.cxx and W1CameraPath.cxx). Both read the
layout's numbers from one specification, Testing/Benchmarks/Support/W1Scene.json,
and the tests W1SceneMatchesCow and W1SceneMatchesSubstitute
(Testing/Benchmarks/TestW1SceneMatch.py) check that they build the same scene:

* the object: cow.obj (read, bit-equal points welded, unused points dropped),
  or the benchmark's cow-sized bumpy ellipsoid when the file is missing,
  with smooth point normals, turned into a Totally Ordered Mesh by
  vtkTOMBuilder when the `timecritical` Python package can be imported
  (otherwise the plain surface: the Time-Critical Render View builds the TOMs
  itself when it loads the scene);
* the herd: `--objects` replicas on a jittered square grid in the y = 0 plane,
  each with a random rotation about +y and a random colour, drawn from
  std::mt19937(seed)'s raw 32-bit stream in the benchmark's order (numpy's
  legacy RandomState(seed) yields the same stream);
* the camera path of `--frames` frames: A (the whole herd in view) -> B (close
  to one cow) -> a sudden turn along the herd's diagonal -> backing away to C.

Output folder (default ./w1-output/scene):

* scene.vtm + scene/scene_<n>.vtp: one block per cow, named cow_<n>, with the
  per-point RGB array "Colors" (unsigned char; colour by it with MapScalars
  off for the cows' own colours). XML binary mode, never appended mode, which
  this platform's expat cannot read back (see the README);
* camera_path.json: per frame position, focal point, view up and view angle,
  the key frames and the window size of the benchmark;
* scene.json: what was generated (settings, the herd's layout, per cow its
  position, angle and colour), so that a later run can tell whether the
  scene is still the one it asks for.

Runs with /usr/bin/python3 or pvpython (both need Debian's vtkmodules and
numpy); put the build tree's Python package on PYTHONPATH for TOM leaves:

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \\
        scripts/make_w1_scene.py --output w1-output/scene

Also importable: examples call ensure_scene() and camera_path().
"""

import argparse
import json
import math
import os
import sys
import time

import numpy as np

SPECIFICATION_FILE = os.path.normpath(os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "..", "Testing", "Benchmarks", "Support",
    "W1Scene.json"))


def load_specification(path=SPECIFICATION_FILE):
    """W1's layout numbers, shared with the C++ benchmarks."""
    with open(path) as stream:
        return json.load(stream)


SPEC = load_specification()
DEFAULT_SEED = SPEC["defaults"]["seed"]
DEFAULT_OBJECTS = SPEC["defaults"]["objects"]
DEFAULT_FRAMES = SPEC["defaults"]["frames"]
WINDOW_SIZE = SPEC["view"]["window_size"]
VIEW_ANGLE = SPEC["view"]["view_angle"]
BACKGROUND = tuple(SPEC["view"]["background"])
# Bumped whenever what this script writes changes, so that old scenes are rebuilt.
FORMAT_VERSION = 1


def default_mesh():
    """cow.obj in the shared data folder (TIMECRITICAL_SHARED_DATA_DIR or ../shared/data)."""
    folder = os.environ.get("TIMECRITICAL_SHARED_DATA_DIR")
    if not folder:
        here = os.path.dirname(os.path.abspath(__file__))
        folder = os.path.join(here, "..", "..", "shared", "data")
    return os.path.normpath(os.path.join(folder, "cow.obj"))


# ---------------------------------------------------------------------------
# Random numbers: the benchmark's Random class on std::mt19937.

class Random:
    """Uniform numbers from std::mt19937(seed): the top 24 bits of each raw draw."""

    def __init__(self, seed):
        self._state = np.random.RandomState(seed)  # legacy seeding = std::mt19937(seed)

    def raw(self):
        return int(self._state.randint(0, 2**32, dtype=np.uint32))

    def uniform(self, low, high):
        return low + (high - low) * ((self.raw() >> 8) * (1.0 / 16777216.0))


def check_random_stream():
    """std::mt19937 with the default seed 5489 must give 4123659995 as its 10000th value."""
    state = np.random.RandomState(5489)
    value = int(state.randint(0, 2**32, size=10000, dtype=np.uint32)[-1])
    if value != 4123659995:
        raise RuntimeError("numpy's RandomState is not std::mt19937 here (got %d)" % value)


def round_half_away(x):
    """std::lround for x >= 0."""
    return int(math.floor(x + 0.5))


def random_color(random):
    """Random hue, moderate saturation, bright value (the benchmark's RandomColor)."""
    colors = SPEC["colors"]
    h = random.uniform(*colors["hue"])
    s = random.uniform(*colors["saturation"])
    v = random.uniform(*colors["value"])
    sector = int(h) % 6
    f = h - math.floor(h)
    p, q, t = v * (1 - s), v * (1 - s * f), v * (1 - s * (1 - f))
    rgb = [(v, t, p), (q, v, p), (p, v, t), (p, q, v), (t, p, v), (v, p, q)][sector]
    return [round_half_away(255.0 * c) for c in rgb]


# ---------------------------------------------------------------------------
# The object

def load_obj(path):
    """Points (n x 3 float64) and triangles (m x 3) of an OBJ file: `v` and `f`
    lines (corners v, v/vt, v//vn, v/vt/vn; negative indices are relative),
    polygons fan-triangulated, `\\` continuation lines joined."""
    points, triangles = [], []
    with open(path, "r", encoding="utf-8", errors="replace") as stream:
        text = stream.read()
    pending = ""
    for line in text.split("\n"):
        line = line.split("#", 1)[0].rstrip()
        if line.endswith("\\"):
            pending += line[:-1] + " "
            continue
        tokens = (pending + line).split()
        pending = ""
        if not tokens or tokens[0] not in ("v", "f"):
            continue
        if tokens[0] == "v":
            points.append([float(x) for x in tokens[1:4]])
            continue
        corners = []
        for token in tokens[1:]:
            index = int(token.split("/", 1)[0])
            corners.append(index - 1 if index > 0 else len(points) + index)
        for i in range(1, len(corners) - 1):
            triangles.append((corners[0], corners[i], corners[i + 1]))
    return np.array(points, dtype=np.float64), np.array(triangles, dtype=np.int64).reshape(-1, 3)


def weld_and_clean(points, triangles):
    """Merges bit-equal points (the first of each kept, in order; -0 = +0), drops
    triangles that become degenerate, then drops unused points (order kept)."""
    keys = points + 0.0  # -0.0 + 0.0 = +0.0
    first = {}
    remap = np.empty(len(points), dtype=np.int64)
    kept = []
    for i, key in enumerate(map(bytes, keys)):
        if key not in first:
            first[key] = len(kept)
            kept.append(i)
        remap[i] = first[key]
    points = points[kept]
    triangles = remap[triangles]
    good = ((triangles[:, 0] != triangles[:, 1]) & (triangles[:, 1] != triangles[:, 2]) &
            (triangles[:, 0] != triangles[:, 2]))
    triangles = triangles[good]
    used = np.zeros(len(points), dtype=bool)
    used[triangles.ravel()] = True
    new_id = np.cumsum(used) - 1
    return points[used], new_id[triangles]


def substitute_cow():
    """The benchmark's stand-in when cow.obj is missing: a bumpy ellipsoid of
    2 x 43 x 68 = 5,848 triangles with the cow's extents."""
    spec = SPEC["substitute_object"]
    latitudes, longitudes = spec["latitudes"], spec["longitudes"]
    amplitude, (fx, fy, fz), (sx, sy, sz) = spec["bump_amplitude"], spec["bump_frequencies"], spec["scale"]
    pts = [(0.0, 0.0, 1.0)]
    for k in range(1, latitudes):
        theta = math.pi * k / latitudes
        for j in range(longitudes):
            phi = 2.0 * math.pi * j / longitudes
            pts.append((math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi),
                        math.cos(theta)))
    pts.append((0.0, 0.0, -1.0))
    south = len(pts) - 1

    def ring(k, j):
        return 1 + (k - 1) * longitudes + j % longitudes

    tris = [(0, ring(1, j), ring(1, j + 1)) for j in range(longitudes)]
    for k in range(1, latitudes - 1):
        for j in range(longitudes):
            a, b, c, d = ring(k, j), ring(k, j + 1), ring(k + 1, j + 1), ring(k + 1, j)
            tris += [(a, d, c), (a, c, b)]
    tris += [(ring(latitudes - 1, j), south, ring(latitudes - 1, j + 1)) for j in range(longitudes)]
    out = []
    for x, y, z in pts:
        bump = 1.0 + amplitude * math.sin(fx * x) * math.sin(fy * y) * math.cos(fz * z)
        out.append((x * (sx * bump), y * (sy * bump), z * (sz * bump)))
    return np.array(out, dtype=np.float64), np.array(tris, dtype=np.int64)


def make_object(mesh_path, want_tom=True):
    """The cow as vtkPolyData with point normals, a TOM when possible.
    Returns (polydata, description, is_substitute, is_tom)."""
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    from vtkmodules.vtkFiltersCore import vtkPolyDataNormals

    if mesh_path and os.path.isfile(mesh_path):
        points, triangles = weld_and_clean(*load_obj(mesh_path))
        source, substitute = mesh_path, False
    else:
        sys.stderr.write("WARNING: %s not found: the scene uses a cow-sized substitute "
                         "(a bumpy ellipsoid)\n" % mesh_path)
        points, triangles = substitute_cow()
        source, substitute = "substitute: bumpy ellipsoid of 5,848 triangles", True

    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(points, deep=True))  # double, as the benchmark's
    cells = vtkCellArray()
    offsets = np.arange(0, 3 * len(triangles) + 1, 3, dtype=np.int64)
    cells.SetData(numpy_to_vtkIdTypeArray(offsets, deep=True),
                  numpy_to_vtkIdTypeArray(triangles.ravel().astype(np.int64), deep=True))
    surface = vtkPolyData()
    surface.SetPoints(vtk_points)
    surface.SetPolys(cells)

    # One normal per vertex (no splitting): smooth shading, the mesh's own vertices.
    normals = vtkPolyDataNormals()
    normals.SetInputData(surface)
    normals.SplittingOff()
    normals.ConsistencyOn()
    normals.ComputePointNormalsOn()
    normals.ComputeCellNormalsOff()
    normals.Update()
    result = normals.GetOutput()

    is_tom = False
    if want_tom:
        try:
            from timecritical import vtkTOMBuilder
        except ImportError:
            sys.stderr.write("note: the timecritical Python package is not on PYTHONPATH: writing "
                             "plain surfaces (the view builds their TOMs when it loads them)\n")
        else:
            builder = vtkTOMBuilder()
            builder.SetInputData(result)
            builder.Update()
            result = builder.GetOutput()
            is_tom = True
    return result, source, substitute, is_tom


# ---------------------------------------------------------------------------
# The herd and the camera path (the benchmark's PlaceObjects and CameraPath)

def place_objects(objects, seed, bounds, footprint_points):
    """The layout of the herd as a dict (grid, spacing, jitter, extent, radius,
    height, focus object, per object x, z, angle and colour)."""
    b = bounds
    cx, cz = 0.5 * (b[0] + b[1]), 0.5 * (b[4] + b[5])
    radius = float(np.max(np.hypot(footprint_points[:, 0] - cx, footprint_points[:, 2] - cz)))
    height = b[3] - b[2]
    grid = int(math.ceil(math.sqrt(objects)))
    placement = SPEC["placement"]
    spacing = 2.0 * radius + placement["gap"]
    jitter = placement["jitter_fraction_of_gap"] * (spacing - 2.0 * radius)
    extent = grid * spacing

    random = Random(seed)
    placed = []
    for n in range(objects):
        i, j = n % grid, n // grid
        x = (i + 0.5) * spacing + random.uniform(-jitter, jitter)
        z = (j + 0.5) * spacing + random.uniform(-jitter, jitter)
        angle = random.uniform(0.0, 360.0)
        placed.append({"x": x, "z": z, "angle": angle, "color": random_color(random)})

    xz = np.array([[p["x"], p["z"]] for p in placed]).reshape(-1, 2)
    for m in range(len(xz) - 1):  # verify "no overlaps" rather than trust the construction
        d = np.hypot(*(xz[m + 1:] - xz[m]).T)
        if np.any(d < 2.0 * radius):
            raise RuntimeError("objects %d and %d overlap" % (m, m + 1 + int(np.argmax(d < 2 * radius))))
    focus = 0
    if placed:
        near = placement["focus_near"]
        d = np.hypot(xz[:, 0] - near[0] * extent, xz[:, 1] - near[1] * extent)
        focus = int(np.argmin(d))  # the first of equals, as the benchmark's strict '<'
    return {"grid": grid, "spacing": spacing, "jitter": jitter, "extent": extent,
            "footprint_radius": radius, "height": height, "focus_object": focus,
            "center": [cx, b[2], cz], "objects": placed}


def _lerp(a, b, t):
    return [x + (y - x) * t for x, y in zip(a, b)]


def _normalized(a):
    length = math.sqrt(sum(x * x for x in a))
    return [x / length for x in a] if length > 0 else list(a)


def _smoothstep(t):
    t = min(max(t, 0.0), 1.0)
    return t * t * (3.0 - 2.0 * t)


def camera_path(layout, frames):
    """The W1 path as a dict: per frame position, focal point, view up, view
    angle; key frames A, B, turn, C."""
    spec = SPEC["camera_path"]
    L, r = layout["extent"], layout["footprint_radius"]
    center = [0.5 * L, 0.0, 0.5 * L]
    focus = layout["objects"][layout["focus_object"]]
    target = [focus["x"], spec["target_height"] * layout["height"], focus["z"]]
    a = [center[k] + spec["a_offset"][k] * L for k in range(3)]
    toward_a = _normalized([a[0] - target[0], 0.0, a[2] - target[2]])
    b_up = [0.0, spec["b_height"] * r, 0.0]
    b = [target[k] + toward_a[k] * (spec["b_distance"] * r) + b_up[k] for k in range(3)]
    turn_direction = _normalized(spec["turn_direction"])
    turn_focus = [b[k] + turn_direction[k] * (spec["turn_focus_distance"] * L) for k in range(3)]
    back = _normalized(spec["c_direction"])
    c_up = [0.0, spec["c_height"] * L, 0.0]
    c = [([b[0], 0.0, b[2]][k] - back[k] * (spec["c_distance"] * L)) + c_up[k] for k in range(3)]
    key_b = round_half_away(spec["key_b"] * (frames - 1))
    ease = spec["focus_ease_scale"]
    last = frames - 1

    positions, focal_points = [], []
    for frame in range(frames):
        if frame <= key_b:
            # Approach: fast at A, easing out to a stop at B, the view turning
            # from the herd's centre to the focus object.
            s = frame / key_b if key_b > 0 else 1.0
            position = _lerp(a, b, 1.0 - (1.0 - s) * (1.0 - s))
            focal = _lerp(center, target, _smoothstep(ease * s))
        else:
            # After the one-frame turn: backing away (ease-in), the view
            # drifting back to the herd's centre.
            s = (frame - key_b - 1) / (last - key_b - 1) if last > key_b + 1 else 1.0
            position = _lerp(b, c, s * s)
            focal = _lerp(turn_focus, center, _smoothstep(s))
        positions.append(position)
        focal_points.append(focal)
    return {"frames": frames, "window": [WINDOW_SIZE, WINDOW_SIZE], "background": list(BACKGROUND),
            "key_frames": {"A": 0, "B": key_b, "turn": min(key_b + 1, last), "C": last},
            "position": positions, "focal_point": focal_points,
            "view_up": [[0.0, 1.0, 0.0]] * frames, "view_angle": [VIEW_ANGLE] * frames}


# ---------------------------------------------------------------------------
# Writing

def _transformed_copy(cow, matrix, color):
    """A deep copy of the cow with points and normals moved by the 4x4 matrix
    (rotation + translation) and the per-point array Colors."""
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    from vtkmodules.vtkCommonDataModel import vtkPolyData

    copy = vtkPolyData()
    copy.DeepCopy(cow)
    rotation, translation = matrix[:3, :3], matrix[:3, 3]
    points = vtk_to_numpy(copy.GetPoints().GetData())
    points[:] = points @ rotation.T + translation
    copy.GetPoints().Modified()
    normals = copy.GetPointData().GetNormals()
    n = vtk_to_numpy(normals)
    moved = n.astype(np.float64) @ rotation.T
    moved /= np.maximum(np.linalg.norm(moved, axis=1), 1e-300)[:, None]
    n[:] = moved
    normals.Modified()
    colors = numpy_to_vtk(np.tile(np.array(color, dtype=np.uint8), (copy.GetNumberOfPoints(), 1)),
                          deep=True)
    colors.SetName("Colors")
    copy.GetPointData().SetScalars(colors)
    return copy


def _matrix(layout, place):
    """The benchmark's transform: footprint centre to the origin (feet on y = 0),
    rotation about +y, translation to the object's place."""
    from vtkmodules.vtkCommonTransforms import vtkTransform

    cx, y0, cz = layout["center"]
    transform = vtkTransform()
    transform.PostMultiply()
    transform.Translate(-cx, -y0, -cz)
    transform.RotateY(place["angle"])
    transform.Translate(place["x"], 0.0, place["z"])
    transform.Update()
    m = transform.GetMatrix()
    return np.array([[m.GetElement(i, j) for j in range(4)] for i in range(4)])


def write_scene(folder, objects=DEFAULT_OBJECTS, seed=DEFAULT_SEED, frames=DEFAULT_FRAMES,
                mesh=None, want_tom=True, quiet=False):
    """Writes scene.vtm (+ its .vtp files), camera_path.json and scene.json into
    folder; returns the scene.json dict."""
    from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet, vtkMultiBlockDataSet
    from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataWriter

    check_random_stream()
    start = time.time()
    mesh = mesh or default_mesh()
    cow, source, substitute, is_tom = make_object(mesh, want_tom)
    cow_points = np.array([cow.GetPoint(i) for i in range(cow.GetNumberOfPoints())])
    layout = place_objects(objects, seed, cow.GetBounds(), cow_points)
    path = camera_path(layout, frames)

    blocks = vtkMultiBlockDataSet()
    blocks.SetNumberOfBlocks(objects)
    for n, place in enumerate(layout["objects"]):
        blocks.SetBlock(n, _transformed_copy(cow, _matrix(layout, place), place["color"]))
        blocks.GetMetaData(n).Set(vtkCompositeDataSet.NAME(), "cow_%03d" % n)
    os.makedirs(folder, exist_ok=True)
    writer = vtkXMLMultiBlockDataWriter()
    writer.SetInputData(blocks)
    writer.SetFileName(os.path.join(folder, "scene.vtm"))
    writer.SetDataModeToBinary()  # appended mode does not read back here (see the README)
    writer.SetHeaderTypeToUInt32()
    writer.SetIdTypeToInt32()
    if writer.Write() != 1:
        raise RuntimeError("cannot write %s" % writer.GetFileName())

    triangles = cow.GetNumberOfPolys()
    info = {"format_version": FORMAT_VERSION, "generator": "scripts/make_w1_scene.py",
            "mesh": source, "substitute": substitute, "tom": is_tom, "seed": seed,
            "objects": objects, "frames": frames, "triangles_per_object": triangles,
            "triangles": triangles * objects, "seconds": time.time() - start, "layout": layout}
    with open(os.path.join(folder, "scene.json"), "w") as stream:
        json.dump(info, stream, indent=1)
    write_path(folder, path)
    if not quiet:
        print("W1 scene: %d objects x %d triangles = %d triangles (%s%s), seed %d, %d frames, "
              "%.1f s -> %s" % (objects, triangles, triangles * objects, source,
                                ", TOM leaves" if is_tom else ", plain surfaces", seed, frames,
                                info["seconds"], folder))
    return info


def write_path(folder, path):
    with open(os.path.join(folder, "camera_path.json"), "w") as stream:
        json.dump(path, stream, indent=1)


def _read_json(path):
    """The JSON document in path, or None when it is missing or unreadable."""
    try:
        with open(path) as stream:
            return json.load(stream)
    except (OSError, ValueError):
        return None


def ensure_scene(folder, objects=DEFAULT_OBJECTS, seed=DEFAULT_SEED, frames=DEFAULT_FRAMES,
                 mesh=None, want_tom=True):
    """The scene in folder, written when missing or made with other settings;
    the camera path rewritten when the number of frames differs. Returns
    (scene.json dict, camera_path dict)."""
    info = _read_json(os.path.join(folder, "scene.json"))
    mesh = mesh or default_mesh()
    wanted_source = mesh if os.path.isfile(mesh) else None
    stale = (info is None or info.get("format_version") != FORMAT_VERSION or
             info.get("objects") != objects or info.get("seed") != seed or
             (wanted_source is not None and info.get("mesh") != wanted_source) or
             (want_tom and not info.get("tom") and _timecritical_available()) or
             not os.path.isfile(os.path.join(folder, "scene.vtm")))
    if stale:
        info = write_scene(folder, objects, seed, frames, mesh, want_tom)
    path = _read_json(os.path.join(folder, "camera_path.json"))
    if path is None or path.get("frames") != frames:
        path = camera_path(info["layout"], frames)
        write_path(folder, path)
    return info, path


def _timecritical_available():
    try:
        import timecritical  # noqa: F401
        return True
    except ImportError:
        return False


def main(argv=None):
    parser = argparse.ArgumentParser(
        description="Write the W1 walkthrough scene (scene.vtm: one cow per block, per-point "
                    "Colors) and its camera path (camera_path.json), as the C++ "
                    "WalkthroughBenchmark builds them.")
    parser.add_argument("--output", default=os.path.join("w1-output", "scene"),
                        help="output folder (default: %(default)s)")
    parser.add_argument("--objects", type=int, default=DEFAULT_OBJECTS,
                        help="number of cows, on a ceil(sqrt(N))-wide grid (default: %(default)s)")
    parser.add_argument("--frames", type=int, default=DEFAULT_FRAMES,
                        help="frames of the camera path (default: %(default)s)")
    parser.add_argument("--seed", type=int, default=DEFAULT_SEED,
                        help="seed of the placement (default: %(default)s, the benchmark's)")
    parser.add_argument("--mesh", default=default_mesh(),
                        help="the object's OBJ file (default: %(default)s; a substitute "
                             "ellipsoid when missing)")
    parser.add_argument("--plain", action="store_true",
                        help="write plain surfaces, not TOMs (the view then builds the TOMs)")
    args = parser.parse_args(argv)
    if args.objects < 1 or args.frames < 2:
        parser.error("--objects must be >= 1 and --frames >= 2")
    write_scene(args.output, args.objects, args.seed, args.frames, args.mesh, not args.plain)
    return 0


if __name__ == "__main__":
    sys.exit(main())
