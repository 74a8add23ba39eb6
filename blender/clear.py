# softbody.clear: removes the caches of the selected objects (or of every baked object when none of the selected
# is baked): their Mesh Cache modifiers, and gives back their transforms and original meshes.
import bpy

from . import cache


class SOFTBODY_OT_clear(bpy.types.Operator):
    """Remove the softbody caches: the Mesh Cache modifiers, and the objects' own transforms and meshes back"""
    bl_idname = "softbody.clear"
    bl_label = "Clear soft-body caches"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        chosen = [obj for obj in context.selected_objects if cache.is_baked(obj)]
        if not chosen:
            chosen = [obj for obj in context.scene.objects if cache.is_baked(obj)]
        for obj in chosen:
            cache.detach(obj)
        context.scene.frame_set(context.scene.frame_current)
        message = "Cleared the caches of %d objects" % len(chosen)
        context.scene.softbody_pressure.last_message = message
        self.report({"INFO"}, message)
        return {"FINISHED"}


def register():
    bpy.utils.register_class(SOFTBODY_OT_clear)


def unregister():
    bpy.utils.unregister_class(SOFTBODY_OT_clear)
