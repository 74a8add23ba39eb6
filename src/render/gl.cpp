// The GL function pointers, their loading from a backend, and GL error checks.
#include "render/gl.hpp"

#include <cstdio>
#include <stdexcept>

namespace render {

#define SOFTBODY_GL_FUNCTION(type, name) type name = nullptr;
#include "render/gl_functions.inc"
#undef SOFTBODY_GL_FUNCTION

void load_gl_functions(GlProcLookup lookup, const std::string& backend) {
#define SOFTBODY_GL_FUNCTION(type, name)                                              \
  name = reinterpret_cast<type>(lookup(#name));                                       \
  if (name == nullptr) {                                                              \
    throw std::runtime_error(backend + " does not provide the OpenGL function " #name \
                                       " (needs OpenGL 4.5 "                          \
                                       "core, as Mesa's llvmpipe gives)");            \
  }
#include "render/gl_functions.inc"
#undef SOFTBODY_GL_FUNCTION
}

std::string gl_version_and_renderer() {
  const auto text = [](GLenum name) {
    const GLubyte* value = glGetString(name);
    return value == nullptr ? std::string("?") : std::string(reinterpret_cast<const char*>(value));
  };
  return text(GL_VERSION) + " on " + text(GL_RENDERER);
}

void check_gl(const char* what) {
  const GLenum error = glGetError();
  if (error == GL_NO_ERROR) return;
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", error);
  throw std::runtime_error(std::string("OpenGL error ") + code + " in " + what);
}

}  // namespace render
