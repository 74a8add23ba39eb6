// An OpenGL context to render into, whatever creates it (EGL or OSMesa): the renderer only needs one that
// is current on the calling thread, with the GL functions of render/gl.hpp loaded, and draws into
// framebuffer objects it makes itself.
#pragma once

#include <memory>
#include <string>

#include "render/gl_backend_choice.hpp"

namespace render {

class GlContext {
 public:
  virtual ~GlContext() = default;
  // Makes the context current on the calling thread (the renderer draws from one thread only).
  virtual void make_current() = 0;
  // Which backend made it: GlBackend::Egl or GlBackend::OsMesa.
  virtual GlBackend backend() const = 0;
  // "OpenGL 4.5 (Core Profile) Mesa 22.3.6 on llvmpipe (LLVM 15.0.6, 256 bits) (EGL, surfaceless)", for
  // logs and error messages.
  virtual std::string description() const = 0;
};

// An off-screen OpenGL 4.5 core-profile context from `backend`, current on the calling thread, its GL
// functions loaded. GlBackend::Auto tries EGL, then OSMesa, among those this build has. Throws
// std::runtime_error saying what failed and what to install when none can be created.
std::unique_ptr<GlContext> create_offscreen_context(GlBackend backend = GlBackend::Auto);

}  // namespace render
