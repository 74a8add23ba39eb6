// Loading the GL function pointers of render/gl.hpp from a backend, without GL headers: the backends'
// own headers (GL/osmesa.h pulls in GL/gl.h) do not mix with glcorearb.h in one file.
#pragma once

#include <string>

namespace render {

// A backend's lookup of a GL entry point by name (both return a generic function pointer).
using GlProc = void (*)();
using GlProcLookup = GlProc (*)(const char* name);

// Fills every pointer of render/gl_functions.inc from `lookup`, with the new context current. Throws
// std::runtime_error naming the first entry point `lookup` does not know (`backend` in the message).
void load_gl_functions(GlProcLookup lookup, const std::string& backend);

// "4.5 (Core Profile) Mesa 22.3.6 on llvmpipe (LLVM 15.0.6, 256 bits)": GL_VERSION and GL_RENDERER.
std::string gl_version_and_renderer();

}  // namespace render
