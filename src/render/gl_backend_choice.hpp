// The off-screen GL backends (EGL, OSMesa), their names, which this build has, and how the one to use is
// chosen: the environment variable SOFTBODY_GL, when set and not empty, wins over the scene's render.backend.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/gl_backend.hpp"

namespace render {

using softbody::GlBackend;

// "auto", "egl", "osmesa": the names the scene key render.backend and SOFTBODY_GL take.
std::string_view gl_backend_name(GlBackend backend);
std::optional<GlBackend> parse_gl_backend(std::string_view name);

// The backends compiled into this build (CMake options SOFTBODY_EGL, SOFTBODY_OSMESA), EGL first.
std::vector<GlBackend> built_gl_backends();

// The backend asked for, and who asked ("render.backend" or "SOFTBODY_GL"), for the summary line.
struct GlBackendRequest {
  GlBackend backend = GlBackend::Auto;
  std::string source = "render.backend";
};

// `environment_value` is SOFTBODY_GL's value (nullptr when unset): when set and not empty it wins over the
// scene's `scene_backend`. Throws softbody::InputError for a value that is not a backend's name.
GlBackendRequest choose_gl_backend(GlBackend scene_backend, const char* environment_value);

}  // namespace render
