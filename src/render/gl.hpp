// The OpenGL API the renderer uses: core-profile types from glcorearb.h and one function pointer per entry
// point (render/gl_functions.inc), loaded from the backend that made the context (OSMesaGetProcAddress,
// eglGetProcAddress). No GL library is linked by symbol, so the OSMesa and EGL backends live in one binary:
// libOSMesa and glvnd's libOpenGL both export glClear & co., and whichever the linker picked would be
// wrong for the other backend's contexts.
#pragma once

#include <GL/glcorearb.h>

#include <string>

#include "render/gl_loader.hpp"

namespace render {

// Inside namespace render, `glClear(...)` names these pointers (valid once a backend loaded them).
#define SOFTBODY_GL_FUNCTION(type, name) extern type name;
#include "render/gl_functions.inc"
#undef SOFTBODY_GL_FUNCTION

// Throws std::runtime_error naming `what` and the GL error code when glGetError reports one.
void check_gl(const char* what);

}  // namespace render
