#!/usr/bin/env python3
"""The markdown table of docs/large_steps_bounce.csv (bench_large_steps) for docs/performance.md."""
import csv
import sys


def figure(text, digits=2):
    """A number to `digits` significant figures, or a dash when empty."""
    if text == "":
        return "–"
    return f"{float(text):.{digits}g}"


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "docs/large_steps_bounce.csv"
    print("| level, span | program | floor | step | dt [s] | CPU s per simulated s | wall s per simulated s "
          "| centre-of-mass max error [m] | worst volume error [%] | RMS vertex error at the end [m] "
          "| RMS vertex error over the frames [m] | status |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            runs = int(row["runs"])
            cpu = figure(row["cpu_s_per_sim_s"]) + (f" (median of {runs})" if runs > 1 else "")
            print(f"| {row['level']}, {row['duration_s']} s | {row['program']} | {row['contact']} | {row['step']} "
                  f"| {figure(row['dt_s'], 3)} | {cpu} | {figure(row['wall_s_per_sim_s'])} "
                  f"| {figure(row['com_max_error_m'])} | {figure(row['volume_worst_error_pct'])} "
                  f"| {figure(row['rms_end_m'])} | {figure(row['rms_samples_m'])} | {row['status']} |")


if __name__ == "__main__":
    main()
