#!/usr/bin/python3
"""Draws docs/images/accuracy_cost_vs_error.png from `rayvec accuracy --json`.

Usage: rayvec accuracy --json > accuracy.json && scripts/plot_accuracy.py accuracy.json [out.png]
x: BVH primary-ray time relative to `mt` on the same ISA (median of back-to-back ratios); y: rays answered wrongly
(false miss + false hit + wrong nearest triangle) over all hard-case families, in percent.
Needs python3-matplotlib (Debian); CI does not run it.
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    src = sys.argv[1] if len(sys.argv) > 1 else "accuracy.json"
    out = sys.argv[2] if len(sys.argv) > 2 else "docs/images/accuracy_cost_vs_error.png"
    with open(src) as f:
        data = json.load(f)
    markers = {"scalar": "o", "avx2": "s", "avx512": "^"}
    colors = {"paper": "tab:gray", "mt": "tab:blue", "mt64": "tab:cyan",
              "watertight": "tab:red", "watertight64": "tab:orange"}
    fig, ax = plt.subplots(figsize=(9, 4.5))
    for m in data["modes"]:
        cost = m["bvh_time_vs_mt"]
        if cost <= 0:
            continue
        fams = [f for f in m["families"] if f["name"] != "random_control"]
        rays = sum(f["rays"] for f in fams)
        wrong = sum(f["false_misses"] + f["false_hits"] + f["wrong_nearest"] for f in fams)
        ax.scatter(cost, 100.0 * wrong / rays, marker=markers.get(m["isa"], "x"),
                   color=colors.get(m["intersector"], "k"), s=60,
                   label=f'{m["intersector"]} ({m["isa"]})')
    ax.set_xlabel("BVH primary-ray time relative to mt on the same ISA")
    ax.set_ylabel("hard-case rays answered wrongly (%)")
    ax.set_title("rayvec: cost against error (%d threads, %s)" % (data["threads"], data["cpu"]))
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print("wrote", out)


if __name__ == "__main__":
    main()
