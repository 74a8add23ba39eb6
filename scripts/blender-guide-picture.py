# The guide's picture of the Blender add-on (docs/guide/images/blender_bake.png): installs the add-on from its zip
# into a headless Blender, bakes two soft balls dropped on the floor and renders one frame of the baked scene with
# Cycles on the CPU, at the frame where the soft one is most squashed.
#   BLENDER_USER_SCRIPTS=/tmp/addons blender -b --factory-startup --python-exit-code 1 \
#     --python scripts/blender-guide-picture.py -- build/blender/softbody_blender.zip build/softbody OUT.png
import math
import os
import sys
import tempfile

import bpy



def top(obj):
    """The highest z of the object's evaluated vertices."""
    evaluated = obj.evaluated_get(bpy.context.evaluated_depsgraph_get())
    mesh = evaluated.to_mesh()
    z = max((obj.matrix_world @ v.co).z for v in mesh.vertices)
    evaluated.to_mesh_clear()
    return z


def most_squashed_frame(scene, obj):
    """The scene frame where obj's top is lowest: the soft ball squashed on the floor."""
    heights = []
    for frame in range(scene.frame_start, scene.frame_end + 1):
        scene.frame_set(frame)
        heights.append((top(obj), frame))
    return min(heights)[1]


def main():
    zip_path, program, out_png = sys.argv[sys.argv.index("--") + 1:]
    bpy.ops.preferences.addon_install(filepath=os.path.abspath(zip_path), overwrite=True)
    bpy.ops.preferences.addon_enable(module="softbody_blender")
    bpy.context.preferences.addons["softbody_blender"].preferences.program = os.path.abspath(program)
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)
    scene = bpy.context.scene
    scene.frame_start, scene.frame_end, scene.render.fps = 1, 31, 30
    scene.softbody_pressure.bake_dir = tempfile.mkdtemp(prefix="softbody_picture_")
    scene.softbody_pressure.floor = True

    balls = []
    for name, location, colour, stiffness in (("Soft", (-0.7, 0.0, 1.2), (0.8, 0.12, 0.07, 1), 150.0),
                                              ("Firm", (0.7, 0.0, 1.5), (0.1, 0.35, 0.8, 1), 3000.0)):
        bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=4, radius=0.5, location=location)
        ball = bpy.context.active_object
        ball.name = name
        bpy.ops.object.shade_smooth()
        material = bpy.data.materials.new(name)
        material.diffuse_color = colour
        material.use_nodes = True
        material.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = colour
        ball.data.materials.append(material)
        ball.softbody_pressure.enabled = True
        ball.softbody_pressure.stiffness = stiffness
        ball.softbody_pressure.damping_mode = "RATIO"
        ball.softbody_pressure.damping_ratio = 0.1
        balls.append(ball)
    bpy.ops.object.select_all(action="DESELECT")
    for ball in balls:
        ball.select_set(True)
    if bpy.ops.softbody.bake() != {"FINISHED"}:
        raise SystemExit("the bake failed: " + scene.softbody_pressure.last_message)

    bpy.ops.mesh.primitive_plane_add(size=8, location=(0, 0, 0))
    bpy.ops.object.camera_add(location=(0.0, -5.2, 1.6), rotation=(math.radians(82), 0, 0))
    scene.camera = bpy.context.active_object
    bpy.ops.object.light_add(type="SUN", rotation=(math.radians(40), math.radians(20), math.radians(30)))
    bpy.context.active_object.data.energy = 4.0
    scene.world = scene.world or bpy.data.worlds.new("World")
    scene.world.use_nodes = True
    scene.world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.45, 0.55, 0.7, 1)
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = 32
    scene.cycles.use_denoising = False  # Debian's Blender is built without OpenImageDenoise
    scene.render.resolution_x, scene.render.resolution_y = 640, 360
    scene.render.image_settings.file_format = "PNG"
    scene.render.filepath = os.path.abspath(out_png)
    frame = most_squashed_frame(scene, balls[0])
    scene.frame_set(frame)
    bpy.ops.render.render(write_still=True)
    print("wrote %s (scene frame %d: %s)" % (out_png, frame, scene.softbody_pressure.last_message))


main()
