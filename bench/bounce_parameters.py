#!/usr/bin/env python3
"""What each parameter of scenes/bounce.json does to the motion: one parameter changed at a time.

Prints a Markdown table (docs/physics/model.md, "What each parameter does"). Every run uses dt = 2.5e-5 s,
inside forward Euler's stable range for every variant (the least damped one, 0.25 N·s/m on 3000 N/m springs,
needs dt < c/k = 8.3e-5 s), so that the rows differ by the parameter only. The squash is the ball's height
(highest minus lowest vertex) at its deepest compression during the first contact, over its diameter at frame 0,
from a PC2 point cache sampled at 60 frames per second (1/60 s holds 667 steps of 2.49875e-5 s, as 1/30 s
holds 1334: the same run as the CSV's); the rest from the simulate CSV.
    bench/bounce_parameters.py [path/to/softbody]
"""
import array
import csv
import os
import struct
import subprocess
import sys
import tempfile

SOFTBODY = sys.argv[1] if len(sys.argv) > 1 else "build/softbody"
SCENE = "scenes/bounce.json"
COMMON = ["--set", "solver.dt=2.5e-5"]
VARIANTS = [
    ("the scene as it is", []),
    ("before issue 16's change: mass 1 kg, nRT 30 J", ["bodies.0.mass=1", "bodies.0.pressure=30"]),
    ("mass 1 kg", ["bodies.0.mass=1"]),
    ("mass 8 kg", ["bodies.0.mass=8"]),
    ("stiffness 1500 N/m", ["bodies.0.stiffness=1500"]),
    ("stiffness 10000 N/m", ["bodies.0.stiffness=10000"]),
    ("damping 0.25 N·s/m", ["bodies.0.damping=0.25"]),
    ("damping 2 N·s/m", ["bodies.0.damping=2"]),
    ("pressure (nRT) 30 J", ["bodies.0.pressure=30"]),
    ("pressure (nRT) 120 J", ["bodies.0.pressure=120"]),
    ("velocity 1 m/s", ["bodies.0.velocity=[1,0,0]"]),
    ("velocity 4 m/s", ["bodies.0.velocity=[4,0,0]"]),
    ("dropped from 5 m", ["bodies.0.position=[0,5,0]"]),
    ("friction floor (restitution 0.3, μ 0.6)",
     ["floor.contact=friction", "floor.restitution=0.3", "floor.friction=0.6"]),
    ("a balloon: 1 kg, stiffness 100 N/m, springs 5 % stretched by the gas (intent)",
     ["bodies.0.mass=1", "bodies.0.stiffness=100", 'bodies.0.pressure={"inflation":0.05}']),
]


def with_sets(args, sets):
    for s in sets:
        args += ["--set", s]
    return args


def heights(sets):
    """Per frame at 60 fps: (height of the ball's box, lowest vertex), from a PC2 point cache."""
    with tempfile.TemporaryDirectory() as folder:
        args = with_sets([SOFTBODY, "export", SCENE, "--format", "pc2", "-o", folder, "--set", "fps=60"] + COMMON, sets)
        subprocess.run(args, capture_output=True, check=True)
        data = open(os.path.join(folder, "body0.pc2"), "rb").read()
    points, samples = struct.unpack("<12siiffi", data[:32])[2::3]  # header: signature, version, points, start, rate, samples
    xyz = array.array("f")
    xyz.frombytes(data[32:32 + 12 * points * samples])
    frames = []
    for f in range(samples):
        ys = xyz[3 * points * f + 1:3 * points * (f + 1):3]
        frames.append((max(ys) - min(ys), min(ys)))
    return frames


def squash(sets):
    """The ball's height at the deepest compression of its first contact (0.5 s from touching, 30 samples) over its diameter."""
    frames = heights(sets)
    diameter = frames[0][0]
    contact = next(i for i, (_, low) in enumerate(frames) if low < 0.01 * diameter)
    return min(h for h, _ in frames[contact:contact + 30]) / diameter, frames[-1][0] / diameter


def measure(sets):
    args = with_sets([SOFTBODY, "simulate", SCENE, "--csv", "-"] + COMMON, sets)
    out = subprocess.run(args, capture_output=True, text=True, check=True).stdout
    rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(out.splitlines())]
    contact = next(i for i, r in enumerate(rows) if r["min_y"] < 0.02)
    after = rows[contact:]
    deepest, rest = squash(sets)
    return {
        "squash": deepest,                                           # height at the deepest squash / diameter
        "rest": rest,                                                # height at the end / diameter (the sag)
        "volume": min(r["volume"] for r in after) / rows[0]["volume"],
        "rebound": max(r["min_y"] for r in after),                   # highest lowest vertex after landing, m
        "forward": max(r["com_x"] for r in rows),                    # farthest x, m
        "back": max(r["com_x"] for r in rows) - rows[-1]["com_x"],   # the going back, m
        "vx": min(r["vel_x"] for r in after),                        # most negative x velocity, m/s
    }


if __name__ == "__main__":
    print("| change from scenes/bounce.json | height at deepest squash / diameter | height at 3 s / diameter | least volume | rebound (m) | farthest x (m) | going back (m) | most negative vx (m/s) |")
    print("|---|---|---|---|---|---|---|---|")
    for name, sets in VARIANTS:
        m = measure(sets)
        print(f"| {name} | {m['squash']:.2f} | {m['rest']:.2f} | {m['volume']:.2f} | {m['rebound']:.2f} | "
              f"{m['forward']:.2f} | {m['back']:.2f} | {m['vx']:+.2f} |", flush=True)
