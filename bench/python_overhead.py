#!/usr/bin/env python3
"""The cost of driving tandem from Python.

1. Planning: the same BiRRT runs (one thread, seeds 1..N) through `tandem plan --json` (a process
   that loads the problem and plans) and through `tandem.plan` (the problem loaded once, and loaded
   at every call), alternating run by run. Per run: the wall time of the call and the planner's own
   time (time_s of the record), whose difference is the overhead of the way in. The runs must agree
   (same tree digest), or the comparison means nothing.
2. Collision queries: tandem.Collision.is_free and distances on batches of random configurations
   within the bounds, against the same queries one call per configuration.

Medians and 90th percentiles; run it on an idle machine.

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/python_overhead.py \
           [--shared ../shared] [--tandem build/apps/tandem/tandem] [--runs 20]
"""
import argparse
import json
import os
import subprocess
import sys
import time

import numpy as np

import tandem


def percentile(values, p):
    return float(np.percentile(np.asarray(values), p))


def cli_run(binary, cfg, seed):
    start = time.perf_counter()
    r = subprocess.run([binary, "plan", cfg, "--planner", "birrt", "--seed", str(seed),
                        "--threads", "1", "--json", "--no-simplify"],
                       capture_output=True, text=True, check=False)
    wall = time.perf_counter() - start
    if r.returncode != 0:
        sys.exit(f"python_overhead: tandem plan failed: {r.stderr.strip()}")
    return wall, json.loads(r.stdout)


def py_run(what, seed):
    start = time.perf_counter()
    record = tandem.plan(what, planner="birrt", seed=seed, threads=1, simplify=False)
    return time.perf_counter() - start, record


def planning(binary, cfg, runs):
    problem = tandem.Problem(cfg)
    ways = {"tandem plan (a process)": [], "tandem.plan, problem loaded": [],
            "tandem.plan, loading the .cfg": []}
    for seed in range(1, runs + 1):
        results = [cli_run(binary, cfg, seed), py_run(problem, seed), py_run(cfg, seed)]
        digests = {r["tree_digest"] for _, r in results}
        if len(digests) != 1:
            sys.exit(f"python_overhead: seed {seed} gives different trees: {digests}")
        for (wall, record), key in zip(results, ways):
            ways[key].append((wall, record["time_s"]))
    print(f"## Planning: BiRRT on Easy, one thread, seeds 1-{runs}, alternating\n")
    print("| way in | median wall s | p90 wall s | median planner s | median overhead ms "
          "| p90 overhead ms |")
    print("| --- | ---: | ---: | ---: | ---: | ---: |")
    for key, rows in ways.items():
        wall = [w for w, _ in rows]
        planner = [p for _, p in rows]
        over = [1000 * (w - p) for w, p in rows]
        print(f"| {key} | {np.median(wall):.4f} | {percentile(wall, 90):.4f} "
              f"| {np.median(planner):.4f} | {np.median(over):.2f} | {percentile(over, 90):.2f} |")
    print()


def random_configs(problem, n, rng):
    lo, hi = problem.bounds
    q = np.empty((n, 7))
    q[:, :3] = rng.uniform(lo, hi, size=(n, 3))
    quat = rng.normal(size=(n, 4))
    q[:, 3:] = quat / np.linalg.norm(quat, axis=1, keepdims=True)
    return q


def rate(fn, count, repeats):
    rates = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        rates.append(count / (time.perf_counter() - start))
    return np.median(rates), percentile(rates, 10)


def collision(cfg, repeats):
    problem = tandem.Problem(cfg)
    c = tandem.Collision(problem)
    rng = np.random.default_rng(1)
    batch = random_configs(problem, 20000, rng)
    few = batch[:2000]
    rows = [
        ("is_free, a batch of 20 000", lambda: c.is_free(batch), len(batch)),
        ("is_free, one call per configuration", lambda: [c.is_free(q) for q in few], len(few)),
        ("distances, a batch of 20 000", lambda: c.distances(batch), len(batch)),
        ("nearest, one call per configuration", lambda: [c.nearest(q) for q in few], len(few)),
    ]
    print(f"## Collision queries on Easy: random configurations in the bounds, {repeats} repeats\n")
    print("| query | median queries/s | p10 queries/s |")
    print("| --- | ---: | ---: |")
    for name, fn, count in rows:
        med, p10 = rate(fn, count, repeats)
        print(f"| {name} | {med:,.0f} | {p10:,.0f} |")
    free = c.is_free(batch)
    print(f"\n({100 * np.mean(free):.0f}% of the configurations are free.)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--shared", default="../shared")
    parser.add_argument("--tandem", default="build/apps/tandem/tandem")
    parser.add_argument("--runs", type=int, default=20)
    parser.add_argument("--repeats", type=int, default=20)
    args = parser.parse_args()
    cfg = os.path.join(args.shared, "benchmarks", "omplapp", "3D", "Easy.cfg")
    if not os.path.exists(cfg):
        print(f"python_overhead: skipped: {cfg} is absent (the shared benchmarks)")
        return 0
    if args.runs < 1 or args.repeats < 1:
        sys.exit("python_overhead: --runs and --repeats must be at least 1")
    planning(args.tandem, cfg, args.runs)
    collision(cfg, args.repeats)
    return 0


if __name__ == "__main__":
    sys.exit(main())
