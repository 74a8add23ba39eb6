// The video writer thread: a bounded queue of frame copies drained into the ffmpeg pipe.
#include "output/video_writer.hpp"

#include <chrono>

namespace output {

VideoWriter::VideoWriter(std::filesystem::path path, int width_px, int height_px, int fps, std::size_t queue_capacity)
    : pipe_(std::move(path), width_px, height_px, fps), capacity_(queue_capacity), thread_([this] { run(); }) {}

VideoWriter::~VideoWriter() {
  if (!finished_) abandon();
}

void VideoWriter::write(const softbody::Image& frame) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return queue_.size() < capacity_ || error_; });
  if (error_) std::rethrow_exception(error_);
  softbody::Image copy;
  if (!spare_images_.empty()) {
    copy = std::move(spare_images_.back());
    spare_images_.pop_back();
  }
  lock.unlock();
  copy.width = frame.width;
  copy.height = frame.height;
  copy.rgb.assign(frame.rgb.begin(), frame.rgb.end());  // reuses the spare's storage
  lock.lock();
  queue_.push_back(std::move(copy));
  changed_.notify_all();
}

void VideoWriter::run() {
  std::unique_lock lock(mutex_);
  while (true) {
    changed_.wait(lock, [&] { return !queue_.empty() || closing_; });
    if (queue_.empty()) return;  // closing and drained
    softbody::Image frame = std::move(queue_.front());
    queue_.pop_front();
    if (!error_) {
      lock.unlock();
      const auto start = std::chrono::steady_clock::now();
      std::exception_ptr error;
      try {
        pipe_.write(frame);
      } catch (...) {
        error = std::current_exception();
      }
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      lock.lock();
      pipe_s_ += seconds;
      if (error && !error_) error_ = error;
    }
    spare_images_.push_back(std::move(frame));
    changed_.notify_all();
  }
}

void VideoWriter::stop_thread(bool drop_queue) {
  {
    std::lock_guard lock(mutex_);
    if (drop_queue) queue_.clear();
    closing_ = true;
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void VideoWriter::finish() {
  stop_thread(false);
  finished_ = true;
  if (error_) {
    pipe_.abandon();
    std::rethrow_exception(error_);
  }
  const auto start = std::chrono::steady_clock::now();
  pipe_.finish();
  pipe_s_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void VideoWriter::abandon() {
  stop_thread(true);
  finished_ = true;
  pipe_.abandon();
}

double VideoWriter::pipe_seconds() const {
  std::lock_guard lock(mutex_);
  return pipe_s_;
}

}  // namespace output
