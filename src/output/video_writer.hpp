// Feeds the ffmpeg video pipe from its own thread, so that the render thread does not wait on ffmpeg.
#pragma once

#include <condition_variable>
#include <deque>
#include <exception>
#include <filesystem>
#include <mutex>
#include <thread>
#include <vector>

#include "core/image.hpp"
#include "output/video_pipe.hpp"

namespace output {

class VideoWriter {
 public:
  // Starts ffmpeg (VideoPipe: throws when it cannot) and the writer thread. At most `queue_capacity`
  // frames wait (each a copy of a whole image); write() blocks beyond that.
  VideoWriter(std::filesystem::path path, int width_px, int height_px, int fps, std::size_t queue_capacity = 2);
  // Abandons the video unless finish() succeeded.
  ~VideoWriter();
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // Queues a copy of `frame`. Rethrows the error of an earlier frame (ffmpeg failed).
  void write(const softbody::Image& frame);
  // Writes every queued frame, then lets ffmpeg finish and renames the video into place; rethrows the
  // first error (the partial file is then removed).
  void finish();
  // Drops the queued frames and the partial video (the run stopped early).
  void abandon();

  // Seconds the writer thread spent in the pipe (ffmpeg's own pace included), summed over frames.
  double pipe_seconds() const;

 private:
  void run();
  void stop_thread(bool drop_queue);

  VideoPipe pipe_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  const std::size_t capacity_;
  std::deque<softbody::Image> queue_;
  std::vector<softbody::Image> spare_images_;
  bool closing_ = false;
  bool finished_ = false;
  std::exception_ptr error_;
  double pipe_s_ = 0.0;
  std::thread thread_;  // last: starts after everything it uses exists
};

}  // namespace output
