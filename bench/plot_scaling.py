#!/usr/bin/env python3
"""Log-log plots of tandem-scaling's measurements (its --jsonl file), as SVG.

Usage: bench/plot_scaling.py scaling.jsonl OUT_DIR
Writes OUT_DIR/scaling-parts.svg, scaling-meshes.svg and scaling-trees.svg (those it has data for).
Needs matplotlib (Debian python3-matplotlib).
"""

import json
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)

SERIES = {
    "parts": ("parts (obstacles)", "queries per second", [
        ("checks_linear", "yes/no checks, linear loop"),
        ("checks_tree", "yes/no checks, broad phase"),
        ("distances_linear", "distance queries, linear loop"),
        ("distances_tree", "distance queries, broad phase"),
        ("clearances_linear", "clearance bounds, linear loop"),
        ("clearances_tree", "clearance bounds, broad phase"),
        ("checks_grid", "yes/no checks, distance grid then broad phase"),
        ("operator_hz", "operator loop (Hz)"),
    ]),
    "mesh": ("triangles", "queries per second", [
        ("checks", "yes/no checks"),
        ("distances", "distance queries"),
        ("clearances", "clearance bounds"),
    ]),
    "tree": ("nodes", "microseconds / bytes", [
        ("nearest_us", "nearest-neighbour query (us)"),
        ("bytes_per_node", "memory per node (bytes)"),
    ]),
}
X = {"parts": "parts", "mesh": "triangles", "tree": "nodes"}
FILE = {"parts": "scaling-parts.svg", "mesh": "scaling-meshes.svg", "tree": "scaling-trees.svg"}


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    try:
        rows = [json.loads(line) for line in Path(argv[1]).read_text().splitlines() if line.strip()]
    except (OSError, json.JSONDecodeError) as e:
        print(f"plot_scaling.py: {argv[1]}: {e}", file=sys.stderr)
        return 2
    out = Path(argv[2])
    out.mkdir(parents=True, exist_ok=True)
    for kind, (x_title, y_title, series) in SERIES.items():
        data = sorted((r for r in rows if r.get("kind") == kind), key=lambda r: r[X[kind]])
        if not data:
            continue
        fig, ax = plt.subplots(figsize=(9.0, 4.2))
        xs = [r[X[kind]] for r in data]
        for key, label in series:
            ax.plot(xs, [r[key] for r in data], marker="o", label=label)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(x_title)
        ax.set_ylabel(y_title)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize="small", loc="center left", bbox_to_anchor=(1.02, 0.5))
        fig.tight_layout()
        fig.savefig(out / FILE[kind])
        plt.close(fig)
        print(out / FILE[kind])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
