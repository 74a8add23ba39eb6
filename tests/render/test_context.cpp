// One GL context for all the tests of the process (the backend SOFTBODY_GL names, else auto), and scratch
// folders under the build tree.
#include "test_context.hpp"

#include "test_helpers.hpp"

#include <cstdlib>
#include <memory>

namespace render_test {

render::GlContext& gl_context() {
  static const std::unique_ptr<render::GlContext> context = render::create_offscreen_context(requested_backend());
  context->make_current();
  return *context;
}

render::GlBackend requested_backend() {
  return render::choose_gl_backend(render::GlBackend::Auto, std::getenv("SOFTBODY_GL")).backend;
}

std::filesystem::path fresh_output_dir(const std::string& name) { return testing_support::scratch_dir(name); }

}  // namespace render_test
