# The add-on's preferences: where the softbody program is (empty: found on PATH).
import shutil

import bpy

ADDON_NAME = __package__


class SoftbodyPreferences(bpy.types.AddonPreferences):
    bl_idname = ADDON_NAME

    program: bpy.props.StringProperty(
        name="softbody program",
        description="Path of the softbody program; empty: the one found on PATH",
        subtype="FILE_PATH",
        default="",
    )

    def draw(self, context):
        self.layout.prop(self, "program")
        found = program_path(context)
        self.layout.label(text="Using: " + found if found else "Not found: set the path or put softbody on PATH",
                          icon="NONE" if found else "ERROR")


def program_path(context):
    """The softbody program to run: the preference's path, else softbody on PATH; None when neither exists."""
    addon = context.preferences.addons.get(ADDON_NAME)
    chosen = bpy.path.abspath(addon.preferences.program) if addon and addon.preferences.program else ""
    if chosen:
        return shutil.which(chosen)
    return shutil.which("softbody")


def register():
    bpy.utils.register_class(SoftbodyPreferences)


def unregister():
    bpy.utils.unregister_class(SoftbodyPreferences)
