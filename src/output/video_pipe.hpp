// An MP4 video made while rendering: raw RGB frames piped into ffmpeg (libx264, yuv420p, +faststart).
// ffmpeg writes a temporary file that is renamed to the requested name only when it succeeded.
#pragma once

#include <sys/types.h>
#include <filesystem>

#include "core/image.hpp"

namespace output {

class VideoPipe {
 public:
  // Starts ffmpeg for width × height frames at `fps` frames per second. Throws std::runtime_error when
  // ffmpeg cannot be started (e.g. not installed). Ignores SIGPIPE process-wide, so that ffmpeg dying
  // shows up as a write error here instead of killing the program.
  VideoPipe(std::filesystem::path path, int width_px, int height_px, int fps);
  // Abandons the video unless finish() succeeded.
  ~VideoPipe();
  VideoPipe(const VideoPipe&) = delete;
  VideoPipe& operator=(const VideoPipe&) = delete;

  // Sends one frame (its size must match). Throws std::runtime_error with ffmpeg's message if it failed.
  void write(const softbody::Image& frame);
  // Closes ffmpeg's input, waits for it to finish the file and renames it into place. Throws
  // std::runtime_error with ffmpeg's message if it failed (the partial file is removed).
  void finish();
  // Stops ffmpeg and removes the partial file (the run stopped early: no video rather than a short one).
  void abandon();

  const std::filesystem::path& path() const { return path_; }

 private:
  [[noreturn]] void fail(const std::string& what);
  int wait_for_ffmpeg();
  void remove_temporaries();

  std::filesystem::path path_;
  std::filesystem::path temporary_;
  std::filesystem::path log_;  // ffmpeg's stderr, quoted in errors
  int width_;
  int height_;
  int input_fd_ = -1;  // the write end of ffmpeg's stdin
  pid_t ffmpeg_ = -1;
  bool finished_ = false;
};

}  // namespace output
