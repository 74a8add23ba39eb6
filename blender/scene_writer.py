# Blender's scene as softbody's input: the scene file (scene.json) and one PLY per baked mesh, in the bake folder.
# Blender is z up, softbody y up (both right-handed, metres): a point (x, y, z) of Blender is (x, z, -y) in softbody,
# a -90° turn about x; lengths are multiplied by the scene's unit scale (Blender units to metres).
import json
import os
import re
import struct

SCENE_FILE = "scene.json"
MESH_FOLDER = "meshes"
CACHE_FOLDER = "cache"


class BakeLayout:
    """The files of one bake under its folder: the scene file, the meshes written for it and the program's caches."""

    def __init__(self, folder):
        self.folder = folder

    @property
    def scene_path(self):
        return os.path.join(self.folder, SCENE_FILE)

    @property
    def cache_folder(self):
        return os.path.join(self.folder, CACHE_FOLDER)

    def mesh_path(self, body):
        return os.path.join(self.folder, MESH_FOLDER, "body%d.ply" % body)

    def written_mesh_path(self, body):
        """The mesh the program wrote for the body (its vertex order is the cache's)."""
        return os.path.join(self.cache_folder, "body%d.obj" % body)

    def cache_path(self, body):
        return os.path.join(self.cache_folder, "body%d.pc2" % body)

    def collider_path(self, collider, extension):
        """A collider's file (.ply, or .obj and .pc2 for a deforming one) and its name in the scene file."""
        path = os.path.join(self.folder, MESH_FOLDER, "collider%d%s" % (collider, extension))
        return path, os.path.relpath(path, self.folder)


def number(value):
    """A setting as the scene file gets it: Blender keeps settings as float32, whose 7 significant digits are what
    was typed (0.0001, not 9.999999747378752e-05)."""
    return float("%.7g" % value)


def to_softbody(point, metres_per_unit=1.0):
    """Blender (z up, scene units) to softbody (y up, metres)."""
    x, y, z = point
    return (x * metres_per_unit, z * metres_per_unit, -y * metres_per_unit)


def to_blender(point, metres_per_unit=1.0):
    """softbody (y up, metres) to Blender (z up, scene units): the inverse of to_softbody."""
    x, y, z = point
    return (x / metres_per_unit, -z / metres_per_unit, y / metres_per_unit)


