// A softbody process started in the background, for tests that signal it at a chosen moment and wait for it.
#pragma once

#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <sys/types.h>

namespace testing_support {

class BackgroundRun {
 public:
  using Clock = std::chrono::steady_clock;

  // Starts softbody with `arguments` from the source folder; its standard error goes to `dir`/stderr.txt,
  // its standard output to /dev/null.
  BackgroundRun(const std::vector<std::string>& arguments, const std::filesystem::path& dir);
  BackgroundRun(const BackgroundRun&) = delete;
  BackgroundRun& operator=(const BackgroundRun&) = delete;
  // Kills it (SIGKILL) and reaps it if it still runs.
  ~BackgroundRun();

  // Waits until `ready` holds (true), or the process ended or `bound` passed (false); polls every 20 ms.
  bool wait_until(const std::function<bool()>& ready, std::chrono::seconds bound);
  // Sends `signal` and notes the time.
  void signal(int signal);
  // The exit status (1000 + the signal when a signal ended it), or nothing if it still runs after `bound`.
  std::optional<int> wait_for_exit(std::chrono::seconds bound);
  // Seconds from signal() to the moment the exit was seen (to within one poll).
  double seconds_to_exit() const;
  // What it has written to standard error so far.
  std::string errors() const;
  // Its process id (to look at it under /proc).
  pid_t pid() const { return pid_; }

 private:
  bool exited();

  std::filesystem::path errors_;
  pid_t pid_ = -1;
  bool running_ = true;
  int status_ = -1;
  Clock::time_point signalled_{}, ended_{};
};

}  // namespace testing_support
