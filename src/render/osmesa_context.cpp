// The OSMesa context: created with OSMesaCreateContextAttribs, because the classic OSMesaCreateContext
// only gives a compatibility profile. The GL entry points come from OSMesaGetProcAddress (render/gl.hpp).
#include "render/osmesa_context.hpp"

#include <stdexcept>

#include <GL/osmesa.h>

#include "render/gl_loader.hpp"

namespace render {

OsMesaContext::OsMesaContext(int major, int minor) {
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            0,  // depth lives in the renderer's framebuffer objects
                            OSMESA_STENCIL_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            major,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            minor,
                            0};
  context_ = OSMesaCreateContextAttribs(attributes, nullptr);
  if (context_ == nullptr) {
    throw std::runtime_error("OSMesa could not create an OpenGL " + std::to_string(major) + "." +
                             std::to_string(minor) +
                             " core-profile context (OSMesaCreateContextAttribs returned NULL; "
                             "needs Mesa's libOSMesa with llvmpipe, Debian package libosmesa6)");
  }
  make_current();
  load_gl_functions([](const char* name) -> GlProc { return OSMesaGetProcAddress(name); }, "OSMesa");
}

OsMesaContext::~OsMesaContext() {
  if (context_ != nullptr) OSMesaDestroyContext(context_);
}

void OsMesaContext::make_current() {
  if (!OSMesaMakeCurrent(context_, default_framebuffer_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
    throw std::runtime_error("OSMesa could not make its context current (OSMesaMakeCurrent failed)");
  }
}

std::string OsMesaContext::description() const { return "OpenGL " + gl_version_and_renderer() + " (OSMesa)"; }

}  // namespace render
