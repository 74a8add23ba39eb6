// Which off-screen OpenGL backend renders: a value of the scene (render.backend) that the renderer acts on.
#pragma once

namespace softbody {

// Auto: EGL where it works, else OSMesa. SOFTBODY_GL in the environment, when set, wins (render/gl_backend_choice.hpp).
enum class GlBackend { Auto, Egl, OsMesa };

}  // namespace softbody
