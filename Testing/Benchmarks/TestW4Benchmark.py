#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Smoke test of the W4 benchmark (scripts/w4_benchmark.py): writes the tiny
series (make_w4_series.py --tiny), plays it under pvbatch in both views, and
checks that w4.json holds every field with plausible values, that the key
frames are written and that scripts/plot_w4.py plots it.

    TestW4Benchmark.py --pvbatch pvbatch --plugin build/.../TimeCritical.so --output DIR

Put the build tree's Python package on PYTHONPATH (the benchmark reads the
view's wrapped classes); run under an X server (xvfb-run).
"""

import argparse
import json
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPTS = os.path.normpath(os.path.join(HERE, "..", "..", "scripts"))
CHANGE_FIELDS = ("phase", "index", "initial", "reader_s", "first_frame_s", "first_frame_total_s",
                 "frames", "rss_mb", "peak_rss_mb", "hierarchy_in_use_s",
                 "frames_until_hierarchy", "builds", "hierarchies_swapped", "cache_hits", "counters")
TC_FRAME_FIELDS = ("wall_ms", "measured_ms", "predicted_ms", "triangles", "still", "objects",
                   "toms", "pending", "hierarchy_in_use")
SUMMARY_FIELDS = ("changes", "reader_s", "first_frame_s", "hierarchy_in_use_s", "interactive_ms",
                  "interactive_within_110_percent", "frames_before_hierarchy_ms",
                  "frames_after_hierarchy_ms", "builds", "cache_hits", "rss_mb_max")
GOALS = ("first frame after a change <= 2x target",
         "loop 1: change -> hierarchy in use <= Render View's change -> first frame",
         "second loop / edit-and-back build nothing",
         "interactive frames after the first <= 110% target in >= 99%")


class Failure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failure(message)


def positive_seconds(value, what, limit=120.0):
    check(isinstance(value, (int, float)) and math.isfinite(value) and 0.0 <= value < limit,
          "%s = %r: not a time in [0, %g) s" % (what, value, limit))


def check_change(run, change, orbit, blocks):
    where = "%s/%s %s change %s" % (run["variant"], run["view"], change.get("phase"),
                                    change.get("index"))
    for field in CHANGE_FIELDS:
        check(field in change, "%s: no field %s" % (where, field))
    positive_seconds(change["reader_s"], where + " reader_s")
    positive_seconds(change["first_frame_s"], where + " first_frame_s")
    check(change["first_frame_s"] > 0, where + ": first frame took no time")
    check(abs(change["first_frame_total_s"] - change["reader_s"] - change["first_frame_s"]) < 1e-9,
          where + ": first_frame_total_s is not reading + first frame")
    check(len(change["frames"]) >= orbit, "%s: %d frames, orbit %d" % (
        where, len(change["frames"]), orbit))
    check(50.0 < change["rss_mb"] <= change["peak_rss_mb"] < 64 * 1024,
          "%s: RSS %r, peak %r MiB" % (where, change["rss_mb"], change["peak_rss_mb"]))
    for frame in change["frames"]:
        check(0.0 < frame["wall_ms"] < 60000.0, "%s: frame of %r ms" % (where, frame["wall_ms"]))
    if run["view"] == "render":
        check(change["hierarchy_in_use_s"] is None and change["builds"] is None,
              where + ": hierarchy figures in ParaView's Render View")
        return
    objects = blocks if run["variant"] == "blocks" else 1
    for frame in change["frames"]:
        for field in TC_FRAME_FIELDS:
            check(field in frame, "%s: frame without %s" % (where, field))
        check(frame["objects"] == objects, "%s: %d objects, expected %d" % (
            where, frame["objects"], objects))
        check(0 <= frame["toms"] <= frame["objects"], where + ": TOM count out of range")
        check(frame["triangles"] > 0, where + ": a frame drew nothing")
        check(not frame["still"], where + ": an interactive frame was a still render")
    check(change["hierarchy_in_use_s"] is not None, where + ": the hierarchy never came into use")
    check(change["hierarchy_in_use_s"] >= change["first_frame_s"] - 1e-6,
          where + ": hierarchy in use before the first frame ended")
    if change["builds"] is None:  # background builds, not countable from Python
        check(change["hierarchies_swapped"] is not None, where + ": neither builds nor swaps")
    else:
        check(0 <= change["builds"] <= 2 * objects, "%s: %r builds of %d objects" % (
            where, change["builds"], objects))
    check(0 <= change["cache_hits"] <= objects, "%s: %r cache hits" % (where, change["cache_hits"]))
    check("builder.Builds" in change["counters"], where + ": builder counters missing")


def check_runs(data, orbit, blocks):
    runs = {(r["variant"], r["view"]): r for r in data["runs"]}
    expected = {(v, k) for v in ("surface", "blocks", "edit") for k in ("render", "timecritical")}
    check(set(runs) == expected, "runs %s, expected %s" % (sorted(runs), sorted(expected)))
    steps = len(data["series"]["triangles"])
    for (variant, view), run in runs.items():
        for field in ("label", "settings", "changes", "summary"):
            check(field in run, "%s/%s: no %s" % (variant, view, field))
        for change in run["changes"]:
            check_change(run, change, orbit, blocks)
        phases = [c["phase"] for c in run["changes"]]
        if variant == "edit":
            check(phases[0] == "edit" and phases[-1] == "back", "edit phases %s" % phases)
            values = [c["contour_value"] for c in run["changes"]]
            check(values[0] == values[-1] and len(set(values)) > 1, "contour values %s" % values)
        else:
            check(phases == ["loop1"] * steps + ["loop2"] * steps, "%s phases %s" % (variant, phases))
        check([c["initial"] for c in run["changes"]].count(True) == 1, "one initial change")
        for phase, summary in run["summary"].items():
            for field in SUMMARY_FIELDS:
                check(field in summary, "%s/%s %s summary: no %s" % (variant, view, phase, field))
        if view == "timecritical" and variant != "edit":
            built = sum(c["builds"] if c["builds"] is not None else c["hierarchies_swapped"]
                        for c in run["changes"] if c["phase"] == "loop1")
            check(built >= steps, "%s: loop 1 built %d leaves over %d new steps" % (
                variant, built, steps))


def check_output(path, output, orbit, blocks):
    with open(path) as stream:
        data = json.load(stream)
    for field in ("benchmark", "settings", "machine", "series", "runs", "goals", "key_frames"):
        check(field in data, "w4.json has no %s" % field)
    check(data["settings"]["orbit_frames"] == orbit, "orbit frames %r" % data["settings"])
    check(len(data["series"]["triangles"]) >= 2 and min(data["series"]["triangles"]) > 1000,
          "series triangles %r" % data["series"]["triangles"])
    check_runs(data, orbit, blocks)
    names = [g["goal"] for g in data["goals"]]
    for name in GOALS:
        check(name in names, "goal %r not evaluated (%s)" % (name, names))
    for g in data["goals"]:
        check(isinstance(g["passed"], bool) and g["text"], "goal %r" % g)
    check(len(data["key_frames"]) >= 4, "key frames %r" % data["key_frames"])
    for name in data["key_frames"]:
        check(os.path.getsize(os.path.join(output, name)) > 1000, "key frame %s is empty" % name)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pvbatch", required=True)
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--output", required=True)
    args = parser.parse_args()
    os.makedirs(args.output, exist_ok=True)
    data = os.path.join(args.output, "data")
    subprocess.run([sys.executable, os.path.join(SCRIPTS, "make_w4_series.py"), "--tiny",
                    "--output", data], check=True)
    with open(os.path.join(data, "series.json")) as stream:
        blocks = json.load(stream)["settings"]["blocks"]
    run = subprocess.run([args.pvbatch, "--force-offscreen-rendering",
                          os.path.join(SCRIPTS, "w4_benchmark.py"), "--tiny", "--data", data,
                          "--output", args.output, "--plugin", args.plugin],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(run.stdout)
    check(run.returncode == 0, "w4_benchmark.py exited with %d" % run.returncode)
    for sign in ("ERR|", "Traceback"):  # warnings: the builder drops degenerate triangles
        check(sign not in run.stdout, "pvbatch printed %r" % sign)
    printed = run.stdout.split("Goals (Time-Critical Render View):")
    check(len(printed) == 2, "no goals printed")
    verdicts = [line.split()[0] for line in printed[1].splitlines() if line.strip()][:len(GOALS)]
    check(len(verdicts) >= len(GOALS) and set(verdicts) <= {"PASS", "MISS"},
          "goal lines without PASS/MISS: %s" % verdicts)
    check_output(os.path.join(args.output, "w4.json"), args.output, 2, blocks)
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        print("no matplotlib: plot_w4.py not checked")
    else:
        png = os.path.join(args.output, "w4.png")
        subprocess.run([sys.executable, os.path.join(SCRIPTS, "plot_w4.py"),
                        os.path.join(args.output, "w4.json"), "--output", png], check=True)
        check(os.path.getsize(png) > 10000, "the plot is empty")
    print("W4 benchmark smoke test passed")


if __name__ == "__main__":
    try:
        main()
    except Failure as failure:
        print("FAILED: %s" % failure)
        sys.exit(1)
