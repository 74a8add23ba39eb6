// Feeds the ffmpeg video pipe from its own thread, so that the render thread does not wait on ffmpeg.
#pragma once

#include <exception>
#include <filesystem>
#include <mutex>

#include "core/image.hpp"
#include "output/video_pipe.hpp"
#include "output/worker_queue.hpp"

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
  // The writer thread's work for one frame: into ffmpeg's stdin.
  void pipe_frame(softbody::Image& frame);
  void add_pipe_seconds(double seconds);

  VideoPipe pipe_;
  bool finished_ = false;
  std::exception_ptr error_;  // a frame that failed (ffmpeg died): the video is abandoned
  mutable std::mutex pipe_s_mutex_;
  double pipe_s_ = 0.0;
  WorkerQueue<softbody::Image> queue_;  // last: its thread starts after everything it uses exists
};

}  // namespace output
