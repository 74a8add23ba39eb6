# Collider objects: mesh objects whose "Collider (softbody)" is on become the scene's mesh colliders (a "colliders"
# entry with "shape": "mesh"), which move the soft bodies and are not moved by them. One that keeps its transform over
# the frame range is written once, in world space. One whose transform is animated is written in its own frame and
# gets one key per frame ("keys", "interpolation": "linear"): softbody moves it between frames as Blender shows it at
# each. softbody's mesh colliders move and turn but do not scale, so the object's scale is baked into the mesh and
# may not change over the range. A collider's contact keys are the floor's (the scene's Floor settings).
import math

import mathutils

from . import scene_writer

# softbody's axes from Blender's: (x, y, z) -> (x, z, -y), a -90 degree turn about x (scene_writer.to_softbody).
Y_UP = mathutils.Matrix(((1.0, 0.0, 0.0), (0.0, 0.0, 1.0), (0.0, -1.0, 0.0)))
SAME_TRANSFORM = 1e-9  # largest difference of two matrices' entries that counts as no motion
SAME_SCALE = 1e-6      # relative


class ColliderError(ValueError):
    pass


def collider_objects(scene):
    """The scene's mesh objects with Collider (softbody) on, by name; a soft body may not also be a collider."""
    chosen = sorted((obj for obj in scene.objects if obj.type == "MESH" and obj.softbody_pressure.collider),
                    key=lambda obj: obj.name)
    for obj in chosen:
        if obj.softbody_pressure.enabled:
            raise ColliderError("%s is both a soft body and a collider: untick one of the two" % obj.name)
    return chosen


def transforms_over(scene, obj):
    """The object's world matrix at each frame of the scene's range, the current frame restored."""
    current = scene.frame_current
    matrices = []
    for frame in range(scene.frame_start, scene.frame_end + 1):
        scene.frame_set(frame)
        matrices.append(obj.matrix_world.copy())
    scene.frame_set(current)
    return matrices


def is_static(matrices):
    first = matrices[0]
    return all(abs(a - b) <= SAME_TRANSFORM for m in matrices[1:] for r, s in zip(m, first) for a, b in zip(r, s))


def constant_scale(obj, matrices):
    """The scale the object keeps over the range (checked: positive, unchanged)."""
    scales = [m.decompose()[2] for m in matrices]
    first = scales[0]
    if matrices[0].determinant() <= 0.0:
        raise ColliderError("%s is mirrored (a negative scale): an animated collider needs a positive scale" % obj.name)
    for frame, scale in enumerate(scales):
        if any(abs(a - b) > SAME_SCALE * max(abs(b), 1e-12) for a, b in zip(scale, first)):
            raise ColliderError("%s changes its scale over the frame range (frame %d of the bake: %s against %s): a "
                                "softbody collider may move and turn but not scale" % (obj.name, frame,
                                                                                      tuple(scale), tuple(first)))
    return first


def key_at(time_s, matrix, metres_per_unit, previous_euler):
    """One "keys" entry: the transform in softbody's axes and metres, rotation as X-then-Y-then-Z degrees."""
    location, rotation, _ = matrix.decompose()
    turned = Y_UP @ rotation.to_matrix() @ Y_UP.transposed()  # the same turn seen in softbody's axes
    euler = turned.to_euler("XYZ", previous_euler) if previous_euler is not None else turned.to_euler("XYZ")
    key = {"time": scene_writer.number(time_s),
           "position": [scene_writer.number(p) for p in Y_UP @ location * metres_per_unit],
           "rotation": [scene_writer.number(math.degrees(a)) for a in euler]}
    return key, euler


def local_mesh(obj, scale, metres_per_unit):
    """The object's mesh in its own frame with its scale applied, in softbody's axes and metres, triangulated."""
    mesh = obj.data
    points = [tuple(Y_UP @ mathutils.Vector([c * s for c, s in zip(v.co, scale)]) * metres_per_unit)
              for v in mesh.vertices]
    mesh.calc_loop_triangles()
    return points, [tuple(t.vertices) for t in mesh.loop_triangles]


def collider_entry(scene, obj, mesh_path, mesh_file, metres_per_unit):
    """Writes the collider's mesh to mesh_path and returns its "colliders" entry (mesh_file: its name in the scene)."""
    matrices = transforms_over(scene, obj)
    entry = {"shape": "mesh", "mesh": mesh_file}
    thickness = obj.softbody_pressure.collider_thickness
    if thickness > 0.0:
        entry["thickness"] = scene_writer.number(thickness * metres_per_unit)
    if is_static(matrices):
        current = scene.frame_current
        scene.frame_set(scene.frame_start)
        points, triangles = scene_writer.world_mesh(obj, metres_per_unit)
        scene.frame_set(current)
        scene_writer.write_ply(mesh_path, points, triangles)
        return entry
    points, triangles = local_mesh(obj, constant_scale(obj, matrices), metres_per_unit)
    scene_writer.write_ply(mesh_path, points, triangles)
    fps = scene.render.fps / scene.render.fps_base
    keys, euler = [], None
    for index, matrix in enumerate(matrices):
        key, euler = key_at(index / fps, matrix, metres_per_unit, euler)
        keys.append(key)
    entry["keys"] = keys
    entry["interpolation"] = "linear"
    return entry
