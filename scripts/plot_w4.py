#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Plot W4 (w4.json of scripts/w4_benchmark.py): per change, for both views
and both loops of each variant (and the contour edit), the reader's time,
the time from the change to the first frame and (Time-Critical view) to the
hierarchy in use; the interactive frames of each change (median and max)
against the target; builds and cache hits; the process's RSS.

    /usr/bin/python3 scripts/plot_w4.py w4.json [--output w4.png]
"""
import argparse
import json
import math
import os

import matplotlib

matplotlib.use("Agg")  # headless: no display needed
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402

COLORS = {"render": "#1f77b4", "timecritical": "#d62728"}
STYLES = {"loop1": "-", "loop2": "--", "edit": "-", "back": "--"}


def series(run, phase, key, scale=1.0):
    changes = [c for c in run["changes"] if c["phase"] == phase]
    return ([c["index"] for c in changes],
            [math.nan if c.get(key) is None else c[key] * scale for c in changes])


def frame_stat(run, phase, fn):
    changes = [c for c in run["changes"] if c["phase"] == phase]
    values = []
    for c in changes:
        walls = [f["wall_ms"] for f in c["frames"][1:]]
        values.append(fn(walls) if walls else math.nan)
    return [c["index"] for c in changes], values


def median(values):
    values = sorted(values)
    n = len(values)
    return values[n // 2] if n % 2 else 0.5 * (values[n // 2 - 1] + values[n // 2])


def plot_times(ax, runs, target_ms):
    for run in runs:
        color = COLORS.get(run["view"], "black")
        for phase in sorted({c["phase"] for c in run["changes"]}):
            style = STYLES.get(phase, "-")
            x, y = series(run, phase, "first_frame_s", 1000.0)
            ax.plot(x, y, style, color=color, marker="o", markersize=3, linewidth=1.1,
                    label="%s %s: first frame" % (run["label"], phase))
            x, y = series(run, phase, "hierarchy_in_use_s", 1000.0)
            if any(not math.isnan(v) for v in y):
                ax.plot(x, y, style, color="#ff7f0e", marker="^", markersize=3, linewidth=0.9,
                        label="%s %s: hierarchy in use" % (run["label"], phase))
        # The reader's time (left out at the first show: showing the data read it).
        changes = [c for c in run["changes"] if c["phase"] == run["changes"][0]["phase"]
                   and not c["initial"]]
        ax.plot([c["index"] for c in changes], [1000.0 * c["reader_s"] for c in changes], ":",
                color=color, linewidth=0.9, label="%s %s: %s alone" % (
                    run["label"], run["changes"][0]["phase"],
                    "contour filter" if run["variant"] == "edit" else "reader"))
        initial = [c for c in run["changes"] if c["initial"]]
        ax.plot([c["index"] for c in initial], [1000.0 * c["first_frame_s"] for c in initial],
                "o", markersize=7, markerfacecolor="none", color=color)
    ax.axhline(2 * target_ms, color="black", linestyle="--", linewidth=0.8, label="2 x target")
    ax.set_yscale("log")
    ax.set_ylabel("ms after the change (log; circled: first show)")
    ax.legend(fontsize=6, loc="best")


def plot_frames(ax, runs, target_ms):
    for run in runs:
        color = COLORS.get(run["view"], "black")
        for phase in sorted({c["phase"] for c in run["changes"]}):
            style = STYLES.get(phase, "-")
            x, y = frame_stat(run, phase, median)
            ax.plot(x, y, style, color=color, linewidth=1.1,
                    label="%s %s: median" % (run["label"], phase))
            x, y = frame_stat(run, phase, max)
            ax.plot(x, y, style, color=color, linewidth=0.6, alpha=0.5,
                    label="%s %s: max" % (run["label"], phase))
    ax.axhline(1.1 * target_ms, color="black", linestyle="--", linewidth=0.8, label="110% target")
    ax.set_ylim(bottom=0)
    ax.set_ylabel("interactive frame ms")
    ax.legend(fontsize=6, loc="best")


def plot_builds(ax, runs):
    twin = ax.twinx()
    plotted = False
    for run in runs:
        color = COLORS.get(run["view"], "black")
        for phase in sorted({c["phase"] for c in run["changes"]}):
            style = STYLES.get(phase, "-")
            x, y = series(run, phase, "builds")
            if any(not math.isnan(v) for v in y):
                ax.plot(x, y, style, color=color, marker="s", markersize=3, linewidth=1.0,
                        label="%s %s: builds" % (run["label"], phase))
                x, h = series(run, phase, "cache_hits")
                ax.plot(x, h, style, color="#2ca02c", marker="x", markersize=3, linewidth=0.8,
                        label="%s %s: cache hits" % (run["label"], phase))
                plotted = True
            x, m = series(run, phase, "rss_mb")
            twin.plot(x, m, style, color=color, linewidth=0.6, alpha=0.4)
    ax.set_ylabel("leaves built / reused")
    twin.set_ylabel("RSS MiB (faint)")
    if plotted:
        ax.legend(fontsize=6, loc="best")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("json", help="w4.json written by scripts/w4_benchmark.py")
    parser.add_argument("--output", help="PNG to write (default: w4.png next to the JSON)")
    args = parser.parse_args()
    with open(args.json, encoding="utf-8") as f:
        data = json.load(f)
    output = args.output or os.path.join(os.path.dirname(os.path.abspath(args.json)), "w4.png")
    target_ms = data["settings"]["target_ms"]
    variants = []
    for run in data["runs"]:
        if run["variant"] not in variants:
            variants.append(run["variant"])
    fig, axes = plt.subplots(len(variants), 3, figsize=(17, 3.6 * len(variants) + 0.8),
                             squeeze=False)
    triangles = data["series"]["triangles"]
    fig.suptitle("W4 changing data: %d steps of %s-%s triangles, %d blocks, target %.0f ms, "
                 "%d orbit frames per change" % (
                     len(triangles), format(min(triangles), ","), format(max(triangles), ","),
                     data["series"]["settings"]["blocks"], target_ms,
                     data["settings"]["orbit_frames"]), fontsize=11)
    for row, variant in enumerate(variants):
        runs = [r for r in data["runs"] if r["variant"] == variant]
        what = "contour value change" if variant == "edit" else "time step"
        plot_times(axes[row][0], runs, target_ms)
        axes[row][0].set_title("%s: change -> first frame / hierarchy" % variant, fontsize=9)
        plot_frames(axes[row][1], runs, target_ms)
        axes[row][1].set_title("%s: interactive frames after the first" % variant, fontsize=9)
        plot_builds(axes[row][2], runs)
        axes[row][2].set_title("%s: builds, cache hits, memory" % variant, fontsize=9)
        for ax in axes[row]:
            ax.set_xlabel(what)
            ax.xaxis.set_major_locator(MaxNLocator(integer=True))
    fig.tight_layout(rect=(0, 0, 1, 0.97))
    fig.savefig(output, dpi=100)
    print(output)


if __name__ == "__main__":
    main()
