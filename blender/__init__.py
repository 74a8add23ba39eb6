# softbody's Blender add-on: a "Soft body (pressure)" panel on mesh objects and on the scene, and a Bake that runs
# the softbody program and plays its point caches through Mesh Cache modifiers.
bl_info = {
    "name": "softbody (pressure soft bodies)",
    "author": "softbody",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "Properties > Physics > Soft body (pressure); Properties > Scene > Soft body (pressure)",
    "description": "Bake pressure-model soft bodies with the softbody program and play them as point caches",
    "category": "Physics",
}

from . import bake, clear, panels, preferences, properties  # noqa: E402

_modules = (preferences, properties, bake, clear, panels)


def register():
    for module in _modules:
        module.register()


def unregister():
    for module in reversed(_modules):
        module.unregister()
