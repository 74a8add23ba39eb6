// The PNG writer thread: a bounded queue of frames, consumed in order.
#include "output/png_writer.hpp"

#include <algorithm>
#include <chrono>
#include <utility>

#include "output/atomic_file.hpp"
#include "output/png_codec.hpp"

namespace output {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_between(Clock::time_point start, Clock::time_point end) {
  return std::chrono::duration<double>(end - start).count();
}

}  // namespace

PngWriter::PngWriter(std::size_t queue_capacity)
    : capacity_(std::max<std::size_t>(queue_capacity, 1)), thread_([this] { run(); }) {}

PngWriter::~PngWriter() {
  try {
    finish();
  } catch (...) {
    // A destructor must not throw; callers who care call finish() and see the error there.
  }
}

void PngWriter::write(std::filesystem::path path, softbody::Image image) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return queue_.size() < capacity_ || error_; });
  rethrow_error_locked();
  queue_.push_back({std::move(path), std::move(image)});
  changed_.notify_all();
}

void PngWriter::finish() {
  {
    std::unique_lock lock(mutex_);
    closing_ = true;
    changed_.notify_all();
  }
  if (thread_.joinable()) thread_.join();
  std::unique_lock lock(mutex_);
  rethrow_error_locked();
}

softbody::Image PngWriter::recycled_image() {
  std::unique_lock lock(mutex_);
  if (spare_images_.empty()) return {};
  softbody::Image image = std::move(spare_images_.back());
  spare_images_.pop_back();
  return image;
}

PngWriterTimings PngWriter::timings() const {
  std::unique_lock lock(mutex_);
  return timings_;
}

void PngWriter::rethrow_error_locked() {
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
}

void PngWriter::run() {
  for (;;) {
    Job job;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [this] { return !queue_.empty() || closing_; });
      if (queue_.empty()) return;  // closing and drained
      job = std::move(queue_.front());
      queue_.pop_front();
      changed_.notify_all();  // room for the next frame
    }
    try {
      const auto start = Clock::now();
      const std::string bytes = encode_png(job.image);
      const auto encoded = Clock::now();
      write_file_atomically(job.path, bytes);
      const auto stored = Clock::now();
      std::unique_lock lock(mutex_);
      timings_.frames += 1;
      timings_.encode_s += seconds_between(start, encoded);
      timings_.store_s += seconds_between(encoded, stored);
      if (spare_images_.size() < capacity_) spare_images_.push_back(std::move(job.image));
    } catch (...) {
      std::unique_lock lock(mutex_);
      if (!error_) error_ = std::current_exception();
      queue_.clear();  // the run is failing: do not write frames after a missing one
      changed_.notify_all();
    }
  }
}

}  // namespace output
