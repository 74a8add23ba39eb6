# Runs inside Blender (blender -b --factory-startup --python-exit-code 1 --python addon_check.py -- ZIP SOFTBODY DIR):
# installs the add-on from its zip, bakes an icosphere dropped on the floor (moved, turned and scaled, so that the
# object's transform and the axes matter), and checks the evaluated vertices against the program's own export of
# the same scene file; then Clear, Cancel (the runner's), and a bad setting's error report. Then a mesh that
# softbody changes (an icosphere with a hole, repaired): the object must play the mesh softbody wrote, and Clear give
# its own mesh back. The panels are drawn into a stand-in layout (no window in background mode).
import itertools
import json
import os
import subprocess
import sys
import time

import bpy

TOLERANCE_M = 1e-5  # the cache and the OBJ hold float32 and 9 digits of the same doubles: 1e-7 m apart here
FRAME = 10          # softbody's frame checked
START = 5           # the scene's start frame: softbody's frame 0


def fail(message):
    raise SystemExit("FAIL: " + message)


def evaluated_world(obj):
    depsgraph = bpy.context.evaluated_depsgraph_get()
    evaluated = obj.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    points = [tuple(obj.matrix_world @ v.co) for v in mesh.vertices]
    evaluated.to_mesh_clear()
    return points


def max_difference(a, b):
    if len(a) != len(b):
        fail("%d vertices against %d" % (len(a), len(b)))
    return max(abs(p - q) for u, v in zip(a, b) for p, q in zip(u, v))


def read_obj_vertices(path):
    with open(path) as f:
        return [tuple(float(v) for v in line.split()[1:4]) for line in f if line.startswith("v ")]


def y_up_to_z_up(points):
    return [(x, -z, y) for x, y, z in points]


def install(zip_path, program):
    bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
    bpy.ops.preferences.addon_enable(module="softbody_blender")
    bpy.context.preferences.addons["softbody_blender"].preferences.program = program
    if not hasattr(bpy.ops.softbody, "bake"):
        fail("the add-on did not register softbody.bake")


def make_scene(bake_dir):
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)
    scene = bpy.context.scene
    scene.frame_start, scene.frame_end = START, START + 20
    scene.render.fps, scene.render.fps_base = 30, 1.0
    settings = scene.softbody_pressure
    settings.bake_dir = bake_dir
    settings.floor, settings.floor_height = True, 0.0
    bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=2, radius=0.5, location=(0.3, -0.2, 1.0),
                                          rotation=(0.3, 0.2, 0.1), scale=(1.1, 1.1, 1.1))
    ball = bpy.context.active_object
    ball.softbody_pressure.enabled = True
    ball.softbody_pressure.mass = 1.0
    ball.softbody_pressure.damping_mode = "RATIO"
    ball.softbody_pressure.damping_ratio = 0.2
    ball.softbody_pressure.self_collision = True
    return ball


def bake():
    result = bpy.ops.softbody.bake()
    if result != {"FINISHED"}:
        fail("softbody.bake returned %s: %s" % (result, bpy.context.scene.softbody_pressure.last_message))
    print("blender addon: bake: " + bpy.context.scene.softbody_pressure.last_message)


def check_scene_keys(bake_dir):
    # The panel's switches reach the scene file the bake wrote (and so the CLI, which check_against_cli runs on it).
    with open(os.path.join(bake_dir, "scene.json")) as f:
        body = json.load(f)["bodies"][0]
    if body.get("self_collision") is not True:
        fail("the bake's scene file lacks the body's \"self_collision\": true: %s" % body)
    print("blender addon: the scene file carries the body's self_collision switch")


def check_integrators(program):
    # The panel offers exactly the integrators the program takes (it offered "implicit" after the program dropped it).
    offered = [item.identifier for item in
               bpy.context.scene.softbody_pressure.bl_rna.properties["integrator"].enum_items]
    schema = json.loads(subprocess.run([program, "schema"], check=True, capture_output=True, text=True).stdout)
    taken = schema["properties"]["solver"]["properties"]["integrator"]["enum"]
    if offered != taken:
        fail("the panel offers the integrators %s, the program takes %s" % (offered, taken))
    print("blender addon: the panel offers the program's integrators: %s" % ", ".join(offered))


