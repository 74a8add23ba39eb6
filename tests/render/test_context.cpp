// One OSMesa context for all the tests of the process, and scratch folders under the build tree.
#include "test_context.hpp"

#include "test_helpers.hpp"

#include <memory>

namespace render_test {

render::GlContext& gl_context() {
  static const std::unique_ptr<render::GlContext> context = render::create_offscreen_context();
  context->make_current();
  return *context;
}

std::filesystem::path fresh_output_dir(const std::string& name) { return testing_support::scratch_dir(name); }

}  // namespace render_test
