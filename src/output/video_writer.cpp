// The video writer: copies of the frames drained into the ffmpeg pipe on a worker queue, in order.
#include "output/video_writer.hpp"

#include <chrono>

#include "core/profile.hpp"

namespace output {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

VideoWriter::VideoWriter(std::filesystem::path path, int width_px, int height_px, int fps, std::size_t queue_capacity)
    : pipe_(std::move(path), width_px, height_px, fps),
      queue_(queue_capacity, [this](softbody::Image& frame) { pipe_frame(frame); }) {}

VideoWriter::~VideoWriter() {
  if (!finished_) abandon();
}

void VideoWriter::write(const softbody::Image& frame) {
  if (error_) std::rethrow_exception(error_);
  softbody::Image copy = queue_.spare().value_or(softbody::Image{});
  copy.width = frame.width;
  copy.height = frame.height;
  copy.rgb.assign(frame.rgb.begin(), frame.rgb.end());  // reuses the spare's storage
  try {
    queue_.push(std::move(copy));
  } catch (...) {
    error_ = std::current_exception();
    throw;
  }
}

void VideoWriter::pipe_frame(softbody::Image& frame) {
  const softbody::ProfileScope profile(softbody::ProfilePhase::video_pipe);
  const auto start = std::chrono::steady_clock::now();
  pipe_.write(frame);
  add_pipe_seconds(seconds_since(start));
}

void VideoWriter::add_pipe_seconds(double seconds) {
  std::lock_guard lock(pipe_s_mutex_);
  pipe_s_ += seconds;
}

void VideoWriter::finish() {
  finished_ = true;
  try {
    queue_.finish();
  } catch (...) {
    error_ = std::current_exception();
  }
  if (error_) {
    pipe_.abandon();
    std::rethrow_exception(error_);
  }
  const softbody::ProfileScope profile(softbody::ProfilePhase::video_pipe);
  const auto start = std::chrono::steady_clock::now();
  pipe_.finish();
  add_pipe_seconds(seconds_since(start));
}

void VideoWriter::abandon() {
  queue_.abandon();
  finished_ = true;
  pipe_.abandon();
}

double VideoWriter::pipe_seconds() const {
  std::lock_guard lock(pipe_s_mutex_);
  return pipe_s_;
}

}  // namespace output