def check_start_frame(ball, before):
    cache = [m for m in ball.modifiers if m.type == "MESH_CACHE"]
    if len(cache) != 1:
        fail("expected one Mesh Cache modifier after the bake, got %d" % len(cache))
    bpy.context.scene.frame_set(START)
    at_start = max_difference(evaluated_world(ball), before)
    print("blender addon: scene frame %d (softbody's frame 0): max |evaluated - the object before| = %.3g m"
          % (START, at_start))
    if at_start > TOLERANCE_M:
        fail("the start frame does not show the object where it was")


def check_against_cli(ball, program, bake_dir, scratch, before):
    # The program's own export of the bake's scene file, frame by frame as OBJ.
    cli_dir = os.path.join(scratch, "cli_obj_" + ball.name)
    subprocess.run([program, "export", os.path.join(bake_dir, "scene.json"), "--format", "obj", "-o", cli_dir],
                   check=True, stdout=subprocess.DEVNULL)
    expected = y_up_to_z_up(read_obj_vertices(os.path.join(cli_dir, "frame_%04d.obj" % FRAME)))
    bpy.context.scene.frame_set(START + FRAME)
    got = evaluated_world(ball)
    difference = max_difference(got, expected)
    if before is None:
        before = y_up_to_z_up(read_obj_vertices(os.path.join(cli_dir, "frame_0000.obj")))
    fallen = max(p[2] for p in before) - max(p[2] for p in got)
    lowest = min(p[2] for p in got)
    print("blender addon: scene frame %d (softbody's frame %d): %d vertices, max |evaluated - CLI export| = %.3g m "
          "(top fell %.3f m, lowest z %.4f m)" % (START + FRAME, FRAME, len(got), difference, fallen, lowest))
    if difference > TOLERANCE_M:
        fail("the baked object differs from the CLI's export by %g m" % difference)
    if fallen < 0.1:
        fail("the ball did not fall: the cache does not play")


def check_repaired_mesh(program, bake_dir, scratch):
    bpy.ops.object.select_all(action="DESELECT")
    bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=2, radius=0.4, location=(-0.8, 0.5, 0.9))
    holed = bpy.context.active_object
    holed.name = "Holed"
    bpy.ops.object.mode_set(mode="EDIT")
    bpy.ops.mesh.select_all(action="DESELECT")
    bpy.ops.object.mode_set(mode="OBJECT")
    holed.data.vertices[0].select = True
    bpy.ops.object.mode_set(mode="EDIT")
    bpy.ops.mesh.delete(type="VERT")  # a vertex and its faces: a hole that repair fills
    bpy.ops.object.mode_set(mode="OBJECT")
    own_mesh, own_vertices = holed.data.name, len(holed.data.vertices)
    holed.softbody_pressure.enabled = True
    holed.softbody_pressure.repair = True
    bake()
    if holed.data.name == own_mesh:
        fail("softbody repaired the mesh but the object kept its own mesh: "
             + bpy.context.scene.softbody_pressure.last_message)
    print("blender addon: repaired: the object plays the mesh softbody wrote (%d vertices, %d faces; its own: %d "
          "vertices)" % (len(holed.data.vertices), len(holed.data.polygons), own_vertices))
    check_against_cli(holed, program, bake_dir, scratch, None)
    bpy.ops.softbody.clear()
    if holed.data.name != own_mesh or len(holed.data.vertices) != own_vertices:
        fail("Clear did not give the repaired object its own mesh back")


def check_cancel(program, bake_dir):
    """Cancel as Esc does it (the modal bake needs a window): the add-on's runner stops a long run within seconds."""
    from softbody_blender.runner import ProgramRun
    run = ProgramRun(program, ["export", os.path.join(bake_dir, "scene.json"), "--set", "duration=600", "--format",
                               "pc2", "-o", os.path.join(bake_dir, "cancelled"), "--progress-lines"], bake_dir)
    deadline = time.time() + 60
    while run.done < 3 and run.running() and time.time() < deadline:
        time.sleep(0.05)
    started = time.time()
    run.cancel()
    print("blender addon: cancel at frame %d/%d: the program ended in %.3f s (status %s)"
          % (run.done, run.total, time.time() - started, run.returncode))
    if run.done < 3 or run.returncode == 0 or time.time() - started > 5.0:
        fail("cancel did not stop the program: %s" % run.error_message())


class CheckingLayout:
    """Stands in for a panel's layout in background mode (no window draws the panels): every property a panel
    shows must exist, every operator it offers must be registered."""

    def __init__(self):
        self.shown = []

    def prop(self, data, name, **_):
        if name not in data.bl_rna.properties:
            fail("a panel shows %s.%s, which does not exist" % (data.bl_rna.identifier, name))
        self.shown.append(name)

    def operator(self, name, **_):
        group, operator = name.split(".")
        if not hasattr(getattr(bpy.ops, group), operator):
            fail("a panel offers the operator %s, which is not registered" % name)

    def row(self, **_):
        return self

    def label(self, **_):
        pass


