// GL error checks.
#include "render/gl.hpp"

#include <cstdio>
#include <stdexcept>

namespace render {

void check_gl(const char* what) {
  const GLenum error = glGetError();
  if (error == GL_NO_ERROR) return;
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", error);
  throw std::runtime_error(std::string("OpenGL error ") + code + " in " + what);
}

}  // namespace render
