#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Turns bench_occlusion's JSON into the docs/occlusion.md table and a PNG plot.

    build/bench/bench_occlusion --benchmark_out=occlusion.json --benchmark_out_format=json
    python3 bench/plot_occlusion.py occlusion.json docs/images/occlusion-bench.png

Prints the markdown table on stdout. Needs matplotlib (apt-get install python3-matplotlib);
only for regenerating the docs, not for building or testing.
"""
import json
import sys
from collections import defaultdict


def load(path):
    with open(path) as f:
        data = json.load(f)
    rows = defaultdict(dict)  # method -> cpu work ms -> counters
    for b in data["benchmarks"]:
        parts = b["name"].split("/")  # BM_FrameLoop/<method>/cpu_work_ms:<n>/...
        method, work = parts[1], int(parts[2].split(":")[1])
        rows[method][work] = b
    return data.get("context", {}), rows


def table(rows):
    works = sorted(next(iter(rows.values())).keys())
    head = ["method"] + [f"fps, {w} ms work" for w in works] + [
        "measure() CPU ms", "all GL calls CPU ms", "GPU ms (timer query)", "latency (frames)",
        "mean abs error", "max abs error"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for method, by_work in rows.items():
        zero = by_work[works[0]]
        cells = [f"`{method}`"] + [f"{by_work[w]['fps']:.1f}" for w in works]
        cells += [f"{zero['measure_cpu_ms']:.1f}", f"{zero['gl_cpu_ms']:.1f}", f"{zero['gpu_ms']:.2f}",
                  f"{int(zero['latency_frames'])}", f"{zero['err_mean']:.4f}", f"{zero['err_max']:.4f}"]
        lines.append("| " + " | ".join(cells) + " |")
    if "readback" in rows and "texture-mask" in rows:
        ratios = [rows["texture-mask"][w]["fps"] / rows["readback"][w]["fps"] for w in works]
        lines.append("")
        lines.append("texture-mask / readback frames/s: " +
                     ", ".join(f"{r:.2f}x at {w} ms" for r, w in zip(ratios, works)) +
                     " (GPG2: 53.5 / 27.8 = 1.92x)")
    return "\n".join(lines)


def plot(rows, context, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.5))
    for method, by_work in rows.items():
        works = sorted(by_work)
        left.plot(works, [by_work[w]["fps"] for w in works], marker="o", label=method)
    left.set_xlabel("simulated game work on the CPU per frame (ms)")
    left.set_ylabel("frames per second")
    left.set_title("Frame rate against CPU work, 600x500 demo drive")
    left.grid(alpha=0.3)
    left.legend(fontsize=8)

    names = list(rows)
    zero = [rows[m][min(rows[m])] for m in names]
    x = range(len(names))
    right.bar([i - 0.2 for i in x], [z["err_mean"] for z in zero], width=0.4, label="mean")
    right.bar([i + 0.2 for i in x], [z["err_max"] for z in zero], width=0.4, label="max")
    right.set_xticks(list(x))
    right.set_xticklabels(names, rotation=30, ha="right", fontsize=8)
    right.set_ylabel("|coverage - raycast|")
    right.set_title("Error against the ray-cast truth (24 drive frames)")
    right.grid(axis="y", alpha=0.3)
    right.legend(fontsize=8)

    label = zero[0].get("label", "")
    fig.suptitle(f"flarekit occlusion methods on {label} ({context.get('num_cpus', '?')} CPUs)", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=100)


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: plot_occlusion.py BENCH.json OUT.png")
    context, rows = load(sys.argv[1])
    print(table(rows))
    plot(rows, context, sys.argv[2])


if __name__ == "__main__":
    main()
