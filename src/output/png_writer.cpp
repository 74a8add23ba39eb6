// The PNG writer: frames encoded and stored on a worker queue, in order.
#include "output/png_writer.hpp"

#include <chrono>
#include <utility>

#include "core/profile.hpp"
#include "output/atomic_file.hpp"
#include "output/png_codec.hpp"

namespace output {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_between(Clock::time_point start, Clock::time_point end) {
  return std::chrono::duration<double>(end - start).count();
}

}  // namespace

PngWriter::PngWriter(std::size_t queue_capacity) : queue_(queue_capacity, [this](Job& job) { store(job); }) {}

PngWriter::~PngWriter() {
  try {
    finish();
  } catch (...) {
    // A destructor must not throw; callers who care call finish() and see the error there.
  }
}

void PngWriter::write(std::filesystem::path path, softbody::Image image) {
  queue_.push({std::move(path), std::move(image)});
}

void PngWriter::after_each_file(std::function<void(const std::filesystem::path&, std::string_view)> stored) {
  stored_ = std::move(stored);
}

void PngWriter::finish() { queue_.finish(); }

softbody::Image PngWriter::recycled_image() {
  std::optional<Job> spare = queue_.spare();
  return spare ? std::move(spare->image) : softbody::Image{};
}

PngWriterTimings PngWriter::timings() const {
  std::unique_lock lock(timings_mutex_);
  return timings_;
}

void PngWriter::store(Job& job) {
  const auto start = Clock::now();
  const std::string bytes =
      softbody::profiled(softbody::ProfilePhase::png_encode, [&] { return encode_png(job.image); });
  const auto encoded = Clock::now();
  softbody::profiled(softbody::ProfilePhase::png_store, [&] {
    write_file_atomically(job.path, bytes);
    if (stored_) stored_(job.path, bytes);
  });
  const auto stored = Clock::now();
  std::unique_lock lock(timings_mutex_);
  timings_.frames += 1;
  timings_.encode_s += seconds_between(start, encoded);
  timings_.store_s += seconds_between(encoded, stored);
}

}  // namespace output
