// ffmpeg as a child process: posix_spawnp with its stdin on a pipe and its stderr in a log file.
#include "output/video_pipe.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "output/atomic_file.hpp"

extern char** environ;

namespace output {
namespace {

constexpr int kPipeBytes = 1 << 20;  // fewer context switches than the 64 KiB default; best effort

std::vector<std::string> ffmpeg_arguments(const std::filesystem::path& output, int width, int height, int fps) {
  return {"ffmpeg", "-hide_banner", "-loglevel", "error", "-y",
          // input: raw RGB frames on stdin
          "-f", "rawvideo", "-pix_fmt", "rgb24", "-video_size", std::to_string(width) + "x" + std::to_string(height),
          "-framerate", std::to_string(fps), "-i", "pipe:0",
          // output: H.264 that every player reads, index at the front for streaming. RGB → YUV with the
          // BT.709 matrix, and the stream tagged so: untagged HD video is read as BT.709 by most players,
          // and converting with ffmpeg's default BT.601 matrix would shift the colours.
          "-vf", "scale=out_color_matrix=bt709:out_range=tv", "-colorspace", "bt709", "-color_primaries", "bt709",
          "-color_trc", "bt709", "-color_range", "tv", "-c:v", "libx264", "-preset", "veryfast", "-crf", "18",
          "-pix_fmt", "yuv420p", "-movflags", "+faststart", "-f", "mp4", output.string()};
}

std::string tail_of_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  std::string all = text.str();
  while (!all.empty() && (all.back() == '\n' || all.back() == '\r')) all.pop_back();
  if (all.size() > 600) all = "..." + all.substr(all.size() - 600);
  return all.empty() ? "no message" : all;
}

}  // namespace

VideoPipe::VideoPipe(std::filesystem::path path, int width_px, int height_px, int fps)
    : path_(std::move(path)), width_(width_px), height_(height_px) {
  if (!path_.parent_path().empty()) std::filesystem::create_directories(path_.parent_path());
  temporary_ = temporary_path_for(path_);
  // A device or FIFO is written through at the end (move_into_place); its folder (/dev) may not be writable.
  if (is_written_through(path_)) temporary_ = std::filesystem::temp_directory_path() / temporary_.filename();
  log_ = temporary_;
  log_ += ".log";
  std::signal(SIGPIPE, SIG_IGN);

  int ends[2];
  if (::pipe2(ends, O_CLOEXEC) != 0)
    throw std::runtime_error("cannot create a pipe for ffmpeg: " + std::string(std::strerror(errno)));
  ::fcntl(ends[1], F_SETPIPE_SZ, kPipeBytes);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, ends[0], STDIN_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);

  const std::vector<std::string> arguments = ffmpeg_arguments(temporary_, width_, height_, fps);
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  // ffmpeg in a process group of its own: a Ctrl-C (SIGINT to the terminal's foreground group) reaches softbody
  // only, which ends the run after the frame in progress and then drops or finishes the video itself.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);
  const int status = posix_spawnp(&ffmpeg_, "ffmpeg", &actions, &attributes, argv.data(), environ);
  posix_spawnattr_destroy(&attributes);
  posix_spawn_file_actions_destroy(&actions);
  ::close(ends[0]);
  if (status != 0) {
    ::close(ends[1]);
    ffmpeg_ = -1;
    std::filesystem::remove(log_);
    throw std::runtime_error("cannot start ffmpeg to write " + path_.string() + ": " + std::strerror(status) +
                             (status == ENOENT ? " (ffmpeg is not on PATH: install it, e.g. scripts/setup)" : ""));
  }
  input_fd_ = ends[1];
}

VideoPipe::~VideoPipe() {
  if (!finished_) abandon();
}

void VideoPipe::write(const softbody::Image& frame) {
  if (frame.width != width_ || frame.height != height_) {
    throw std::logic_error("VideoPipe::write: frame size differs from the video's");
  }
  const std::uint8_t* data = frame.rgb.data();
  std::size_t left = frame.rgb.size();
  while (left > 0) {
    const ssize_t written = ::write(input_fd_, data, left);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) fail("ffmpeg stopped reading frames");
    data += written;
    left -= static_cast<std::size_t>(written);
  }
}

void VideoPipe::finish() {
  ::close(std::exchange(input_fd_, -1));  // end of input: ffmpeg flushes the encoder and writes the index
  const int status = wait_for_ffmpeg();
  if (status != 0) fail("ffmpeg exited with status " + std::to_string(status));
  // A device or FIFO (an existing non-regular file) is written through, never replaced.
  try {
    move_into_place(temporary_, path_);
  } catch (const std::runtime_error& e) {
    fail(std::string("cannot put the video in place: ") + e.what());
  }
  std::error_code ec;
  std::filesystem::remove(log_, ec);
  finished_ = true;
}

void VideoPipe::abandon() {
  if (input_fd_ >= 0) ::close(std::exchange(input_fd_, -1));
  if (ffmpeg_ > 0) {
    ::kill(ffmpeg_, SIGTERM);
    wait_for_ffmpeg();
  }
  remove_temporaries();
  finished_ = true;
}

void VideoPipe::fail(const std::string& what) {
  if (input_fd_ >= 0) ::close(std::exchange(input_fd_, -1));
  if (ffmpeg_ > 0) wait_for_ffmpeg();
  const std::string message = "video " + path_.string() + ": " + what + ": " + tail_of_file(log_);
  remove_temporaries();
  finished_ = true;
  throw std::runtime_error(message);
}

int VideoPipe::wait_for_ffmpeg() {
  int status = 0;
  while (::waitpid(ffmpeg_, &status, 0) < 0 && errno == EINTR) {
  }
  ffmpeg_ = -1;
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

void VideoPipe::remove_temporaries() {
  std::error_code ec;
  std::filesystem::remove(temporary_, ec);
  std::filesystem::remove(log_, ec);
}

}  // namespace output
