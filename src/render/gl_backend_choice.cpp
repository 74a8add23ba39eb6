// Backend names, the backends of this build, and the choice between the scene and SOFTBODY_GL.
#include "render/gl_backend_choice.hpp"

#include <array>
#include <utility>

#include "core/errors.hpp"

namespace render {
namespace {

constexpr std::array<std::pair<std::string_view, GlBackend>, 3> kNames = {
    {{"auto", GlBackend::Auto}, {"egl", GlBackend::Egl}, {"osmesa", GlBackend::OsMesa}}};

}  // namespace

std::string_view gl_backend_name(GlBackend backend) {
  for (const auto& [name, value] : kNames) {
    if (value == backend) return name;
  }
  return "?";
}

std::optional<GlBackend> parse_gl_backend(std::string_view name) {
  for (const auto& [known, value] : kNames) {
    if (known == name) return value;
  }
  return std::nullopt;
}

std::vector<GlBackend> built_gl_backends() {
  std::vector<GlBackend> backends;
#ifdef SOFTBODY_HAVE_EGL
  backends.push_back(GlBackend::Egl);
#endif
#ifdef SOFTBODY_HAVE_OSMESA
  backends.push_back(GlBackend::OsMesa);
#endif
  return backends;
}

GlBackendRequest choose_gl_backend(GlBackend scene_backend, const char* environment_value) {
  if (environment_value == nullptr || *environment_value == '\0') return {scene_backend, "render.backend"};
  const std::optional<GlBackend> backend = parse_gl_backend(environment_value);
  if (!backend) {
    throw softbody::InputError(
        std::string("SOFTBODY_GL: expected one of \"auto\" \"egl\" \"osmesa\" (or unset), got \"") + environment_value +
        "\"");
  }
  return {*backend, "SOFTBODY_GL"};
}

}  // namespace render
