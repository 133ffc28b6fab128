#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Plot the W2 benchmark (viewdependent.json of ViewDependentBenchmark).

Per frame and policy: frame time (log scale, with the target), triangles drawn
(log scale), PSNR against full resolution, and the refinement time of the
view-dependent policies; the camera distance and the light turn are shaded.
With --mixed results, a last row shows the mixed scene (cows + the object)
next to the cows alone: frame times and PSNR on the reference frames.

    /usr/bin/python3 scripts/plot_viewdependent.py viewdependent.json [--output viewdependent.png]
"""
import argparse
import json
import math
import os

import matplotlib

matplotlib.use("Agg")  # headless: no display needed
import matplotlib.pyplot as plt  # noqa: E402

COLORS = {
    "full": "#444444",
    "tau1": "#d62728",
    "uniform": "#1f77b4",
    "budget": "#2ca02c",
    "mixed": "#9467bd",
    "cows": "#ff7f0e",
}


def values(array, scale=1.0):
    """JSON nulls become NaN so that matplotlib leaves gaps."""
    return [math.nan if v is None else v * scale for v in array]


def shade_path(axis, data, frames):
    phases = data["path"]["phases"]
    last = max(frames - 1, 1)
    axis.axvspan(phases["light_start"] * last, phases["light_end"] * last, color="#fff2cc",
                 zorder=0, label="light turns")
    for name, frame in data["path"]["key_frames"].items():
        axis.axvline(frame, color="#cccccc", linewidth=0.8, zorder=0)
        axis.annotate(name, (frame, 1.0), xycoords=("data", "axes fraction"), xytext=(2, -10),
                      textcoords="offset points", fontsize=7, color="#777777")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("json", help="viewdependent.json written by ViewDependentBenchmark")
    parser.add_argument("--output", help="PNG to write (default: viewdependent.png next to the JSON)")
    args = parser.parse_args()
    with open(args.json, encoding="utf-8") as f:
        data = json.load(f)
    output = args.output or os.path.join(os.path.dirname(os.path.abspath(args.json)),
                                         "viewdependent.png")
    target_ms = 1000.0 * data["settings"]["target_frame_time"]
    frames = data["settings"]["frames"]
    runs = [p for p in data["policies"] if p.get("ran")]
    mixed = data.get("mixed")

    rows = 3 if mixed else 2
    fig, axes = plt.subplots(rows, 2, figsize=(14, 4.2 * rows), squeeze=False)
    x = list(range(frames))

    ax = axes[0][0]
    shade_path(ax, data, frames)
    for run in runs:
        ax.plot(x, values(run["frames"]["measured"], 1000.0), color=COLORS.get(run["name"]),
                linewidth=1.2, label=run["label"])
    ax.axhline(target_ms, color="black", linestyle="--", linewidth=0.8, label="target")
    ax.axhline(1.1 * target_ms, color="black", linestyle=":", linewidth=0.8, label="+10%")
    ax.set_yscale("log")
    ax.set_ylabel("frame time (ms)")
    ax.set_title("frame time (wall clock around Render, glFinish)")
    ax.legend(fontsize=7, loc="upper right")

    ax = axes[0][1]
    shade_path(ax, data, frames)
    for run in runs:
        ax.plot(x, values(run["frames"]["triangles"]), color=COLORS.get(run["name"]),
                linewidth=1.2, label=run["label"])
    ax.set_yscale("log")
    ax.set_ylabel("triangles drawn")
    ax.set_title("triangles (full: %d, %s)" % (data["object"]["triangles"],
                                                os.path.basename(data["object"]["source"].split(" ")[0])))
    ax.legend(fontsize=7, loc="lower right")

    ax = axes[1][0]
    shade_path(ax, data, frames)
    for run in runs:
        if run["name"] == "full":
            continue
        ax.plot(x, values(run["frames"]["psnr"]), color=COLORS.get(run["name"]), linewidth=1.2,
                label="%s (mean %.1f dB)" % (run["label"], run["statistics"]["psnr_mean"] or math.nan))
    ax.axhline(40.0, color="black", linestyle="--", linewidth=0.8, label="40 dB goal")
    ax.set_ylabel("PSNR vs full resolution (dB)")
    ax.set_xlabel("frame")
    ax.set_title("image quality")
    ax.legend(fontsize=7, loc="lower left")

    ax = axes[1][1]
    shade_path(ax, data, frames)
    for run in runs:
        if run["name"] in ("tau1", "budget"):
            ax.plot(x, values(run["frames"]["refinement"], 1000.0), color=COLORS.get(run["name"]),
                    linewidth=1.2, label=run["label"])
    ax.axhline(5.0, color="black", linestyle="--", linewidth=0.8, label="5 ms goal")
    ax.set_ylabel("refinement time (ms)")
    ax.set_xlabel("frame")
    ax.set_title("front update (splits and merges) per frame")
    ax.legend(fontsize=7, loc="upper right")

    if mixed:
        mx = list(range(mixed["frames"]))
        ax = axes[2][0]
        for run in mixed["runs"]:
            ax.plot(mx, values(run["frames"]["measured"], 1000.0), color=COLORS.get(run["name"]),
                    linewidth=1.2, label=run["label"])
        w1 = mixed.get("w1", {})
        if w1.get("found") and w1.get("median") is not None:
            ax.axhline(1000.0 * w1["median"], color="#8c564b", linestyle="-.", linewidth=0.8,
                       label="W1 TimeCritical median (walkthrough.json)")
        ax.axhline(target_ms, color="black", linestyle="--", linewidth=0.8, label="target")
        ax.axhline(1.1 * target_ms, color="black", linestyle=":", linewidth=0.8)
        ax.set_ylabel("frame time (ms)")
        ax.set_xlabel("frame of W1's path")
        ax.set_title("mixed scene: %d cows + the object, one budget" % mixed["cows"])
        ax.legend(fontsize=7, loc="upper right")
        ax = axes[2][1]
        for run in mixed["runs"]:
            psnr = values(run["frames"]["psnr"])
            pts = [(i, v) for i, v in enumerate(psnr) if not math.isnan(v)]
            ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="o", markersize=3,
                    color=COLORS.get(run["name"]), linewidth=1.0, label=run["label"])
        ax.set_ylabel("PSNR vs full resolution (dB)")
        ax.set_xlabel("frame of W1's path")
        ax.set_title("mixed scene: PSNR on the reference frames (identical = 99 dB)")
        ax.legend(fontsize=7, loc="lower left")

    fig.suptitle("W2 view-dependent refinement: %s, %d frames at %dx%d" % (
        data["object"]["name"], frames, data["settings"]["window"][0],
        data["settings"]["window"][1]))
    fig.tight_layout()
    fig.savefig(output, dpi=110)
    print("wrote", output)


if __name__ == "__main__":
    main()
