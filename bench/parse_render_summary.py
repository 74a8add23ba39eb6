"""Turns the summary line of `softbody render` into one CSV row for bench/run_performance.sh."""
import re
import sys

width, height, shadows, msaa, line = sys.argv[1:6]
frames = re.search(r"(\d+) frames", line).group(1)
fps = re.search(r"([\d.]+) fps end to end", line).group(1)
stage = {name: re.search(name + r" ([\d.]+)", line).group(1)
         for name in ("simulate", "render", "read-back", "encode")}
print(",".join([width, height, shadows, msaa, frames, fps, stage["simulate"], stage["render"],
                stage["read-back"], stage["encode"]]))