def check_panels(ball):
    """Draws both panels in every mode of their choices."""
    settings, scene_settings, shown = ball.softbody_pressure, bpy.context.scene.softbody_pressure, set()
    modes = [[(group, name, item.identifier) for item in group.bl_rna.properties[name].enum_items]
             for group, name in ((settings, "stiffness_mode"), (settings, "damping_mode"), (settings, "pressure_mode"),
                                 (settings, "bending_mode"), (settings, "resolution_mode"),
                                 (scene_settings, "floor_contact"))]
    for choice in itertools.product(*modes):
        for group, name, value in choice:
            setattr(group, name, value)
        for panel in (bpy.types.SOFTBODY_PT_object, bpy.types.SOFTBODY_PT_collider, bpy.types.SOFTBODY_PT_scene):
            layout = CheckingLayout()
            drawn = type("Panel", (), {"layout": layout})()
            panel.draw(drawn, bpy.context)
            if hasattr(panel, "draw_header"):
                panel.draw_header(drawn, bpy.context)
            shown.update(layout.shown)
    unshown = {"rna_type", "name", "last_message"}  # name: every property group's; last_message: a label
    missing = [name for group in (settings, scene_settings)
               for name in group.bl_rna.properties.keys() if name not in shown and name not in unshown]
    print("blender addon: panels: %d settings shown in %d combinations of modes" % (len(shown), len(list(
        itertools.product(*modes)))))
    if missing:
        fail("the panels never show %s" % ", ".join(missing))
    for group, name, value in (m[0] for m in modes):
        setattr(group, name, value)


def check_clear(ball, before, matrix_before):
    if bpy.ops.softbody.clear() != {"FINISHED"}:
        fail("softbody.clear did not finish")
    if any(m.type == "MESH_CACHE" for m in ball.modifiers):
        fail("a Mesh Cache modifier is left after Clear")
    matrix_difference = max(abs(a - b) for r, s in zip(ball.matrix_world, matrix_before) for a, b in zip(r, s))
    bpy.context.scene.frame_set(START + FRAME)
    difference = max_difference(evaluated_world(ball), before)
    print("blender addon: clear: no Mesh Cache modifier, transform back (%.3g), vertices back (%.3g m)"
          % (matrix_difference, difference))
    if matrix_difference > 1e-6 or difference > TOLERANCE_M:
        fail("Clear did not give the object back as it was")


def bake_error(what):
    """The error report of a bake that must fail (`what`: the setting that makes it fail)."""
    try:
        bpy.ops.softbody.bake()
    except RuntimeError as error:
        return str(error)
    fail("a bake with %s did not report an error" % what)


def check_error_report(ball):
    ball.softbody_pressure.mass = 0.0
    message = bake_error("mass 0")
    print("blender addon: mass 0: the report is %r" % message.strip())
    if "bodies.0.mass" not in message or "> 0" not in message:
        fail("the error report does not carry the program's message")
    if any(m.type == "MESH_CACHE" for m in ball.modifiers):
        fail("a failed bake attached a cache")


def nearest_distances(points, others):
    """For each point, the distance to the nearest of others: the largest [m]."""
    return max(min(max(abs(p - q) for p, q in zip(a, b)) for b in others) for a in points)


