# A baked object: its Mesh Cache modifier reads softbody's PC2, which holds world positions in softbody's axes
# (y up, metres). The object's transform is set to a scale of 1/unit scale only (its original transform is kept
# on the object and restored by Clear), and the modifier turns y up into Blender's z up, so
# the evaluated vertices are where softbody put them. Where softbody changed the mesh (repair), the object gets
# the mesh softbody wrote, whose vertices are the cache's; Clear gives back the original mesh.
import bpy
from mathutils import Matrix

from .scene_writer import read_obj, to_blender

MODIFIER_NAME = "softbody"
ORIGINAL_MATRIX = "softbody_original_matrix"
ORIGINAL_MESH = "softbody_original_mesh"
SAME_POINT_M = 1e-6  # what the program's OBJ (9 significant digits) may differ from the doubles written to it


def is_baked(obj):
    return ORIGINAL_MATRIX in obj


def mesh_is_unchanged(written, written_faces, points, triangles):
    """Whether the program's mesh has the same vertices, in the same order, and the same triangles (either winding)
    as the one written for it."""
    if len(written) != len(points) or len(written_faces) != len(triangles):
        return False
    if not all(abs(a - b) <= SAME_POINT_M * max(1.0, abs(b)) for p, q in zip(written, points) for a, b in zip(p, q)):
        return False
    return sorted(tuple(sorted(f)) for f in written_faces) == sorted(tuple(sorted(t)) for t in triangles)


def mesh_from_obj(name, path, metres_per_unit):
    """A Blender mesh of the program's OBJ, in Blender's axes (its vertex order kept)."""
    points, faces = read_obj(path)
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([to_blender(p, metres_per_unit) for p in points], [], faces)
    mesh.update()
    return mesh


def attach(obj, pc2_path, written_mesh_path, mesh_written, frame_start, metres_per_unit):
    """Turns obj into a player of the cache. Returns True when its mesh had to be replaced by the program's."""
    obj[ORIGINAL_MATRIX] = [value for row in obj.matrix_world for value in row]
    written, written_faces = read_obj(written_mesh_path)
    replaced = not mesh_is_unchanged(written, written_faces, *mesh_written)
    if replaced:
        original = obj.data
        obj[ORIGINAL_MESH] = original.name
        original.use_fake_user = True  # kept for Clear while no object uses it
        obj.data = mesh_from_obj(original.name + ".softbody", written_mesh_path, metres_per_unit)
        for material in original.materials:
            obj.data.materials.append(material)
    obj.matrix_world = Matrix.Scale(1.0 / metres_per_unit, 4)
    modifier = obj.modifiers.new(MODIFIER_NAME, "MESH_CACHE")
    modifier.cache_format = "PC2"
    modifier.filepath = bpy.path.relpath(pc2_path) if bpy.data.filepath else pc2_path
    modifier.deform_mode = "OVERWRITE"
    # (x, y, z) of the cache to (x, -z, y): softbody's y up stands up in Blender's z. The modifier's axes name the
    # turn from the other side (Forward -Z, Up +Y, as an OBJ importer would say it, gives the inverse turn): this
    # pair was found by trying all of them against the object's own vertices (tests/blender/addon_check.py).
    modifier.forward_axis = "POS_Z"
    modifier.up_axis = "NEG_Y"
    modifier.time_mode = "FRAME"
    modifier.play_mode = "SCENE"
    modifier.frame_start = float(frame_start)  # scene frame F reads the cache's frame F - frame_start
    modifier.frame_scale = 1.0
    with bpy.context.temp_override(object=obj):
        bpy.ops.object.modifier_move_to_index(modifier=modifier.name, index=0)
    return replaced


def detach(obj):
    """Removes the cache: the modifier, and gives back the object's transform and original mesh."""
    for modifier in [m for m in obj.modifiers if m.type == "MESH_CACHE" and m.name.startswith(MODIFIER_NAME)]:
        obj.modifiers.remove(modifier)
    if ORIGINAL_MESH in obj:
        original = bpy.data.meshes.get(obj[ORIGINAL_MESH])
        if original is not None:
            baked = obj.data
            obj.data = original
            original.use_fake_user = False
            if baked.users == 0:
                bpy.data.meshes.remove(baked)
        del obj[ORIGINAL_MESH]
    if ORIGINAL_MATRIX in obj:
        values = list(obj[ORIGINAL_MATRIX])
        obj.matrix_world = Matrix([values[0:4], values[4:8], values[8:12], values[12:16]])
        del obj[ORIGINAL_MATRIX]
