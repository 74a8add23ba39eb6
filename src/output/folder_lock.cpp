// Output folder locks: Linux open-file-description locks (F_OFD_SETLK) on two bytes of DIR/.softbody-lock.
// Byte 0 is a short guard: whoever holds it checks and takes byte 1 without a race (a shared chunk writes
// the run's identity there first). Byte 1 is the folder: exclusive for a whole run, shared for chunks. The
// kernel releases both when the process ends, however it ends (SIGKILL included); the file is opened
// close-on-exec, so ffmpeg does not inherit it. The last run out removes the file (holding the guard); a run
// that then finds the file it opened removed opens the new one.
#include "output/folder_lock.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <system_error>
#include <thread>

#include "core/errors.hpp"
#include "core/one_line.hpp"
#include "output/atomic_file.hpp"

namespace output {
namespace {

constexpr off_t kGuardByte = 0;
constexpr off_t kFolderByte = 1;

// Sets a lock of `type` (F_RDLCK, F_WRLCK, F_UNLCK) on one byte; `wait` blocks until it is free. Returns
// false when another holds a conflicting lock (without `wait`); throws std::system_error on other failures.
bool set_lock(int fd, short type, off_t byte, bool wait) {
  struct flock lock {};
  lock.l_type = type;
  lock.l_whence = SEEK_SET;
  lock.l_start = byte;
  lock.l_len = 1;
  while (::fcntl(fd, wait ? F_OFD_SETLKW : F_OFD_SETLK, &lock) != 0) {
    if (errno == EINTR) continue;
    if (errno == EAGAIN || errno == EACCES) return false;
    throw std::system_error(errno, std::generic_category());
  }
  return true;
}

// The type of a lock that another open file holds on `byte` and that a write lock would conflict with (F_RDLCK,
// F_WRLCK), or F_UNLCK when there is none.
short conflicting_lock(int fd, off_t byte) {
  struct flock lock {};
  lock.l_type = F_WRLCK;
  lock.l_whence = SEEK_SET;
  lock.l_start = byte;
  lock.l_len = 1;
  if (::fcntl(fd, F_OFD_GETLK, &lock) != 0) throw std::system_error(errno, std::generic_category());
  return lock.l_type;
}

std::string contents(int fd) {
  std::string text(4096, '\0');
  const ssize_t n = ::pread(fd, text.data(), text.size(), 0);
  text.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
  return text;
}

// The lock file's text: the run's identity on the first line, who holds it on the second.
void write_contents(int fd, const std::string& text) {
  if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, text.data(), text.size(), 0) != static_cast<ssize_t>(text.size()))
    throw std::system_error(errno, std::generic_category());
}

std::string holder_words(const std::string& text) {
  const std::size_t line = text.find('\n');
  if (line == std::string::npos || line + 1 >= text.size()) return "";
  std::string holder = text.substr(line + 1);
  if (!holder.empty() && holder.back() == '\n') holder.pop_back();
  return " (" + softbody::one_line(holder) + ")";
}

}  // namespace

FolderLock::FolderLock(const std::filesystem::path& dir, const std::string& run_identity, Sharing sharing,
                       const std::string& holder)
    : path_(dir / kFolderLockName) {
  created_folder_ = std::filesystem::create_directories(dir);
  const std::string identity = run_identity + "\n";
  try {
    open_holding_the_guard();
    // A chunk joins the chunks of its run that hold the folder; otherwise the run takes it alone first.
    bool held = sharing == Sharing::SameRunOnly && contents(fd_).compare(0, identity.size(), identity) == 0 &&
                set_lock(fd_, F_RDLCK, kFolderByte, /*wait=*/false);
    if (!held && take_folder_byte()) {
      held = true;
      write_contents(fd_, identity + "pid " + std::to_string(::getpid()) + ": " + holder + "\n");
      if (sharing == Sharing::SameRunOnly) set_lock(fd_, F_RDLCK, kFolderByte, /*wait=*/false);  // a downgrade
    }
    if (!held) {
      const std::string text = contents(fd_);
      ::close(fd_);
      fd_ = -1;
      throw softbody::InputError(dir.string() + ": another softbody run is writing into this folder" +
                                 holder_words(text) +
                                 "; wait until it ends or choose another folder (-o); only the --frames chunks of "
                                 "one render (the same scene and settings) share a folder");
    }
    set_lock(fd_, F_UNLCK, kGuardByte, /*wait=*/false);
  } catch (const std::system_error& e) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    std::fprintf(stderr, "note: %s: cannot lock the folder (%s): no other run may write into it meanwhile\n",
                 path_.c_str(), e.what());
  }
}

bool FolderLock::take_folder_byte() const {
  // A run that was killed (SIGKILL) a moment ago may still hold the lock: the kernel releases a dead process's
  // files shortly after its parent saw it end. While the pid the file names no longer runs, try again for a
  // while; a holder that runs is answered at once. A shared hold is the chunks of another run (a whole run holds
  // the folder alone): the chunk that wrote its pid may have ended while the others go on, so they are answered at
  // once too.
  constexpr int kTries = 100;
  constexpr auto kPause = std::chrono::milliseconds(50);
  for (int attempt = 1;; ++attempt) {
    if (set_lock(fd_, F_WRLCK, kFolderByte, /*wait=*/false)) return true;
    if (conflicting_lock(fd_, kFolderByte) == F_RDLCK) return false;
    const std::string text = contents(fd_);
    const std::size_t pid_at = text.find("\npid ");
    const long pid = pid_at == std::string::npos ? 0 : std::atol(text.c_str() + pid_at + 5);
    if (attempt == kTries || (pid > 0 && process_runs(static_cast<pid_t>(pid)))) return false;
    std::this_thread::sleep_for(kPause);
  }
}

void FolderLock::open_holding_the_guard() {
  for (;;) {
    std::filesystem::create_directories(path_.parent_path());  // the last holder's folder, if it was empty, went
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) {
      throw std::runtime_error(path_.string() + ": cannot open the folder's lock (" + std::strerror(errno) + ")");
    }
    set_lock(fd_, F_WRLCK, kGuardByte, /*wait=*/true);
    struct stat opened {};
    if (::fstat(fd_, &opened) == 0 && opened.st_nlink > 0) return;
    ::close(fd_);  // the last holder removed this file while this run waited for its guard: open the new one
  }
}

FolderLock::~FolderLock() {
  if (fd_ < 0) return;
  try {
    // The last run out removes the file; a run waiting for the guard meanwhile then opens a new one.
    set_lock(fd_, F_WRLCK, kGuardByte, /*wait=*/true);
    if (set_lock(fd_, F_WRLCK, kFolderByte, /*wait=*/false)) {
      ::unlink(path_.c_str());
      if (created_folder_) ::rmdir(path_.parent_path().c_str());  // fails unless empty
    }
  } catch (const std::system_error&) {
    // Left in place: the next run takes it as it is.
  }
  ::close(fd_);
}

}  // namespace output
