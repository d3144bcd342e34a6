#!/usr/bin/env python3
"""Compares two results folders of `tandem bench` (made on a cluster and on one machine): the same
runs (configuration, seed, status, validity, iterations, nodes, tree digest, ...) and the same
report, apart from timings (the report's time column, a run's time_s and operator_wait_s) and the
command quoted in the report.

Usage: compare_results.py FOLDER_A FOLDER_B   (exit 0 when equal; else prints the differences)
"""
import json
import re
import sys

TIMING_FIELDS = {"time_s", "operator_wait_s"}


def runs(folder):
    records = {}
    with open(f"{folder}/runs.jsonl") as f:
        for line in f:
            r = json.loads(line)
            key = (r["config"], r["seed"])
            records[key] = {k: v for k, v in r.items() if k not in TIMING_FIELDS}
    return records


def report(folder):
    """report.md without the time column of its tables and the command it quotes."""
    lines = []
    time_column = None
    with open(f"{folder}/report.md") as f:
        for line in f:
            line = re.sub(r"Produced by `[^`]*`", "Produced by `...`", line.rstrip("\n"))
            if line.startswith("|"):
                cells = line.split("|")
                if "time s" in [c.strip() for c in cells]:
                    time_column = [c.strip() for c in cells].index("time s")
                if time_column is not None and len(cells) > time_column:
                    del cells[time_column]
                line = "|".join(cells)
            else:
                time_column = None
            lines.append(line)
    return lines


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    a, b = sys.argv[1:]
    failed = False
    ra, rb = runs(a), runs(b)
    if ra.keys() != rb.keys():
        print(f"different runs: only in {a}: {sorted(ra.keys() - rb.keys())}; "
              f"only in {b}: {sorted(rb.keys() - ra.keys())}")
        failed = True
    for key in sorted(ra.keys() & rb.keys()):
        if ra[key] != rb[key]:
            diff = {k: (ra[key].get(k), rb[key].get(k)) for k in ra[key].keys() | rb[key].keys()
                    if ra[key].get(k) != rb[key].get(k)}
            print(f"run {key} differs: {diff}")
            failed = True
    pa, pb = report(a), report(b)
    if pa != pb:
        for la, lb in zip(pa, pb):
            if la != lb:
                print(f"report differs:\n  {la}\n  {lb}")
        if len(pa) != len(pb):
            print(f"report lengths differ: {len(pa)} and {len(pb)} lines")
        failed = True
    if failed:
        return 1
    print(f"same {len(ra)} runs and the same report apart from timings: {a} and {b}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
