// Rendering each frame and handing the image to the outputs.
#include "render/render_sink.hpp"

#include <chrono>
#include <cstdio>

#include "core/profile.hpp"
#include "output/atomic_file.hpp"
#include "output/frame_pattern.hpp"
#include "output/mesh_snapshot.hpp"
#include "output/png_codec.hpp"

namespace render {
namespace {

using Clock = std::chrono::steady_clock;

// Adds the seconds since `start` to `total` and restarts `start`.
void lap(Clock::time_point& start, double& total) {
  const auto now = Clock::now();
  total += std::chrono::duration<double>(now - start).count();
  start = now;
}

constexpr std::size_t kPngQueueFrames = 2;  // frames waiting for the writer: enough to overlap, bounded memory

}  // namespace

RenderSink::RenderSink(Renderer& renderer, RenderOutputs outputs) : renderer_(renderer), outputs_(std::move(outputs)) {
  const RenderSettings& settings = renderer_.settings();
  if (outputs_.write_frames) {
    png_writer_.emplace(kPngQueueFrames);
    if (outputs_.frame_stored) png_writer_->after_each_file(outputs_.frame_stored);
  }
  if (outputs_.video && !outputs_.video_from_files) {
    video_ =
        std::make_unique<output::VideoWriter>(*outputs_.video, settings.width_px, settings.height_px, outputs_.fps);
  }
  std::vector<int> figure_frames = outputs_.figure_frame_list;
  if (figure_frames.empty()) figure_frames = output::evenly_spaced_frames(outputs_.figure_frames, outputs_.last_frame);
  if (!figure_frames.empty()) {
    figure_.emplace(std::move(figure_frames), settings.width_px, settings.height_px);
    for (int index = 0; index <= outputs_.resumed_after; ++index) {
      if (figure_->wants(index)) {
        figure_->add(index, output::read_png(outputs_.dir / output::frame_file_name(outputs_.pattern, index)),
                     time_label(index));
      }
    }
  }
}

void RenderSink::capture(int index, double time_s, const sim::World& world) {
  auto start = Clock::now();
  const softbody::ProfileScope profile(softbody::ProfilePhase::snapshot);
  output::snapshot_surfaces(world, meshes_);
  captured_index_ = index;
  captured_time_s_ = time_s;
  lap(start, timings_.snapshot_s);
}

void RenderSink::deliver() {
  const int index = captured_index_;
  auto start = Clock::now();
  softbody::profiled(softbody::ProfilePhase::render, [&] {
    renderer_.pose_colliders(captured_time_s_);
    renderer_.draw(meshes_);
  });
  lap(start, timings_.render_s);
  if (png_writer_) frame_ = png_writer_->recycled_image();
  softbody::profiled(softbody::ProfilePhase::read_back, [&] { renderer_.read_back(frame_); });
  lap(start, timings_.read_back_s);
  if (video_) {
    video_->write(frame_);
    lap(start, timings_.video_s);
  }
  if (figure_ && figure_->wants(index)) {
    figure_->add(index, frame_, time_label(index));
    lap(start, timings_.figure_s);
  }
  if (png_writer_) {
    png_writer_->write(outputs_.dir / output::frame_file_name(outputs_.pattern, index), std::move(frame_));
    lap(start, timings_.queue_wait_s);
  }
  ++timings_.frames;
}

void RenderSink::finish(bool complete) {
  if (!complete) {
    // The run is already failing with its own error, which must not be replaced by a secondary one:
    // write what is queued (valid frames) as well as possible and drop the unfinished video.
    try {
      if (png_writer_) png_writer_->finish();
    } catch (const std::exception&) {
    }
    if (video_) video_->abandon();
    return;
  }
  if (png_writer_) png_writer_->finish();
  if (video_) {
    auto start = Clock::now();
    video_->finish();
    lap(start, timings_.video_s);
  }
  if (outputs_.video && outputs_.video_from_files) encode_video_from_files();
  if (figure_ && figure_->complete()) write_figure();
  if (outputs_.write_frames && outputs_.remove_stale_frames) remove_stale_frames();
}

void RenderSink::encode_video_from_files() {
  auto start = Clock::now();
  const RenderSettings& settings = renderer_.settings();
  output::VideoWriter video(*outputs_.video, settings.width_px, settings.height_px, outputs_.fps);
  for (int index = 0; index <= outputs_.last_frame; ++index) {
    video.write(output::read_png(outputs_.dir / output::frame_file_name(outputs_.pattern, index)));
  }
  video.finish();
  lap(start, timings_.video_s);
}

std::string RenderSink::time_label(int index) const {
  char text[32];
  std::snprintf(text, sizeof text, "t = %.2f s", static_cast<double>(index) / outputs_.fps);
  return text;
}

void RenderSink::write_figure() {
  auto start = Clock::now();
  output::write_file_atomically(outputs_.dir / "figure.png", output::encode_png(figure_->image()));
  figure_written_ = true;
  lap(start, timings_.figure_s);
}

void RenderSink::remove_stale_frames() const {
  for (int index = outputs_.last_frame + 1;; ++index) {
    const std::filesystem::path stale = outputs_.dir / output::frame_file_name(outputs_.pattern, index);
    std::error_code ec;
    if (!std::filesystem::remove(stale, ec)) return;
  }
}

RenderTimings RenderSink::timings() const {
  RenderTimings timings = timings_;
  if (png_writer_) timings.png = png_writer_->timings();
  return timings;
}

std::optional<std::filesystem::path> RenderSink::figure_path() const {
  if (!figure_written_) return std::nullopt;
  return outputs_.dir / "figure.png";
}

}  // namespace render
