// An OpenGL context to render into, whatever creates it (OSMesa today, EGL later): the renderer only
// needs one that is current on the calling thread and draws into framebuffer objects it makes itself.
#pragma once

#include <memory>
#include <string>

namespace render {

class GlContext {
 public:
  virtual ~GlContext() = default;
  // Makes the context current on the calling thread (the renderer draws from one thread only).
  virtual void make_current() = 0;
  // "OpenGL 4.5 (Core Profile) Mesa 22.3.6 on llvmpipe ...", for logs and error messages.
  virtual std::string description() const = 0;
};

// An off-screen OpenGL 3.3-or-newer core-profile context, current on the calling thread. Throws
// std::runtime_error saying what failed and what to install when none can be created.
std::unique_ptr<GlContext> create_offscreen_context();

}  // namespace render
