// Where a frame is drawn and read from: a multisample framebuffer resolved into a single-sample one
// (or the single-sample one directly when multisampling is off). Colour is stored sRGB-encoded.
#pragma once

#include <cstdint>
#include <vector>

#include "core/image.hpp"
#include "render/gl_objects.hpp"

namespace render {

class RenderTargets {
 public:
  // `samples` = 1 draws into the single-sample target; more asks for that many (clamped to GL_MAX_SAMPLES).
  RenderTargets(int width_px, int height_px, int samples);

  // Binds the framebuffer to draw into and sets the viewport to it.
  void bind_for_drawing() const;
  // Averages the samples into the single-sample target (glBlitFramebuffer); nothing when samples = 1.
  void resolve() const;
  // Copies the single-sample target into `image`, flipping rows (GL's row 0 is the bottom) and dropping alpha.
  void read_rgb(softbody::Image& image);

  int samples() const { return samples_; }

 private:
  int width_;
  int height_;
  int samples_;
  GlFramebuffer resolved_;  // single-sample: colour (+ depth when it is also the draw target)
  GlRenderbuffer resolved_color_;
  GlRenderbuffer resolved_depth_;
  GlFramebuffer multisampled_;
  GlRenderbuffer multisampled_color_;
  GlRenderbuffer multisampled_depth_;
  std::vector<std::uint8_t> rgba_;  // read-back staging, bottom row first
};

}  // namespace render
