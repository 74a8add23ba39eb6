# Collider objects: mesh objects whose "Collider (softbody)" is on become the scene's mesh colliders (a "colliders"
# entry with "shape": "mesh"), which move the soft bodies and are not moved by them. One that keeps its transform over
# the frame range is written once, in world space. One whose transform is animated is written in its own frame and
# gets one key per frame ("keys", "interpolation": "linear"): softbody moves it between frames as Blender shows it at
# each. softbody's mesh colliders move and turn but do not scale, so the object's scale is baked into the mesh and
# may not change over the range. One whose evaluated mesh changes shape (modifiers, shape keys, an armature) is
# written as an OBJ and a PC2 point cache of its world positions at every frame ("cache"). The mesh is the evaluated
# one (modifiers applied). A collider's contact keys are the floor's (the scene's Floor settings).
import math

import bpy
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


def sample_over(scene, obj):
    """The object at each frame of the scene's range, the current frame restored: its world matrix and its evaluated
    mesh (modifiers and shape keys applied) as local points and triangles."""
    current = scene.frame_current
    samples = []
    for frame in range(scene.frame_start, scene.frame_end + 1):
        scene.frame_set(frame)
        evaluated = obj.evaluated_get(bpy.context.evaluated_depsgraph_get())
        mesh = evaluated.to_mesh()
        mesh.calc_loop_triangles()
        samples.append(Sample(obj.matrix_world.copy(), [v.co.copy() for v in mesh.vertices],
                              [tuple(t.vertices) for t in mesh.loop_triangles]))
        evaluated.to_mesh_clear()
    scene.frame_set(current)
    return samples


class Sample:
    def __init__(self, matrix, points, triangles):
        self.matrix, self.points, self.triangles = matrix, points, triangles


def is_static(matrices):
    first = matrices[0]
    return all(abs(a - b) <= SAME_TRANSFORM for m in matrices[1:] for r, s in zip(m, first) for a, b in zip(r, s))


def deforms(obj, samples):
    """Whether the evaluated mesh changes shape over the range (checked: its triangles stay the same)."""
    first = samples[0]
    for frame, sample in enumerate(samples[1:], start=1):
        if sample.triangles != first.triangles:
            raise ColliderError("%s changes its triangles over the frame range (frame %d of the bake): a collider "
                                "needs the same mesh at every frame" % (obj.name, frame))
    return any(abs(a - b) > SAME_TRANSFORM for sample in samples[1:] for p, q in zip(sample.points, first.points)
               for a, b in zip(p, q))


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
           "position": [scene_writer.number(p) for p in scene_writer.to_softbody(location, metres_per_unit)],
           "rotation": [scene_writer.number(math.degrees(a)) for a in euler]}
    return key, euler


def collider_entry(scene, obj, paths, metres_per_unit):
    """Writes the collider's files and returns its "colliders" entry. paths(extension) gives the file to write and its
    name in the scene file."""
    samples = sample_over(scene, obj)
    entry = {"shape": "mesh"}
    thickness = obj.softbody_pressure.collider_thickness
    if thickness > 0.0:
        entry["thickness"] = scene_writer.number(thickness * metres_per_unit)
    if deforms(obj, samples):  # an OBJ (the cache follows its v lines) and a PC2 of world points, frame 0 at 0 s
        mesh_path, entry["mesh"] = paths(".obj")
        cache_path, entry["cache"] = paths(".pc2")
        placed = [scene_writer.placed_mesh(s.matrix, s.points, s.triangles, metres_per_unit) for s in samples]
        scene_writer.write_obj(mesh_path, *placed[0])
        scene_writer.write_pc2(cache_path, [points for points, _ in placed])
        return entry
    mesh_path, entry["mesh"] = paths(".ply")
    matrices = [sample.matrix for sample in samples]
    if is_static(matrices):
        scene_writer.write_ply(mesh_path, *scene_writer.placed_mesh(samples[0].matrix, samples[0].points,
                                                                    samples[0].triangles, metres_per_unit))
        return entry
    scale = constant_scale(obj, matrices)
    points = [scene_writer.to_softbody([c * s for c, s in zip(p, scale)], metres_per_unit) for p in samples[0].points]
    scene_writer.write_ply(mesh_path, points, samples[0].triangles)
    fps = scene.render.fps / scene.render.fps_base
    keys, euler = [], None
    for index, matrix in enumerate(matrices):
        key, euler = key_at(index / fps, matrix, metres_per_unit, euler)
        keys.append(key)
    entry["keys"] = keys
    entry["interpolation"] = "linear"
    return entry