def check_colliders(program, bake_dir, scratch):
    """A static block, an animated paddle (moved and turned) and a sheet raised by a shape key, ticked as colliders:
    the scene file carries the three (the paddle with one key per frame, the sheet as a point cache), softbody's own
    export of the paddle and the sheet at a frame is where Blender shows them, and a ball dropped on the block comes
    to rest on it, not on the floor below."""
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)
    scene = bpy.context.scene
    bpy.ops.mesh.primitive_cube_add(size=1.0, location=(0.0, 0.0, 0.25), scale=(1.2, 1.2, 0.5))
    block = bpy.context.active_object
    block.name = "Block"
    block.softbody_pressure.collider = True
    bpy.ops.mesh.primitive_cube_add(size=0.2, location=(1.5, 0.0, 0.4), scale=(1.0, 2.0, 1.0))
    paddle = bpy.context.active_object
    paddle.name = "Paddle"
    paddle.softbody_pressure.collider = True
    for frame, location, turn in ((START, (1.5, 0.0, 0.4), 0.0), (START + 20, (1.5, 1.0, 0.6), 1.2)):
        scene.frame_set(frame)
        paddle.location, paddle.rotation_euler = location, (0.3 * turn, 0.0, turn)
        paddle.keyframe_insert("location")
        paddle.keyframe_insert("rotation_euler")
    bpy.ops.mesh.primitive_grid_add(x_subdivisions=4, y_subdivisions=4, size=1.0, location=(-1.5, 0.0, 0.2))
    sheet = bpy.context.active_object
    sheet.name = "Sheet"
    sheet.softbody_pressure.collider = True
    sheet.shape_key_add(name="Basis")
    raised = sheet.shape_key_add(name="Raised")
    for i, point in enumerate(raised.data):
        point.co.z += 0.3 * (1.0 - abs(sheet.data.vertices[i].co.x))  # a ridge along y rises out of the sheet
    for frame, value in ((START, 0.0), (START + 20, 1.0)):
        raised.value = value
        raised.keyframe_insert("value", frame=frame)
    scene.frame_set(START)
    bpy.ops.object.select_all(action="DESELECT")
    bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=2, radius=0.25, location=(0.0, 0.0, 1.0))
    ball = bpy.context.active_object
    ball.softbody_pressure.enabled = True
    ball.softbody_pressure.damping_mode = "RATIO"
    ball.softbody_pressure.damping_ratio = 0.5
    bake()
    with open(os.path.join(bake_dir, "scene.json")) as f:
        written = json.load(f).get("colliders", [])
    if len(written) != 3 or "keys" in written[0] or len(written[1].get("keys", [])) != 21 or \
            not written[2].get("cache", "").endswith(".pc2") or not written[2]["mesh"].endswith(".obj"):
        fail("expected the static Block, the Paddle with 21 keys and the Sheet's point cache, got %s" % written)
    cli_dir = os.path.join(scratch, "cli_colliders")
    subprocess.run([program, "export", os.path.join(bake_dir, "scene.json"), "--format", "obj", "-o", cli_dir],
                   check=True, stdout=subprocess.DEVNULL)
    scene.frame_set(START + FRAME)
    shown = evaluated_world(paddle)
    exported = y_up_to_z_up(read_obj_vertices(os.path.join(cli_dir, "collider_1_%04d.obj" % FRAME)))
    paddle_error = nearest_distances(shown, exported)
    sheet_exported = read_obj_vertices(os.path.join(cli_dir, "collider_2_%04d.obj" % FRAME))
    sheet_error = nearest_distances(evaluated_world(sheet), y_up_to_z_up(sheet_exported))
    block_error = nearest_distances(evaluated_world(block),
                                    y_up_to_z_up(read_obj_vertices(os.path.join(cli_dir, "collider_0.obj"))))
    scene.frame_set(START + 20)
    lowest = min(p[2] for p in evaluated_world(ball))
    print("blender addon: colliders: at frame %d the paddle is %.3g m from softbody's export of it, the raised sheet "
          "%.3g m, the block %.3g m; the ball's lowest point at the end z = %.4f m (the block's top: 0.5 m)"
          % (FRAME, paddle_error, sheet_error, block_error, lowest))
    if max(paddle_error, sheet_error, block_error) > TOLERANCE_M:
        fail("softbody's colliders are not where Blender shows them")
    if lowest < 0.45:
        fail("the ball did not land on the block collider")
    paddle.softbody_pressure.enabled = True
    message = bake_error("an object both body and collider")
    if "both a soft body and a collider" not in message:
        fail("the error report does not say what is wrong: %r" % message)


def main():
    zip_path, program, scratch = sys.argv[sys.argv.index("--") + 1:]
    print("blender %s" % bpy.app.version_string)
    install(zip_path, program)
    bake_dir = os.path.join(scratch, "bake")
    ball = make_scene(bake_dir)
    check_panels(ball)
    check_integrators(program)
    ball.softbody_pressure.damping_mode = "RATIO"
    bpy.context.view_layer.update()
    before = evaluated_world(ball)
    matrix_before = [list(row) for row in ball.matrix_world]
    bake()
    check_scene_keys(bake_dir)
    check_start_frame(ball, before)
    check_against_cli(ball, program, bake_dir, scratch, before)
    check_clear(ball, before, matrix_before)
    check_cancel(program, bake_dir)
    check_error_report(ball)
    ball.softbody_pressure.enabled = False
    check_repaired_mesh(program, bake_dir, scratch)
    check_colliders(program, bake_dir, scratch)
    print("blender addon check: OK")


main()
