// The GL backends: names, SOFTBODY_GL against render.backend, and that the context of this test process
// is the backend asked for (ctest runs the render tests under SOFTBODY_GL=egl and =osmesa).
#include <gtest/gtest.h>

#include <string>

#include "core/errors.hpp"
#include "render/gl_backend_choice.hpp"
#include "test_context.hpp"

namespace {

using render::GlBackend;

TEST(GlBackend, NamesRoundTrip) {
  for (const GlBackend backend : {GlBackend::Auto, GlBackend::Egl, GlBackend::OsMesa}) {
    EXPECT_EQ(render::parse_gl_backend(render::gl_backend_name(backend)), backend);
  }
  EXPECT_FALSE(render::parse_gl_backend("opengl").has_value());
}

TEST(GlBackend, EnvironmentWinsOverTheScene) {
  EXPECT_EQ(render::choose_gl_backend(GlBackend::OsMesa, "egl").backend, GlBackend::Egl);
  EXPECT_EQ(render::choose_gl_backend(GlBackend::OsMesa, "egl").source, "SOFTBODY_GL");
  EXPECT_EQ(render::choose_gl_backend(GlBackend::Egl, "auto").backend, GlBackend::Auto);
  // Unset or empty: the scene's key.
  EXPECT_EQ(render::choose_gl_backend(GlBackend::OsMesa, nullptr).backend, GlBackend::OsMesa);
  EXPECT_EQ(render::choose_gl_backend(GlBackend::Egl, "").backend, GlBackend::Egl);
  EXPECT_EQ(render::choose_gl_backend(GlBackend::Egl, "").source, "render.backend");
  EXPECT_THROW(render::choose_gl_backend(GlBackend::Auto, "vulkan"), softbody::InputError);
}

TEST(GlBackend, TheContextIsTheOneAskedFor) {
  const GlBackend asked = render_test::requested_backend();
  const render::GlContext& context = render_test::gl_context();
  const std::string description = context.description();
  if (asked != GlBackend::Auto) {
    EXPECT_EQ(context.backend(), asked) << description;
  }
  EXPECT_NE(description.find(context.backend() == GlBackend::Egl ? "(EGL" : "(OSMesa)"), std::string::npos)
      << description;
  // The renderer needs a 4.5 core context from either backend.
  EXPECT_NE(description.find("OpenGL 4."), std::string::npos) << description;
  EXPECT_NE(description.find("Core Profile"), std::string::npos) << description;
}

}  // namespace
