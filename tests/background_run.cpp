// A background softbody process: fork, exec, poll, signal, reap.
#include "background_run.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <iterator>
#include <thread>

namespace testing_support {

BackgroundRun::BackgroundRun(const std::vector<std::string>& arguments, const std::filesystem::path& dir)
    : errors_(dir / "stderr.txt") {
  pid_ = ::fork();
  if (pid_ == 0) {
    const int errors = ::open(errors_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int null = ::open("/dev/null", O_WRONLY);
    if (errors < 0 || null < 0 || ::dup2(errors, 2) < 0 || ::dup2(null, 1) < 0) ::_exit(126);
    if (::chdir(SOFTBODY_SOURCE_DIR) != 0) ::_exit(126);
    std::vector<char*> argv{const_cast<char*>(SOFTBODY_EXE)};
    for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(SOFTBODY_EXE, argv.data());
    ::_exit(127);
  }
  if (pid_ < 0) running_ = false;
}

BackgroundRun::~BackgroundRun() {
  if (!running_) return;
  ::kill(pid_, SIGKILL);
  ::waitpid(pid_, nullptr, 0);
}

bool BackgroundRun::wait_until(const std::function<bool()>& ready, std::chrono::seconds bound) {
  const auto until = Clock::now() + bound;
  while (Clock::now() < until) {
    if (ready()) return true;
    if (exited()) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return ready();
}

void BackgroundRun::signal(int signal) {
  ::kill(pid_, signal);
  signalled_ = Clock::now();
}

std::optional<int> BackgroundRun::wait_for_exit(std::chrono::seconds bound) {
  wait_until([this] { return exited(); }, bound);
  if (running_) return std::nullopt;
  return status_;
}

double BackgroundRun::seconds_to_exit() const { return std::chrono::duration<double>(ended_ - signalled_).count(); }

std::string BackgroundRun::errors() const {
  std::ifstream in(errors_, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

bool BackgroundRun::exited() {
  if (!running_) return true;
  int status = 0;
  if (::waitpid(pid_, &status, WNOHANG) != pid_) return false;
  running_ = false;
  ended_ = Clock::now();
  status_ = WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
  return true;
}

}  // namespace testing_support
