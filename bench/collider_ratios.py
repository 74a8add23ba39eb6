#!/usr/bin/env python3
"""The collider cost table of docs/performance.md from bench_colliders' JSON output (median CPU time per step).

    build/bench_colliders --benchmark_repetitions=7 --benchmark_min_time=0.3 \
        --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true \
        --benchmark_out=colliders.json --benchmark_out_format=json
    bench/collider_ratios.py colliders.json
"""
import json
import sys

INTEGRATORS = ["symplectic", "xpbd", "vbd"]  # the benchmark's first argument
GROUNDS = ["floor", "box", "far box", "mesh"]  # its second


def medians(path):
    """{(integrator, ground): median CPU time per step [µs]} from the benchmark's JSON file."""
    with open(path, encoding="utf-8") as f:
        runs = json.load(f)["benchmarks"]
    found = {}
    for run in runs:
        if run.get("aggregate_name") != "median":
            continue
        integrator, ground = (int(a) for a in run["run_name"].split("/")[1:3])
        found[(integrator, ground)] = run["cpu_time"]
    return found


def main():
    found = medians(sys.argv[1])
    print("| integrator | on the floor, no collider | on a box collider | a box 20 m away | on a mesh collider |")
    print("|---|---|---|---|---|")
    for i, name in enumerate(INTEGRATORS):
        if (i, 0) not in found:
            continue
        base = found[(i, 0)]
        cells = [f"{base:,.0f} µs"]
        for g in range(1, len(GROUNDS)):
            cells.append(f"{found[(i, g)]:,.0f} µs ({found[(i, g)] / base:.3f})" if (i, g) in found else "")
        print(f"| {name} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
