// create_offscreen_context: the backend asked for, or with GlBackend::Auto the first of this build's that
// works (EGL, then OSMesa).
#include <stdexcept>

#include "render/gl_context.hpp"
#ifdef SOFTBODY_HAVE_EGL
#include "render/egl_context.hpp"
#endif
#ifdef SOFTBODY_HAVE_OSMESA
#include "render/osmesa_context.hpp"
#endif

namespace render {
namespace {

std::string built_names() {
  std::string names;
  for (const GlBackend backend : built_gl_backends())
    names += (names.empty() ? "" : ", ") + std::string(gl_backend_name(backend));
  return names;
}

std::unique_ptr<GlContext> create_context_of(GlBackend backend) {
#ifdef SOFTBODY_HAVE_EGL
  if (backend == GlBackend::Egl) return std::make_unique<EglContext>();
#endif
#ifdef SOFTBODY_HAVE_OSMESA
  // Any core profile of 3.3 or newer: Mesa answers with its highest, 4.5.
  if (backend == GlBackend::OsMesa) return std::make_unique<OsMesaContext>(3, 3);
#endif
  throw std::runtime_error("this build has no " + std::string(gl_backend_name(backend)) + " backend (it has: " +
                           built_names() + "; see the CMake options SOFTBODY_EGL, SOFTBODY_OSMESA)");
}

}  // namespace

std::unique_ptr<GlContext> create_offscreen_context(GlBackend backend) {
  if (backend != GlBackend::Auto) return create_context_of(backend);
  std::string failures;
  for (const GlBackend candidate : built_gl_backends()) {
    try {
      return create_context_of(candidate);
    } catch (const std::runtime_error& e) {
      failures += (failures.empty() ? "" : " | ") + std::string(e.what());
    }
  }
  throw std::runtime_error("no off-screen OpenGL context could be made: " + failures);
}

}  // namespace render
