// One OSMesa context for all the tests of the process, and scratch folders under the build tree.
#include "test_context.hpp"

#include <unistd.h>


#include <memory>

namespace render_test {

render::GlContext& gl_context() {
  static const std::unique_ptr<render::GlContext> context = render::create_offscreen_context();
  context->make_current();
  return *context;
}

std::filesystem::path fresh_output_dir(const std::string& name) {
  // ctest runs each test in its own process, two at a time: a per-process folder keeps them apart.
  const std::filesystem::path dir = std::filesystem::path(SOFTBODY_TEST_OUTPUT_DIR) / (name + "." + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace render_test
