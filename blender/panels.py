# The "Soft body (pressure)" panels: on a mesh object (Properties > Physics) its body's settings, on the scene
# (Properties > Scene) the run's settings, with Bake and Clear on both.
import bpy

from . import cache


def draw_bake_buttons(layout, scene):
    row = layout.row(align=True)
    row.operator("softbody.bake", icon="PHYSICS")
    row.operator("softbody.clear", icon="TRASH")
    if scene.softbody_pressure.last_message:
        layout.label(text=scene.softbody_pressure.last_message)


class MeshPhysicsPanel:
    """Where the object panels go: Properties > Physics, on a mesh object."""
    bl_space_type = "PROPERTIES"
    bl_region_type = "WINDOW"
    bl_context = "physics"

    @classmethod
    def poll(cls, context):
        return context.object is not None and context.object.type == "MESH"


class SOFTBODY_PT_object(MeshPhysicsPanel, bpy.types.Panel):
    bl_label = "Soft body (pressure)"
    bl_idname = "SOFTBODY_PT_object"

    def draw_header(self, context):
        self.layout.prop(context.object.softbody_pressure, "enabled", text="")

    def draw(self, context):
        settings = context.object.softbody_pressure
        layout = self.layout
        layout.use_property_split = True
        layout.active = settings.enabled
        layout.prop(settings, "mass")
        layout.prop(settings, "stiffness_mode")
        if settings.stiffness_mode == "YOUNGS":
            layout.prop(settings, "youngs")
            layout.prop(settings, "thickness")
        elif settings.stiffness_mode == "FREQUENCY":
            layout.prop(settings, "frequency")
        else:
            layout.prop(settings, "stiffness")
        layout.prop(settings, "damping_mode")
        layout.prop(settings, "damping_ratio" if settings.damping_mode == "RATIO" else "damping")
        layout.prop(settings, "pressure_mode")
        if settings.pressure_mode == "INFLATION":
            layout.prop(settings, "inflation")
            layout.prop(settings, "inflation_start")
        else:
            layout.prop(settings, "pressure")
        layout.prop(settings, "bending_mode")
        layout.prop(settings, "bending_ratio" if settings.bending_mode == "RATIO" else "bending")
        layout.prop(settings, "resolution_mode")
        if settings.resolution_mode == "VERTICES":
            layout.prop(settings, "resolution")
        elif settings.resolution_mode == "EDGE_LENGTH":
            layout.prop(settings, "edge_length")
        layout.prop(settings, "repair")
        layout.prop(settings, "self_collision")
        if cache.is_baked(context.object):
            layout.label(text="Baked: plays softbody's cache", icon="CHECKMARK")
        draw_bake_buttons(layout, context.scene)


class SOFTBODY_PT_collider(MeshPhysicsPanel, bpy.types.Panel):
    bl_label = "Collider (softbody)"
    bl_idname = "SOFTBODY_PT_collider"

    def draw_header(self, context):
        self.layout.prop(context.object.softbody_pressure, "collider", text="")

    def draw(self, context):
        settings = context.object.softbody_pressure
        layout = self.layout
        layout.use_property_split = True
        layout.active = settings.collider
        layout.prop(settings, "collider_thickness")
        layout.label(text="Moves with the object's animation; contact as the scene's floor")


class SOFTBODY_PT_scene(bpy.types.Panel):
    bl_label = "Soft body (pressure)"
    bl_idname = "SOFTBODY_PT_scene"
    bl_space_type = "PROPERTIES"
    bl_region_type = "WINDOW"
    bl_context = "scene"

    def draw(self, context):
        scene = context.scene
        settings = scene.softbody_pressure
        layout = self.layout
        layout.use_property_split = True
        layout.prop(settings, "integrator")
        layout.prop(settings, "dt_auto")
        if not settings.dt_auto:
            layout.prop(settings, "dt")
        frames = scene.frame_end - scene.frame_start
        layout.label(text="Frames %d..%d at %g fps: %g s (the scene's frame range and rate)"
                     % (scene.frame_start, scene.frame_end, scene.render.fps / scene.render.fps_base,
                        frames * scene.render.fps_base / scene.render.fps))
        layout.prop(scene, "use_gravity")
        if scene.use_gravity:
            layout.prop(scene, "gravity")
        layout.prop(settings, "floor")
        if settings.floor:
            layout.prop(settings, "floor_height")
            layout.prop(settings, "floor_contact")
            if settings.floor_contact != "paper":
                layout.prop(settings, "floor_restitution")
                layout.prop(settings, "floor_friction")
        layout.prop(settings, "bake_dir")
        draw_bake_buttons(layout, scene)


_classes = (SOFTBODY_PT_object, SOFTBODY_PT_collider, SOFTBODY_PT_scene)


def register():
    for cls in _classes:
        bpy.utils.register_class(cls)


def unregister():
    for cls in reversed(_classes):
        bpy.utils.unregister_class(cls)
