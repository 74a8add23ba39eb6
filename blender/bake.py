# softbody.bake: writes the scene, the selected soft-body meshes and the scene's colliders into the bake folder, runs
# `softbody export scene.json --format pc2 -o cache --progress-lines`, and attaches each body's cache to its object.
# Interactive: runs beside Blender with the progress in the status bar, Esc cancels. In background mode
# (blender -b) or from a script (execute): blocking.
import os
import tempfile
import time

import bpy

from . import cache, colliders, scene_writer
from .preferences import program_path
from .runner import ProgramRun


def baked_objects(context):
    """The bodies of a bake: the selected mesh objects whose Soft body (pressure) is on, by name."""
    chosen = [obj for obj in context.selected_objects if obj.type == "MESH" and obj.softbody_pressure.enabled]
    return sorted(chosen, key=lambda obj: obj.name)


def bake_folder(scene):
    folder = scene.softbody_pressure.bake_dir or "//softbody_bake/"
    if folder.startswith("//") and not bpy.data.filepath:  # an unsaved file: no folder to be relative to
        return os.path.join(tempfile.gettempdir(), "softbody_bake", scene_writer.scene_name(scene.name))
    return os.path.abspath(bpy.path.abspath(folder))


def metres_per_unit(scene):
    scale = scene.unit_settings.scale_length
    return scale if scale > 0.0 else 1.0


class SOFTBODY_OT_bake(bpy.types.Operator):
    """Simulate the selected soft bodies with the softbody program and play them through Mesh Cache modifiers"""
    bl_idname = "softbody.bake"
    bl_label = "Bake soft bodies"
    bl_options = {"REGISTER"}

    _run = None
    _timer = None

    @classmethod
    def poll(cls, context):
        return context.scene is not None and cls._run is None

    def _report_and_keep(self, context, level, message):
        context.scene.softbody_pressure.last_message = message
        self.report({level}, message)

    def _start(self, context):
        """Writes the bake's inputs and starts the program; False (with a report) when it cannot."""
        scene = context.scene
        objects = baked_objects(context)
        if not objects:
            self._report_and_keep(context, "ERROR", "Select the mesh objects to bake, with Soft body (pressure) on")
            return False
        program = program_path(context)
        if program is None:
            self._report_and_keep(context, "ERROR", "The softbody program was not found: put it on PATH or set its "
                                  "path in the add-on's preferences")
            return False
        scale = metres_per_unit(scene)
        try:
            run_keys = scene_writer.run_keys(scene, scale)
        except scene_writer.FrameRangeError as error:
            self._report_and_keep(context, "ERROR", str(error))
            return False
        layout = scene_writer.BakeLayout(bake_folder(scene))
        try:
            world = [colliders.collider_entry(scene, obj, lambda extension, i=index: layout.collider_path(i, extension),
                                              scale)
                     for index, obj in enumerate(colliders.collider_objects(scene))]
        except colliders.ColliderError as error:
            self._report_and_keep(context, "ERROR", str(error))
            return False
        bodies, self._meshes = [], []
        for index, obj in enumerate(objects):
            cache.detach(obj)  # an earlier bake: back to the object's own transform and mesh
            points, triangles = scene_writer.world_mesh(obj, scale)
            scene_writer.write_ply(layout.mesh_path(index), points, triangles)
            mesh_file = os.path.relpath(layout.mesh_path(index), layout.folder)
            bodies.append(scene_writer.body_keys(obj.softbody_pressure, mesh_file, scale))
            self._meshes.append((points, triangles))
        scene_writer.write_scene(layout.scene_path, run_keys, bodies, world)
        self._layout, self._names, self._scale = layout, [obj.name for obj in objects], scale
        self._frame_start = scene.frame_start
        args = ["export", layout.scene_path, "--format", "pc2", "-o", layout.cache_folder, "--progress-lines"]
        try:
            SOFTBODY_OT_bake._run = ProgramRun(program, args, layout.folder)
        except OSError as error:
            self._report_and_keep(context, "ERROR", "Could not run %s: %s" % (program, error))
            return False
        return True

    def _finish(self, context):
        run, SOFTBODY_OT_bake._run = SOFTBODY_OT_bake._run, None
        if run.cancelled:
            self._report_and_keep(context, "WARNING", "Bake cancelled: no cache attached")
            return {"CANCELLED"}
        if run.returncode != 0:
            self._report_and_keep(context, "ERROR", "softbody: " + run.error_message())
            return {"CANCELLED"}
        replaced = []
        for index, name in enumerate(self._names):
            obj = bpy.data.objects.get(name)
            if obj is None:  # deleted during the bake
                continue
            if cache.attach(obj, self._layout.cache_path(index), self._layout.written_mesh_path(index),
                            self._meshes[index], self._frame_start, self._scale):
                replaced.append(name)
        context.scene.frame_set(context.scene.frame_current)
        message = "Baked %d soft bodies into %s" % (len(self._names), self._layout.cache_folder)
        if replaced:
            message += "; softbody changed the mesh of %s: it now plays the mesh softbody wrote" % ", ".join(replaced)
        self._report_and_keep(context, "INFO", message)
        return {"FINISHED"}

    def execute(self, context):
        if not self._start(context):
            return {"CANCELLED"}
        run, shown = SOFTBODY_OT_bake._run, -1
        while run.running():
            time.sleep(0.05)
            if run.done != shown and run.total and bpy.app.background:
                shown = run.done
                print("softbody: frame %d/%d" % (run.done, run.total), flush=True)
        run.wait()
        return self._finish(context)

    def invoke(self, context, event):
        if bpy.app.background:
            return self.execute(context)
        if not self._start(context):
            return {"CANCELLED"}
        wm = context.window_manager
        self._timer = wm.event_timer_add(0.1, window=context.window)
        wm.progress_begin(0, 1)
        wm.modal_handler_add(self)
        self._show_progress(context)
        return {"RUNNING_MODAL"}

    def _show_progress(self, context):
        run = SOFTBODY_OT_bake._run
        text = "softbody: frame %d/%d (Esc: cancel)" % (run.done, run.total) if run.total else \
            "softbody: preparing the scene (Esc: cancel)"
        if context.workspace:
            context.workspace.status_text_set(text)
        context.window_manager.progress_update(run.done / run.total if run.total else 0.0)

    def _end_modal(self, context):
        wm = context.window_manager
        wm.event_timer_remove(self._timer)
        wm.progress_end()
        if context.workspace:
            context.workspace.status_text_set(None)

    def modal(self, context, event):
        run = SOFTBODY_OT_bake._run
        if event.type == "ESC":
            run.cancel()
            self._end_modal(context)
            return self._finish(context)
        if event.type == "TIMER":
            if run.running():
                self._show_progress(context)
            else:
                run.wait()
                self._end_modal(context)
                return self._finish(context)
        return {"PASS_THROUGH"}


def register():
    bpy.utils.register_class(SOFTBODY_OT_bake)


def unregister():
    if SOFTBODY_OT_bake._run is not None:
        SOFTBODY_OT_bake._run.cancel()
        SOFTBODY_OT_bake._run = None
    bpy.utils.unregister_class(SOFTBODY_OT_bake)
