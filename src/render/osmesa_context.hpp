// OSMesa (Mesa's software off-screen renderer, llvmpipe): a core-profile context without a display.
#pragma once

#include <cstdint>
#include <vector>

#include "render/gl_context.hpp"

struct osmesa_context;

namespace render {

class OsMesaContext final : public GlContext {
 public:
  // Asks for a core profile of at least `major.minor` (Mesa 22 answers with 4.5 for anything up to
  // 4.5). Throws std::runtime_error when OSMesa cannot create or bind one.
  OsMesaContext(int major, int minor);
  ~OsMesaContext() override;
  OsMesaContext(const OsMesaContext&) = delete;
  OsMesaContext& operator=(const OsMesaContext&) = delete;

  void make_current() override;
  GlBackend backend() const override { return GlBackend::OsMesa; }
  std::string description() const override;

 private:
  osmesa_context* context_ = nullptr;
  // OSMesa needs a default framebuffer in user memory to make a context current. Everything is drawn
  // into framebuffer objects, so one pixel is enough.
  std::vector<std::uint8_t> default_framebuffer_ = std::vector<std::uint8_t>(4, 0);
};

}  // namespace render
