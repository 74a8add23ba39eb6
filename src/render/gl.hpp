// The OpenGL API the renderer uses: core-profile declarations only. With GL_GLEXT_PROTOTYPES the
// functions are declared directly and resolved by the linker from libOSMesa, which exports every GL
// entry point it implements (OSMesaGetProcAddress cannot be used to probe: it returns non-NULL even
// for names it does not know). An EGL backend would link libOpenGL the same way.
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>

#include <string>

namespace render {

// Throws std::runtime_error naming `what` and the GL error code when glGetError reports one.
void check_gl(const char* what);

}  // namespace render
