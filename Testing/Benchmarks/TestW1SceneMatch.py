#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Checks that the W1 scene of scripts/make_w1_scene.py (as
Examples/Python/w1_walkthrough.py makes it, through ensure_scene) is the scene
of the C++ benchmarks (WalkthroughBenchmark --write-scene): object count, each
object's place, turn, colour, transform and bounds, the triangles per object,
and the camera path frame by frame, within float tolerance.

    TestW1SceneMatch.py --benchmark build/bin/WalkthroughBenchmark --output DIR
        [--objects N] [--frames N] [--data DIR]

--data names the folder with cow.obj; a folder without it makes both sides
use the substitute ellipsoid. Put the build tree's Python package on
PYTHONPATH so that the Python side builds TOMs, as the example does.
"""

import argparse
import json
import math
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPOSITORY = os.path.normpath(os.path.join(HERE, "..", ".."))
TOLERANCE = 1e-9  # relative to the herd's extent


class Mismatch(Exception):
    pass


def close(a, b, scale, what):
    if not math.isclose(a, b, rel_tol=0.0, abs_tol=TOLERANCE * scale):
        raise Mismatch("%s: C++ %r, Python %r" % (what, a, b))


def close_vectors(a, b, scale, what):
    if len(a) != len(b):
        raise Mismatch("%s: C++ has %d values, Python %d" % (what, len(a), len(b)))
    for k, (x, y) in enumerate(zip(a, b)):
        close(x, y, scale, "%s[%d]" % (what, k))


def equal(a, b, what):
    if a != b:
        raise Mismatch("%s: C++ %r, Python %r" % (what, a, b))


def cpp_scene(args, path):
    subprocess.run([args.benchmark, "--write-scene", path, "--objects", str(args.objects),
                    "--frames", str(args.frames), "--data", args.data], check=True)
    with open(path) as stream:
        return json.load(stream)


def python_scene(args, folder):
    sys.path.insert(0, os.path.join(REPOSITORY, "scripts"))
    import make_w1_scene

    shutil.rmtree(folder, ignore_errors=True)
    info, path = make_w1_scene.ensure_scene(folder, args.objects, make_w1_scene.DEFAULT_SEED,
                                            args.frames, os.path.join(args.data, "cow.obj"))
    return make_w1_scene, info, path


def block_bounds(folder):
    """Triangles and bounds of each block of scene.vtm, in block order."""
    from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataReader

    reader = vtkXMLMultiBlockDataReader()
    reader.SetFileName(os.path.join(folder, "scene.vtm"))
    reader.Update()
    blocks = reader.GetOutput()
    return [(blocks.GetBlock(n).GetNumberOfPolys(), blocks.GetBlock(n).GetBounds())
            for n in range(blocks.GetNumberOfBlocks())]


def compare_layout(cpp, py, generator):
    a, b = cpp["layout"], py["layout"]
    scale = a["extent"]
    equal(cpp["objects"], py["objects"], "object count")
    equal(cpp["substitute"], py["substitute"], "substitute object")
    equal(cpp["triangles_per_object"], py["triangles_per_object"], "triangles per object")
    equal(a["grid"], b["grid"], "grid side")
    equal(a["focus_object"], b["focus_object"], "focus object")
    for key in ("spacing", "jitter", "extent", "footprint_radius", "height"):
        close(a[key], b[key], scale, key)
    close_vectors(a["center"], b["center"], scale, "object anchor")
    for n, (p, q) in enumerate(zip(a["objects"], b["objects"])):
        close(p["x"], q["x"], scale, "object %d x" % n)
        close(p["z"], q["z"], scale, "object %d z" % n)
        close(p["angle"], q["angle"], 360.0, "object %d angle" % n)
        equal(p["color"], q["color"], "object %d colour" % n)
        matrix = generator._matrix(b, q)
        for i in range(4):
            close_vectors(p["matrix"][i], list(matrix[i]), scale, "object %d matrix row %d" % (n, i))


def compare_blocks(cpp, blocks):
    scale = cpp["layout"]["extent"]
    equal(len(blocks), cpp["objects"], "blocks in scene.vtm")
    for n, (triangles, bounds) in enumerate(blocks):
        equal(triangles, cpp["triangles_per_object"], "block %d triangles" % n)
        # The scene's points are stored as written (double), so the bounds
        # agree to rounding.
        close_vectors(cpp["layout"]["objects"][n]["bounds"], list(bounds), scale,
                      "block %d bounds" % n)


def compare_path(cpp, py):
    a, b = cpp["camera_path"], py
    scale = cpp["layout"]["extent"]
    equal(a["frames"], b["frames"], "frames")
    equal(a["key_frames"], b["key_frames"], "key frames")
    equal(a["window"], b["window"], "window")
    for frame in range(a["frames"]):
        close_vectors(a["position"][frame], b["position"][frame], scale,
                      "frame %d position" % frame)
        close_vectors(a["focal_point"][frame], b["focal_point"][frame], scale,
                      "frame %d focal point" % frame)
        close(a["view_angle"], b["view_angle"][frame], 1.0, "frame %d view angle" % frame)
        close_vectors([0.0, 1.0, 0.0], b["view_up"][frame], 1.0, "frame %d view up" % frame)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--benchmark", required=True, help="the WalkthroughBenchmark executable")
    parser.add_argument("--output", required=True, help="scratch folder")
    parser.add_argument("--objects", type=int, default=64)
    parser.add_argument("--frames", type=int, default=30)
    parser.add_argument("--data", default=os.environ.get("TIMECRITICAL_SHARED_DATA_DIR", ""),
                        help="folder with cow.obj (a folder without it: the substitute)")
    args = parser.parse_args()
    os.makedirs(args.output, exist_ok=True)

    cpp = cpp_scene(args, os.path.join(args.output, "cpp-scene.json"))
    folder = os.path.join(args.output, "python-scene")
    generator, info, path = python_scene(args, folder)
    if not info["tom"]:
        print("note: the Python side wrote plain surfaces (no timecritical package)")
    try:
        compare_layout(cpp, info, generator)
        compare_blocks(cpp, block_bounds(folder))
        compare_path(cpp, path)
    except Mismatch as error:
        print("W1 scenes differ: %s" % error)
        return 1
    print("W1 scenes match: %d objects x %d triangles (%s), %d frames" % (
        cpp["objects"], cpp["triangles_per_object"], cpp["mesh"], cpp["frames"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
