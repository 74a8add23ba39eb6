// Writes frames as PNG files on a writer thread while the caller renders the next frame. Each file is
// encoded, written under a temporary name and renamed, so a killed run never leaves a broken frame.
#pragma once

#include <filesystem>
#include <functional>
#include <mutex>
#include <string_view>

#include "core/image.hpp"
#include "output/worker_queue.hpp"

namespace output {

// Time the writer thread spent per stage, summed over all frames [s].
struct PngWriterTimings {
  int frames = 0;
  double encode_s = 0.0;  // libpng, in memory
  double store_s = 0.0;   // writing the file and renaming it into place
};

class PngWriter {
 public:
  // At most `queue_capacity` frames wait for the writer (each holds a whole image): write() blocks
  // beyond that, which keeps memory bounded when encoding is slower than rendering.
  explicit PngWriter(std::size_t queue_capacity = 2);
  // Finishes the queued frames (errors are dropped here: call finish() to see them).
  ~PngWriter();
  PngWriter(const PngWriter&) = delete;
  PngWriter& operator=(const PngWriter&) = delete;

  // Calls `stored(path, bytes)` on the writer thread after each file is in place (set before the first write).
  void after_each_file(std::function<void(const std::filesystem::path&, std::string_view)> stored);
  // Queues `image` for `path`. Rethrows the error of an earlier frame that failed to write.
  void write(std::filesystem::path path, softbody::Image image);
  // Waits until every queued frame is on disk; rethrows the first error. Later writes are not allowed.
  void finish();

  // An image the writer is done with (pixels unspecified), to read the next frame into without a fresh
  // allocation; a default-constructed one when none is free yet.
  softbody::Image recycled_image();

  PngWriterTimings timings() const;

 private:
  struct Job {
    std::filesystem::path path;
    softbody::Image image;
  };
  // The writer thread's work for one frame: encode, write under a temporary name, rename.
  void store(Job& job);

  std::function<void(const std::filesystem::path&, std::string_view)> stored_;
  mutable std::mutex timings_mutex_;
  PngWriterTimings timings_;
  WorkerQueue<Job> queue_;  // last: its thread starts after everything it uses exists
};

}  // namespace output
