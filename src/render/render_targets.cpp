// Framebuffer objects for drawing, resolving and reading back.
//
// sRGB: colour renderbuffers are GL_SRGB8_ALPHA8 and the renderer keeps GL_FRAMEBUFFER_SRGB on while
// drawing and resolving, so the shaders write linear light, the hardware encodes it on store, and the
// resolve averages decoded samples. glReadPixels returns the stored bytes: encoded once, never twice.
#include "render/render_targets.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

namespace render {
namespace {

void attach_storage(GLuint framebuffer, GLuint renderbuffer, GLenum attachment, GLenum format, int samples, int width,
                    int height) {
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer);
  if (samples > 1)
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
  else
    glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, attachment, GL_RENDERBUFFER, renderbuffer);
}

void require_complete(const char* which) {
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw std::runtime_error(std::string("the ") + which + " framebuffer is incomplete (status " +
                             std::to_string(status) + ")");
  }
}

int supported_samples(int requested) {
  GLint max_samples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  return std::clamp(requested, 1, static_cast<int>(max_samples));
}

}  // namespace

RenderTargets::RenderTargets(int width_px, int height_px, int samples)
    : width_(width_px), height_(height_px), samples_(supported_samples(samples)) {
  attach_storage(resolved_.get(), resolved_color_.get(), GL_COLOR_ATTACHMENT0, GL_SRGB8_ALPHA8, 1, width_, height_);
  if (samples_ == 1) {
    attach_storage(resolved_.get(), resolved_depth_.get(), GL_DEPTH_ATTACHMENT, GL_DEPTH_COMPONENT24, 1, width_,
                   height_);
  }
  require_complete("resolve");
  if (samples_ > 1) {
    attach_storage(multisampled_.get(), multisampled_color_.get(), GL_COLOR_ATTACHMENT0, GL_SRGB8_ALPHA8, samples_,
                   width_, height_);
    attach_storage(multisampled_.get(), multisampled_depth_.get(), GL_DEPTH_ATTACHMENT, GL_DEPTH_COMPONENT24, samples_,
                   width_, height_);
    require_complete("multisample");
  }
  rgba_.resize(static_cast<std::size_t>(width_) * height_ * 4);
  check_gl("creating the render targets");
}

void RenderTargets::bind_for_drawing() const {
  glBindFramebuffer(GL_FRAMEBUFFER, samples_ > 1 ? multisampled_.get() : resolved_.get());
  glViewport(0, 0, width_, height_);
}

void RenderTargets::resolve() const {
  if (samples_ == 1) return;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, multisampled_.get());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved_.get());
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

void RenderTargets::read_rgb(softbody::Image& image) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved_.get());
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  // RGBA reads are about twice as fast as RGB on llvmpipe (no repacking in the driver); the alpha is
  // dropped below while flipping, which has to touch every row anyway.
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba_.data());
  check_gl("reading back the frame");
  if (image.width != width_ || image.height != height_) image = softbody::Image(width_, height_);
  for (int y = 0; y < height_; ++y) {
    const std::uint8_t* source = rgba_.data() + static_cast<std::size_t>(height_ - 1 - y) * width_ * 4;
    std::uint8_t* target = image.pixel(0, y);
    for (int x = 0; x < width_; ++x, source += 4, target += 3) std::memcpy(target, source, 3);
  }
}

}  // namespace render
