#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Plot the W3 scale benchmark (w3.json of W3Benchmark).

Top: measured and predicted frame time per frame with the target and 110% of
it. Middle: triangles drawn per frame. Bottom: process RSS and glibc heap in
use at each memory sample.

    /usr/bin/python3 scripts/plot_w3.py w3.json [--output w3.png]
"""
import argparse
import json
import os

import matplotlib

matplotlib.use("Agg")  # headless: no display needed
import matplotlib.pyplot as plt  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("json")
    parser.add_argument("--output", default=None)
    args = parser.parse_args()
    with open(args.json) as f:
        data = json.load(f)
    rows = data["rows"]
    frames = [r["frame"] for r in rows]
    target = 1000.0 * data["target"]
    fig, axes = plt.subplots(3, 1, figsize=(9, 10))
    ax = axes[0]
    ax.plot(frames, [1000.0 * r["measured"] for r in rows], label="measured")
    ax.plot(frames, [1000.0 * (r["predicted"] or 0.0) for r in rows], label="predicted", alpha=0.7)
    ax.axhline(target, color="k", lw=0.8, label="target")
    ax.axhline(1.1 * target, color="r", lw=0.8, ls="--", label="110% of target")
    ax.set_ylabel("frame time (ms)")
    ax.set_title("W3: %d objects, %.1fM triangles; %.1f%% of frames <= 110%% of target"
                 % (data["objects"], data["triangles"] / 1e6,
                    100.0 * data["frame_time"]["share_within_110_percent"]))
    ax.legend(fontsize=8)
    ax = axes[1]
    ax.plot(frames, [r["triangles"] for r in rows])
    ax.set_ylabel("triangles drawn")
    ax.set_xlabel("frame")
    ax = axes[2]
    memory = data["memory"]
    labels = [m["label"] for m in memory]
    x = range(len(memory))
    ax.bar([i - 0.2 for i in x], [m["rss"] / 2**20 for m in memory], width=0.4, label="RSS")
    ax.bar([i + 0.2 for i in x], [m["heap"] / 2**20 for m in memory], width=0.4, label="heap in use")
    ax.set_xticks(list(x))
    ax.set_xticklabels(labels, rotation=20, ha="right", fontsize=7)
    ax.set_ylabel("MiB")
    ax.legend(fontsize=8)
    fig.tight_layout()
    output = args.output or os.path.splitext(args.json)[0] + ".png"
    fig.savefig(output, dpi=100)
    print("wrote", output)


if __name__ == "__main__":
    main()