def write_ply(path, points, triangles):
    """A binary PLY (float32 x y z, as Blender holds them; int32 triangles). PLY, not OBJ: softbody keeps a PLY's
    vertex order, so the cache it writes fits the object's own mesh (an OBJ's vertices come back in the order the
    faces first use them)."""
    os.makedirs(os.path.dirname(path), exist_ok=True)
    header = ("ply\nformat binary_little_endian 1.0\ncomment written by softbody's Blender add-on: y up, metres\n"
              "element vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
              "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % (len(points), len(triangles)))
    with open(path, "wb") as f:
        f.write(header.encode("ascii"))
        f.write(b"".join(struct.pack("<3f", *p) for p in points))
        f.write(b"".join(struct.pack("<B3i", 3, *t) for t in triangles))


def write_obj(path, points, triangles):
    """An OBJ of v and f lines (9 significant digits): softbody keeps an OBJ's v order, which a point cache follows."""
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write("# written by softbody's Blender add-on: y up, metres\n")
        f.write("".join("v %.9g %.9g %.9g\n" % p for p in points))
        f.write("".join("f %d %d %d\n" % (a + 1, b + 1, c + 1) for a, b, c in triangles))


def write_pc2(path, frames):
    """A PC2 point cache: every frame's points (float32), sample i at frame i (start frame 0, one frame apart)."""
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as f:
        f.write(b"POINTCACHE2\0" + struct.pack("<iiffi", 1, len(frames[0]), 0.0, 1.0, len(frames)))
        f.write(b"".join(struct.pack("<3f", *p) for points in frames for p in points))


def read_obj(path):
    """The v and f lines of an OBJ (faces as 0-based vertex indices; texture and normal indices dropped)."""
    points, faces = [], []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                points.append(tuple(float(v) for v in parts[1:4]))
            elif parts[0] == "f":
                faces.append(tuple(int(v.split("/")[0]) - 1 for v in parts[1:]))
    return points, faces


def scene_name(name):
    """A name softbody accepts for a scene (it names out/NAME): letters, digits, '-', '_' and '.'."""
    cleaned = re.sub(r"[^A-Za-z0-9_.-]+", "_", name).strip(".") or "blender"
    return cleaned[:200]


def body_keys(settings, mesh_file, metres_per_unit=1.0):
    """One bodies[] entry from an object's settings (properties.SoftbodyObjectSettings)."""
    body = {"mesh": mesh_file, "mass": number(settings.mass)}
    if settings.stiffness_mode == "YOUNGS":
        body["stiffness"] = {"youngs": number(settings.youngs),
                             "thickness": number(settings.thickness * metres_per_unit)}
    elif settings.stiffness_mode == "FREQUENCY":
        body["stiffness"] = {"frequency": number(settings.frequency)}
    else:
        body["stiffness"] = settings.stiffness
    if settings.damping_mode == "RATIO":
        body["damping"] = {"ratio": number(settings.damping_ratio)}
    else:
        body["damping"] = number(settings.damping)
    if settings.pressure_mode == "INFLATION":
        body["pressure"] = {"inflation": number(settings.inflation), "start": settings.inflation_start}
    else:
        body["pressure"] = number(settings.pressure)
    if settings.bending_mode == "RATIO":
        body["bending"] = {"ratio": number(settings.bending_ratio)}
    else:
        body["bending"] = number(settings.bending)
    if settings.resolution_mode == "VERTICES":
        body["resolution"] = settings.resolution
    elif settings.resolution_mode == "EDGE_LENGTH":
        body["resolution"] = {"edge_length": number(settings.edge_length * metres_per_unit)}
    if settings.repair:
        body["repair"] = True
    if settings.self_collision:
        body["self_collision"] = True
    return body


class FrameRangeError(ValueError):
    pass


def run_keys(scene, metres_per_unit=1.0):
    """The scene file's top-level keys but the bodies, from a Blender scene: its frame range and frame rate make
    duration and fps (softbody's frame 0 is the scene's start frame), its gravity the gravity."""
    settings = scene.softbody_pressure
    if scene.render.fps_base != 1.0:
        raise FrameRangeError("softbody needs a whole number of frames per second: the scene's frame rate is %g/%g"
                              % (scene.render.fps, scene.render.fps_base))
    frames = scene.frame_end - scene.frame_start
    if frames < 1:
        raise FrameRangeError("the scene's frame range %d..%d holds no frame after the start"
                              % (scene.frame_start, scene.frame_end))
    fps = scene.render.fps
    gravity = to_softbody(scene.gravity, metres_per_unit) if scene.use_gravity else (0.0, 0.0, 0.0)
    keys = {
        "name": scene_name(scene.name),
        "duration": frames / fps,
        "fps": fps,
        "solver": {"integrator": settings.integrator, "dt": "auto" if settings.dt_auto else number(settings.dt)},
        "gravity": [number(g) for g in gravity],
    }
    if settings.floor:
        floor = {"height": number(settings.floor_height * metres_per_unit), "contact": settings.floor_contact}
        if settings.floor_contact != "paper":
            floor.update(restitution=number(settings.floor_restitution), friction=number(settings.floor_friction))
        keys["floor"] = floor
    return keys


def write_scene(path, keys, bodies, colliders=()):
    scene = dict(keys)
    if colliders:
        scene["colliders"] = list(colliders)
    scene["bodies"] = bodies
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        json.dump(scene, f, indent=2)
        f.write("\n")


def placed_mesh(matrix, local_points, triangles, metres_per_unit=1.0):
    """Local points placed by a Blender world matrix, in softbody's axes and metres, and the triangles facing out."""
    points = [to_softbody(matrix @ p, metres_per_unit) for p in local_points]
    if matrix.determinant() < 0.0:  # a mirroring transform turns the faces inside out: keep them facing out
        triangles = [(a, c, b) for a, b, c in triangles]
    return points, triangles


def world_mesh(obj, metres_per_unit=1.0):
    """The object's mesh (without its modifiers) in world space, in softbody's axes and metres, triangulated."""
    mesh = obj.data
    mesh.calc_loop_triangles()
    triangles = [tuple(t.vertices) for t in mesh.loop_triangles]
    return placed_mesh(obj.matrix_world, [v.co for v in mesh.vertices], triangles, metres_per_unit)
