#!/usr/bin/env python3
"""The breathing frequency of body 0 in a `softbody simulate` CSV: upward crossings of the volume's mean.

usage: bench/breathing_frequency.py FILE.csv   (frames fine enough to resolve the period: fps >= 20 x f)
"""
import csv
import sys


def main(path):
    rows = [r for r in csv.DictReader(open(path)) if r["body"] == "0"]
    t = [float(r["time"]) for r in rows]
    v = [float(r["volume"]) for r in rows]
    mean = sum(v) / len(v)
    # linear interpolation of the time where V passes its mean upwards
    ups = [t[i - 1] + (t[i] - t[i - 1]) * (mean - v[i - 1]) / (v[i] - v[i - 1])
           for i in range(1, len(v)) if v[i - 1] < mean <= v[i]]
    print(f"volume: start {v[0]:.4g} m^3, mean {mean:.4g}, range {min(v) / v[0] - 1:+.1%} .. {max(v) / v[0] - 1:+.1%}")
    if len(ups) < 2:
        print("fewer than two upward crossings of the mean: no frequency")
        return 1
    print(f"{len(ups)} upward crossings, frequency {(len(ups) - 1) / (ups[-1] - ups[0]):.3f} Hz")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
