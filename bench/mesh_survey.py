#!/usr/bin/env python3
"""Every mesh file given, from its original file to a soft body (issue 17): what `softbody prepare` repairs,
then the drop of bench/mesh_survey.json (repair, a 1,500-vertex proxy, bending links), its volume over the run
and its last frame rendered; the last frames tiled into one contact sheet (ffmpeg), in the order given.

usage: bench/mesh_survey.py OUT MESH...   (each MESH a file; it is scaled to 1 m across and set 0.3 m up)
environment: SOFTBODY (default build/softbody)
Prints one Markdown table row per model; writes OUT/NAME.txt (every command's output), OUT/NAME.csv,
OUT/NAME/frame_0045.png and OUT/contact_sheet.png."""
import csv
import os
import re
import subprocess
import sys
import time

SCENE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "mesh_survey.json")
EXE = os.environ.get("SOFTBODY", "build/softbody")
LAST_FRAME = 45  # 1.5 s at 30 fps


def run(command, log):
    """Runs command, appends its output to log; returns (exit status, wall seconds, output)."""
    start = time.monotonic()
    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, errors="replace")
    wall = time.monotonic() - start
    with open(log, "a", encoding="utf-8") as f:
        f.write("$ " + " ".join(command) + f"\n{done.stdout}exit {done.returncode}, {wall:.1f} s\n\n")
    return done.returncode, wall, done.stdout


def bounding_box(obj_path):
    """The smallest and largest corner of an OBJ file's vertices."""
    low, high = [float("inf")] * 3, [float("-inf")] * 3
    with open(obj_path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("v "):
                p = [float(c) for c in line.split()[1:4]]
                low = [min(a, b) for a, b in zip(low, p)]
                high = [max(a, b) for a, b in zip(high, p)]
    return low, high


def notes_of(output, words):
    """The `note:` lines of output that contain one of words, without the file prefix."""
    found = []
    for line in output.splitlines():
        if line.startswith("note:") and any(w in line for w in words):
            found.append(line.split(": ", 3)[-1] if line.count(": ") >= 3 else line[6:])
    return found


def survey(out, mesh):
    name = os.path.splitext(os.path.basename(mesh))[0]
    log = os.path.join(out, name + ".txt")
    open(log, "w", encoding="utf-8").close()
    prepared = os.path.join(out, name + "_prepared.obj")
    status, wall, text = run([EXE, "prepare", mesh, prepared], log)
    if status != 0:
        return name, f"refused (exit {status}): {text.strip().splitlines()[-1]}", "", "", None
    repair = "; ".join(n.removeprefix("repair: ") for n in notes_of(text, ["repair", "removed", "filled", "split",
                                                                          "joined", "part"])) or "nothing"
    low, high = bounding_box(prepared)
    extent = max(h - l for l, h in zip(low, high))
    scale = 1.0 / extent
    position = [-(low[0] + high[0]) / 2 * scale, 0.3 - low[1] * scale, -(low[2] + high[2]) / 2 * scale]
    settings = ["--set", f"bodies.0.mesh={os.path.abspath(mesh)}", "--set", f"bodies.0.scale={scale:.6g}",
                "--set", "bodies.0.position=[%.6g,%.6g,%.6g]" % tuple(position)]
    table = os.path.join(out, name + ".csv")
    status, wall, text = run([EXE, "simulate", SCENE, *settings, "--csv", table], log)
    if status != 0:
        return name, repair, f"simulate exit {status}: {text.strip().splitlines()[-1]}", "", None
    proxy = "; ".join(notes_of(text, ["resolution"]))
    match = re.search(r"remesh of (\d+) vertices .*\(volume ([^)]*)\); the mesh's (\d+) vertices", proxy)
    if match:
        proxy = f"{match[1]} vertices (volume {match[2]}) for {match[3]}"
    with open(table, encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    volumes = [float(r["volume"]) for r in rows]
    lowest = min(float(r["min_y"]) for r in rows)
    result = (f"{wall:.1f} s for 1.5 s; volume {min(volumes) / volumes[0]:.3f}..{max(volumes) / volumes[0]:.3f} "
              f"of the start; lowest vertex {lowest * 1000:.0f} mm")
    frames = os.path.join(out, name)
    status, _, text = run([EXE, "render", SCENE, *settings, "--frames", str(LAST_FRAME), "-o", frames], log)
    picture = os.path.join(frames, "frame_%04d.png" % LAST_FRAME) if status == 0 else None
    return name, repair, proxy, result, picture


def contact_sheet(out, pictures):
    columns = 4
    inputs, layout = [], []
    for k, p in enumerate(pictures):
        inputs += ["-i", p]
        layout.append(f"{k % columns * 480}_{k // columns * 360}")
    rows = (len(pictures) + columns - 1) // columns
    subprocess.run(["ffmpeg", "-loglevel", "error", "-y", *inputs, "-filter_complex",
                    f"xstack=inputs={len(pictures)}:layout={'|'.join(layout)}:fill=white,"
                    f"pad={columns * 480}:{rows * 360}:0:0:white",
                    os.path.join(out, "contact_sheet.png")], check=True)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    print("| model | what repair did | proxy | the drop (xpbd auto, 1.5 s) |\n|---|---|---|---|")
    pictures = []
    for mesh in sys.argv[2:]:
        name, repair, proxy, result, picture = survey(out, mesh)
        print(f"| {name} | {repair} | {proxy} | {result} |", flush=True)
        if picture:
            pictures.append(picture)
    if len(pictures) > 1:
        models = len(pictures)
        contact_sheet(out, pictures)
        print(f"wrote {out}/contact_sheet.png ({models} models in the order above, rows of 4)")


if __name__ == "__main__":
    main()
