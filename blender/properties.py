# The settings the panels show: per mesh object (its body's keys) and per scene (the run's keys). Each maps to one
# key of softbody's scene file (docs/guide/scene-keys.md); scene_writer.py does the mapping.
import bpy
from bpy.props import (BoolProperty, EnumProperty, FloatProperty, IntProperty, PointerProperty,
                       StringProperty)


class SoftbodyObjectSettings(bpy.types.PropertyGroup):
    enabled: BoolProperty(name="Soft body", description="Bake this mesh as a softbody pressure body", default=False)
    mass: FloatProperty(name="Mass", description="The whole body's mass (bodies[].mass)", unit="MASS",
                        default=1.0, min=0.0, soft_min=1e-3)
    stiffness_mode: EnumProperty(name="Stiffness", items=(
        ("SPRING", "Spring constant", "Each edge spring's k in N/m (bodies[].stiffness)"),
        ("YOUNGS", "Young's modulus", "k from a shell material: Young's modulus and thickness (stiffness.youngs)"),
        ("FREQUENCY", "Frequency", "k from the breathing mode's frequency (stiffness.frequency)"),
    ), default="SPRING")
    stiffness: FloatProperty(name="k (N/m)", description="Each edge spring's constant", default=1000.0, min=0.0)
    youngs: FloatProperty(name="Young's modulus (Pa)", default=1e6, min=0.0, soft_min=1.0)
    thickness: FloatProperty(name="Thickness", description="Shell thickness", unit="LENGTH", default=0.001, min=0.0,
                             soft_min=1e-6, precision=4)
    frequency: FloatProperty(name="Frequency (Hz)", description="The breathing mode's frequency", default=5.0,
                             min=0.0, soft_min=0.01)
    damping_mode: EnumProperty(name="Damping", items=(
        ("COEFFICIENT", "Coefficient", "Each spring's damper c in N·s/m (bodies[].damping)"),
        ("RATIO", "Ratio", "Damping ratio ζ of the breathing mode, 1 = critical (damping.ratio)"),
    ), default="COEFFICIENT")
    damping: FloatProperty(name="c (N·s/m)", default=1.0, min=0.0)
    damping_ratio: FloatProperty(name="ζ", default=0.1, min=0.0)
    pressure_mode: EnumProperty(name="Pressure", items=(
        ("NRT", "nRT", "nRT of the enclosed gas in J, 0 = no gas (bodies[].pressure)"),
        ("INFLATION", "Inflation", "The springs are stretched by this fraction at equilibrium (pressure.inflation)"),
    ), default="NRT")
    pressure: FloatProperty(name="nRT (J)", default=50.0, min=0.0)
    inflation: FloatProperty(name="Inflation", default=0.1, min=0.0, max=0.99)
    inflation_start: EnumProperty(name="Start", items=(
        ("equilibrium", "Equilibrium", "The mesh is the equilibrium shape (no pop)"),
        ("rest", "Rest", "The mesh is the springs' rest shape and the gas inflates it"),
    ), default="equilibrium")
    bending_mode: EnumProperty(name="Bending", items=(
        ("STIFFNESS", "Stiffness", "k_b of the bending links in N/m, 0 = none (bodies[].bending)"),
        ("RATIO", "Ratio", "k_b relative to the edge springs (bending.ratio)"),
    ), default="STIFFNESS")
    bending: FloatProperty(name="k_b (N/m)", default=0.0, min=0.0)
    bending_ratio: FloatProperty(name="Ratio", default=0.1, min=0.0)
    resolution_mode: EnumProperty(name="Resolution", items=(
        ("MESH", "The mesh", "Simulate the mesh as it is"),
        ("VERTICES", "Vertices", "Simulate a remesh (proxy) of about this many vertices; the mesh follows it"),
        ("EDGE_LENGTH", "Edge length", "Simulate a remesh (proxy) with edges of about this length"),
    ), default="MESH")
    resolution: IntProperty(name="Proxy vertices", default=500, min=20, max=1000000)
    edge_length: FloatProperty(name="Proxy edge length", unit="LENGTH", default=0.1, min=0.0, soft_min=1e-4)
    repair: BoolProperty(name="Repair mesh", description="Repair the mesh before it is checked (bodies[].repair); "
                         "the cache is then attached to the repaired mesh", default=False)
    self_collision: BoolProperty(name="Self-collision", description="Its vertices also collide with its own triangles, "
                                 "so that it folds onto itself instead of through itself (bodies[].self_collision)",
                                 default=False)
    collider: BoolProperty(name="Collider", description="A collider: moves the soft bodies and is not moved by them, "
                           "following the object's animated transform (colliders[], shape mesh)", default=False)
    collider_thickness: FloatProperty(name="Thickness", description="An open mesh's thickness (colliders[].thickness, "
                                      "0: softbody's default, 1 cm); a closed mesh is a solid", unit="LENGTH",
                                      default=0.0, min=0.0, precision=4)


class SoftbodySceneSettings(bpy.types.PropertyGroup):
    integrator: EnumProperty(name="Integrator", items=[
        (name, name, "solver.integrator = " + name)
        for name in ("euler", "symplectic", "verlet", "rk4", "rk45", "xpbd", "vbd")],
        default="euler")
    dt_auto: BoolProperty(name="Automatic step", description="solver.dt = \"auto\": from the stable-step estimate",
                          default=False)
    dt: FloatProperty(name="Step (s)", description="Requested time step (solver.dt)", default=1e-4, min=1e-9,
                      precision=6, step=0.001)
    floor: BoolProperty(name="Floor", description="A ground plane at this height (floor)", default=True)
    floor_height: FloatProperty(name="Height", unit="LENGTH", default=0.0)
    floor_contact: EnumProperty(name="Contact", items=(
        ("paper", "Paper", "A vertex below is reflected and put back on the floor"),
        ("friction", "Friction", "Restitution and Coulomb friction impulses"),
        ("smooth", "Smooth", "A penalty spring-damper force with regularised friction"),
    ), default="paper")
    floor_restitution: FloatProperty(name="Restitution", default=0.5, min=0.0, max=1.0)
    floor_friction: FloatProperty(name="Friction", default=0.5, min=0.0)
    bake_dir: StringProperty(name="Bake folder", description="Where the scene file, the meshes and the caches go",
                             subtype="DIR_PATH", default="//softbody_bake/")
    last_message: StringProperty(name="Last bake", default="")


def register():
    bpy.utils.register_class(SoftbodyObjectSettings)
    bpy.utils.register_class(SoftbodySceneSettings)
    bpy.types.Object.softbody_pressure = PointerProperty(type=SoftbodyObjectSettings)
    bpy.types.Scene.softbody_pressure = PointerProperty(type=SoftbodySceneSettings)


def unregister():
    del bpy.types.Scene.softbody_pressure
    del bpy.types.Object.softbody_pressure
    bpy.utils.unregister_class(SoftbodySceneSettings)
    bpy.utils.unregister_class(SoftbodyObjectSettings)
