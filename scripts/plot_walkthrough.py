#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Plot the W1 walkthrough (walkthrough.json of WalkthroughBenchmark) like
Fig. 8 of Gobbetti & Bouvier: per frame the target, predicted and measured
frame time, and the triangles drawn against the potentially visible ones.

Layout: a top row of overlays of all policies (measured frame time on a log
scale, PSNR against full resolution), then one row per policy with its frame
times (left) and triangles (right); key frames A, B, turn and C are marked,
and the frames whose full-resolution time exceeds the target (where a policy
has to reduce, and the W1 goals measure the mean frame time) are shaded.

    /usr/bin/python3 scripts/plot_walkthrough.py walkthrough.json [--output walkthrough.png]
"""
import argparse
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # headless: no display needed
import matplotlib.pyplot as plt  # noqa: E402

COLORS = {
    "none": "#444444",
    "timecritical": "#d62728",
    "static": "#1f77b4",
    "feedback": "#2ca02c",
    "greedy": "#9467bd",
    "lodprop3d": "#ff7f0e",
}


def values(array, scale=1.0):
    """JSON nulls become NaN so that matplotlib leaves gaps."""
    return [math.nan if v is None else v * scale for v in array]


def mark_keys(axis, keys):
    # B and the turn are adjacent frames: B's label goes left of its line,
    # the others right, and C (the last frame) left, so none overlap.
    for name, frame in keys.items():
        axis.axvline(frame, color="#bbbbbb", linewidth=0.8, zorder=0)
        left = name in ("B", "C")
        axis.annotate(name, (frame, 1.0), xycoords=("data", "axes fraction"),
                      xytext=(-2 if left else 2, -10), textcoords="offset points",
                      ha="right" if left else "left", fontsize=7, color="#777777")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("json", help="walkthrough.json written by WalkthroughBenchmark")
    parser.add_argument("--output", help="PNG to write (default: walkthrough.png next to the JSON)")
    args = parser.parse_args()
    with open(args.json, encoding="utf-8") as f:
        data = json.load(f)
    output = args.output or os.path.join(os.path.dirname(os.path.abspath(args.json)), "walkthrough.png")

    target_ms = 1000.0 * data["settings"]["target_frame_time"]
    keys = data["path"]["key_frames"]
    policies = data["policies"]
    if not policies:
        sys.exit("no policy in " + args.json)
    reference = next((p for p in policies if p["name"] == "none"), None)
    frames = list(range(len(policies[0]["frames"]["measured"])))
    heavy = [m is not None and 1000.0 * m > target_ms
             for m in reference["frames"]["measured"]] if reference else []

    rows = 1 + len(policies)
    fig, axes = plt.subplots(rows, 2, figsize=(13, 2.3 * rows + 0.8), sharex=True, squeeze=False)
    scene = data["scene"]
    fig.suptitle(
        f"Walkthrough of {scene['objects']} objects ({scene['triangles']:,} triangles), "
        f"{len(frames)} frames, target {target_ms:.0f} ms"
        + (" - SUBSTITUTE MESH" if scene.get("substitute") else ""),
        fontsize=11)

    # Overlays: frame time of every policy, and PSNR.
    ax = axes[0][0]
    for p in policies:
        ax.plot(frames, values(p["frames"]["measured"], 1000.0), color=COLORS.get(p["name"]),
                linewidth=1.0, label=p["label"])
    ax.axhline(target_ms, color="black", linestyle="--", linewidth=0.8, label="target")
    ax.set_yscale("log")
    ax.set_ylabel("measured ms (log)")
    ax.set_title("frame time, all policies", fontsize=9)
    ax.legend(fontsize=7, ncol=2, loc="best")
    mark_keys(ax, keys)
    ax = axes[0][1]
    plotted = False
    for p in policies:
        psnr = values(p["frames"]["psnr"])
        if p["name"] != "none" and any(not math.isnan(v) for v in psnr):
            ax.plot(frames, psnr, color=COLORS.get(p["name"]), linewidth=1.0, label=p["label"])
            plotted = True
    ax.set_ylabel("PSNR dB")
    cap = data["settings"].get("psnr_cap", 99)
    ax.set_title(f"PSNR against full resolution (identical frames = {cap:g} dB)", fontsize=9)
    if plotted:
        ax.legend(fontsize=7, ncol=2, loc="lower right")
        ax.set_ylim(bottom=max(0.0, ax.get_ylim()[0]), top=min(cap + 2, ax.get_ylim()[1] + 1))
    mark_keys(ax, keys)

    # One row per policy, like Fig. 8: times on the left, triangles on the right.
    for row, p in enumerate(policies, start=1):
        fr = p["frames"]
        s = p["statistics"]
        color = COLORS.get(p["name"], "black")
        ax = axes[row][0]
        ax.plot(frames, values(fr["measured"], 1000.0), color=color, linewidth=1.2, label="measured")
        predicted = values(fr["predicted"], 1000.0)
        if any(not math.isnan(v) for v in predicted):
            ax.plot(frames, predicted, color="black", linewidth=0.8, linestyle=":", label="predicted")
        optimizer = values(fr["optimizer"], 1000.0)
        if any(not math.isnan(v) and v > 0 for v in optimizer):
            ax.plot(frames, optimizer, color="#8c564b", linewidth=0.8, label="optimizer")
        ax.axhline(target_ms, color="black", linestyle="--", linewidth=0.8, label="target")
        if any(heavy):
            ax.fill_between(frames, 0, 1, where=heavy, transform=ax.get_xaxis_transform(),
                            color="#f2e6c9", linewidth=0, zorder=0,
                            label="full res. > target")
        ax.set_ylim(bottom=0)
        ax.set_ylabel("ms")
        err = s.get("prediction_error")
        heavy_mean = s.get("heavy_mean")
        ax.set_title(
            f"{p['label']}: mean {1000 * s['mean']:.0f} ms"
            + (f" ({1000 * heavy_mean:.0f} shaded)" if heavy_mean is not None else "")
            + f", max {1000 * s['max']:.0f} ms, "
            f"CV {100 * s['cv']:.1f}%, {100 * s['share_within_110_percent']:.0f}% <= 1.1 target"
            + (f", pred. err. {100 * err:.1f}%" if err is not None else ""),
            fontsize=8)
        ax.legend(fontsize=7, loc="upper right")
        mark_keys(ax, keys)

        ax = axes[row][1]
        if reference is not None:
            ax.fill_between(frames, values(reference["frames"]["triangles"]), color="#dddddd",
                            label="full resolution (visible)")
        ax.plot(frames, values(fr["triangles"]), color=color, linewidth=1.2, label="drawn")
        ax.set_ylim(bottom=0)
        ax.set_ylabel("triangles")
        psnr = s.get("psnr_mean")
        ax.set_title(
            f"{p['label']}: {s['triangles_mean']:,.0f} triangles per frame"
            + (f", mean PSNR {psnr:.1f} dB" if psnr is not None and p["name"] != "none" else ""),
            fontsize=8)
        ax.legend(fontsize=7, loc="upper right")
        mark_keys(ax, keys)

    for ax in axes[-1]:
        ax.set_xlabel("frame")
    fig.tight_layout(rect=(0, 0, 1, 0.98))
    fig.savefig(output, dpi=110)
    print(output)


if __name__ == "__main__":
    main()
