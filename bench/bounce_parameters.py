#!/usr/bin/env python3
"""What each parameter of scenes/bounce.json does to the motion: one parameter changed at a time.

Prints a Markdown table (README "What each parameter does to the picture"). Every run uses dt = 2.5e-5 s,
inside forward Euler's stable range for every variant (the least damped one, 0.1 N·s/m, needs dt < c/k =
3.3e-5 s), so that the rows differ by the parameter only.
    bench/bounce_parameters.py [path/to/softbody]
"""
import csv
import subprocess
import sys

SOFTBODY = sys.argv[1] if len(sys.argv) > 1 else "build/softbody"
VARIANTS = [
    ("the scene as it is", []),
    ("stiffness 1000 N/m", ["bodies.0.stiffness=1000"]),
    ("stiffness 10000 N/m", ["bodies.0.stiffness=10000"]),
    ("damping 0.1 N·s/m", ["bodies.0.damping=0.1"]),
    ("damping 2 N·s/m", ["bodies.0.damping=2"]),
    ("pressure (nRT) 15 J", ["bodies.0.pressure=15"]),
    ("pressure (nRT) 60 J", ["bodies.0.pressure=60"]),
    ("velocity 1 m/s", ["bodies.0.velocity=[1,0,0]"]),
    ("velocity 4 m/s", ["bodies.0.velocity=[4,0,0]"]),
    ("dropped from 5 m", ["bodies.0.position=[0,5,0]"]),
]


def measure(sets):
    args = [SOFTBODY, "simulate", "scenes/bounce.json", "--csv", "-", "--set", "solver.dt=2.5e-5"]
    for s in sets:
        args += ["--set", s]
    out = subprocess.run(args, capture_output=True, text=True, check=True).stdout
    rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(out.splitlines())]
    contact = next(i for i, r in enumerate(rows) if r["min_y"] < 0.02)
    after = rows[contact:]
    return {
        "deepest": min(r["com_y"] for r in after[:30]),            # centre height at the deepest squash, m
        "rest": rows[-1]["com_y"],                                   # centre height at the end (the sag), m
        "volume": min(r["volume"] for r in after) / rows[0]["volume"],
        "rebound": max(r["min_y"] for r in after),                   # highest lowest vertex after landing, m
        "forward": max(r["com_x"] for r in rows),                    # farthest x, m
        "back": max(r["com_x"] for r in rows) - rows[-1]["com_x"],   # the going back, m
        "vx": min(r["vel_x"] for r in after),                        # most negative x velocity, m/s
    }


print("| change from scenes/bounce.json | centre at deepest squash (m) | centre at 3 s (m) | least volume | rebound (m) | farthest x (m) | going back (m) | most negative vx (m/s) |")
print("|---|---|---|---|---|---|---|---|")
for name, sets in VARIANTS:
    m = measure(sets)
    print(f"| {name} | {m['deepest']:.2f} | {m['rest']:.2f} | {m['volume']:.2f} | {m['rebound']:.2f} | "
          f"{m['forward']:.2f} | {m['back']:.2f} | {m['vx']:+.2f} |", flush=True)
