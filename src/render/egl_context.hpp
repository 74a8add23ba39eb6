// EGL without a window system: a core-profile OpenGL 4.5 context with no surface at all (the renderer
// draws into its own framebuffer objects), on a GPU where EGL offers one, else on Mesa's llvmpipe.
#pragma once

#include <string>

#include "render/gl_context.hpp"

namespace render {

class EglContext final : public GlContext {
 public:
  // Opens the first display that gives a 4.5 core context, in this order: the device platform's hardware
  // devices (EGL_EXT_platform_device: a GPU's driver, NVIDIA's included), Mesa's surfaceless platform
  // (EGL_MESA_platform_surfaceless: a render node, else llvmpipe), the device platform's software device.
  // Throws std::runtime_error listing what each one answered.
  EglContext();
  ~EglContext() override;
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  void make_current() override;
  GlBackend backend() const override { return GlBackend::Egl; }
  std::string description() const override;

 private:
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
  std::string platform_;     // "surfaceless", "device 0", ...
};

}  // namespace render
