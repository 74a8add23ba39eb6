// Shared pieces of the render tests: one GL context per test process and scratch folders.
#pragma once

#include <filesystem>
#include <string>

#include "render/gl_context.hpp"

namespace render_test {

// The process's off-screen context, created on first use (current on the test thread) with the backend
// that SOFTBODY_GL names (ctest runs the golden tests once per backend), else GlBackend::Auto.
render::GlContext& gl_context();

// SOFTBODY_GL's backend, GlBackend::Auto when unset.
render::GlBackend requested_backend();

// An empty folder under the build tree for `name` (removed and recreated).
std::filesystem::path fresh_output_dir(const std::string& name);

}  // namespace render_test
