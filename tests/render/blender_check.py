# Runs inside Blender (blender -b --factory-startup --python-exit-code 1 --python blender_check.py -- ARGS):
# imports softbody's exports and checks them against the binary PLY frames, read here independently.
#   blender_check.py -- CACHE_DIR PLY_DIR OBJ_DIR CSV FRAME [FRAME ...]
# CACHE_DIR holds body0.obj, body0.pc2 and body0.mdd (one body), PLY_DIR/OBJ_DIR frame_%04d.ply/.obj.
# Point caches: the Mesh Cache modifier's evaluated vertices at each FRAME equal the PLY frame's vertices to
# float precision (the PC2/MDD and the PLY both hold float32 of the same doubles: the difference must be 0;
# 1e-6 m allows a last-bit rounding in Blender's reader). Sequences: the OBJ and the PLY of each FRAME
# imported by Blender have the PLY header's vertex and face counts and the same bounding box, whose lowest
# y equals the CSV's min_y to float precision.
import struct
import sys

import bpy

TOLERANCE_M = 1e-6


def read_ply(path):
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode()
    vertices = int(header.split("element vertex ")[1].split()[0])
    faces = int(header.split("element face ")[1].split()[0])
    xyz = struct.unpack_from("<%df" % (3 * vertices), data, end)
    return [xyz[i:i + 3] for i in range(0, len(xyz), 3)], faces


def read_min_y(csv_path, frame):
    with open(csv_path) as f:
        names = f.readline().strip().split(",")
        for line in f:
            row = dict(zip(names, line.strip().split(",")))
            if int(row["frame"]) == frame and int(row["body"]) == 0:
                return float(row["min_y"])
    raise SystemExit("FAIL: no CSV row for frame %d" % frame)


def clear_scene():
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)


def import_obj(path):
    # Blender's own axes are z up: ask for no conversion, so that coordinates stay the file's.
    before = set(bpy.data.objects)
    if hasattr(bpy.ops.wm, "obj_import"):
        bpy.ops.wm.obj_import(filepath=path, forward_axis="Y", up_axis="Z")
    else:
        bpy.ops.import_scene.obj(filepath=path, axis_forward="Y", axis_up="Z", split_mode="OFF")
    (obj,) = set(bpy.data.objects) - before
    return obj


def import_ply(path):
    before = set(bpy.data.objects)
    bpy.ops.import_mesh.ply(filepath=path)
    (obj,) = set(bpy.data.objects) - before
    return obj


def evaluated_vertices(obj):
    depsgraph = bpy.context.evaluated_depsgraph_get()
    evaluated = obj.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    world = obj.matrix_world
    points = [tuple(world @ v.co) for v in mesh.vertices]
    faces = len(mesh.polygons)
    evaluated.to_mesh_clear()
    return points, faces


def max_difference(a, b):
    if len(a) != len(b):
        raise SystemExit("FAIL: %d vertices against %d" % (len(a), len(b)))
    return max(abs(p - q) for u, v in zip(a, b) for p, q in zip(u, v))


def bounding_box(points):
    return [min(p[i] for p in points) for i in range(3)], [max(p[i] for p in points) for i in range(3)]


def check_point_cache(cache_dir, ply_dir, fmt, frames):
    clear_scene()
    obj = import_obj(cache_dir + "/body0.obj")
    modifier = obj.modifiers.new("softbody", "MESH_CACHE")
    modifier.cache_format = fmt.upper()
    modifier.filepath = cache_dir + "/body0." + fmt
    modifier.time_mode = "FRAME"
    modifier.play_mode = "SCENE"
    modifier.frame_start = 0.0   # scene frame F reads the cache's sample F
    modifier.frame_scale = 1.0
    modifier.interpolation = "NONE"
    worst = 0.0
    for frame in frames:
        bpy.context.scene.frame_set(frame)
        points, _ = evaluated_vertices(obj)
        expected, _ = read_ply("%s/frame_%04d.ply" % (ply_dir, frame))
        difference = max_difference(points, expected)
        moved = max_difference(points, read_ply("%s/frame_%04d.ply" % (ply_dir, 0))[0]) if frame else 0.0
        print("blender %s: frame %d: %d vertices, max |blender - ply| = %.3g m (moved %.3g m from frame 0)"
              % (fmt, frame, len(points), difference, moved))
        if frame and moved < 1e-3:
            raise SystemExit("FAIL: %s frame %d is where frame 0 is: the cache did not move the mesh" % (fmt, frame))
        if difference > TOLERANCE_M:
            raise SystemExit("FAIL: %s frame %d differs from the PLY by %g m" % (fmt, frame, difference))
        worst = max(worst, difference)
    return worst


def check_sequences(ply_dir, obj_dir, csv_path, frames):
    for frame in frames:
        expected, expected_faces = read_ply("%s/frame_%04d.ply" % (ply_dir, frame))
        low, high = bounding_box(expected)
        for kind, path, importer in (("obj", "%s/frame_%04d.obj" % (obj_dir, frame), import_obj),
                                     ("ply", "%s/frame_%04d.ply" % (ply_dir, frame), import_ply)):
            clear_scene()
            points, faces = evaluated_vertices(importer(path))
            got_low, got_high = bounding_box(points)
            box_difference = max(abs(a - b) for a, b in zip(got_low + got_high, low + high))
            print("blender %s sequence: frame %d: %d vertices, %d faces, box (%.4f %.4f %.4f)..(%.4f %.4f %.4f), "
                  "max box difference %.3g m" % (kind, frame, len(points), faces, *got_low, *got_high, box_difference))
            if len(points) != len(expected) or faces != expected_faces:
                raise SystemExit("FAIL: %s frame %d: %d vertices and %d faces, expected %d and %d"
                                 % (kind, frame, len(points), faces, len(expected), expected_faces))
            if box_difference > TOLERANCE_M:
                raise SystemExit("FAIL: %s frame %d: bounding box off by %g m" % (kind, frame, box_difference))
        min_y = read_min_y(csv_path, frame)
        if abs(low[1] - min_y) > TOLERANCE_M * max(1.0, abs(min_y)):
            raise SystemExit("FAIL: frame %d: lowest y %.9g, the CSV's min_y %.9g" % (frame, low[1], min_y))


def main():
    args = sys.argv[sys.argv.index("--") + 1:]
    cache_dir, ply_dir, obj_dir, csv_path = args[:4]
    frames = [int(a) for a in args[4:]]
    print("blender %s" % bpy.app.version_string)
    for fmt in ("pc2", "mdd"):
        check_point_cache(cache_dir, ply_dir, fmt, frames)
    check_sequences(ply_dir, obj_dir, csv_path, frames)
    print("blender check: OK")


main()
