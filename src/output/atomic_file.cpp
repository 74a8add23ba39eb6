// Atomic file writes.
#include "output/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "core/one_line.hpp"
#include "frames/stop_request.hpp"

namespace output {

std::filesystem::path temporary_path_for(const std::filesystem::path& path) {
  std::string name = path.filename().string();
  name.insert(0, 1, '.');
  name += ".tmp";
  name += std::to_string(::getpid());
  return path.parent_path() / name;
}

bool process_runs(pid_t pid) {
  if (::kill(pid, 0) != 0 && errno != EPERM) return false;
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text;
  std::getline(stat, text);
  const std::size_t paren = text.rfind(')');  // "pid (comm) S ppid pgrp session tty tpgid flags ...": after the name
  if (paren == std::string::npos || paren + 2 >= text.size()) return true;
  if (text[paren + 2] == 'Z' || text[paren + 2] == 'X') return false;
  // A process that a signal killed but that is still tearing itself down (closing its files, releasing its locks)
  // is no longer running: the kernel marks it PF_EXITING in its flags, the sixth field after the state. A killer
  // that does not wait for it (`timeout -s KILL` kills itself with its process group) returns before that ends.
  std::istringstream fields(text.substr(paren + 2));
  std::string skipped;
  for (int k = 0; k < 6; ++k) fields >> skipped;  // state, ppid, pgrp, session, tty_nr, tpgid
  unsigned long long flags = 0;                   // stays 0 (running) where the field cannot be read
  fields >> flags;
  constexpr unsigned long long kExiting = 0x4;  // PF_EXITING (include/linux/sched.h)
  return (flags & kExiting) == 0;
}

int remove_stale_temporaries(const std::filesystem::path& dir) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) return 0;
  int removed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    std::string name = entry.path().filename().string();
    if (name.size() < 2 || name[0] != '.') continue;
    if (name.size() > 4 && name.compare(name.size() - 4, 4, ".log") == 0) name.resize(name.size() - 4);
    const std::size_t tmp = name.rfind(".tmp");
    if (tmp == std::string::npos || tmp + 4 == name.size()) continue;
    const std::string digits = name.substr(tmp + 4);
    if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    const auto pid = static_cast<pid_t>(std::stol(digits));
    if (pid == ::getpid() || process_runs(pid)) continue;  // its writer still runs
    if (std::filesystem::remove(entry.path(), ec)) ++removed;
  }
  return removed;
}

namespace {

[[noreturn]] void throw_stopped_while_writing(const std::string& output) {
  throw frames::Interrupted::while_writing(frames::stop_signal(), softbody::one_line(output));
}

// Opens an existing device or FIFO for writing (null on failure, errno set). Opening a FIFO waits for a reader:
// a stop request (SIGINT, SIGTERM) ends the wait, and once one was made it does not wait at all (a FIFO without
// a reader gets nothing); both throw frames::Interrupted, so that the run ends with 128 + the signal.
std::FILE* open_to_write_through(const std::filesystem::path& path) {
  for (;;) {
    const bool stopping = frames::stop_requested();
    const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | (stopping ? O_NONBLOCK : 0));
    if (fd >= 0) {
      if (stopping) ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);  // writes wait for the reader again
      std::FILE* file = ::fdopen(fd, "wb");
      if (file == nullptr) ::close(fd);
      return file;
    }
    if (frames::stop_requested() && (errno == EINTR || errno == ENXIO)) throw_stopped_while_writing(path.string());
    if (errno != EINTR) return nullptr;
  }
}

// Standard output or an existing non-regular file (a device, a FIFO): written in place, never renamed onto.
void write_through(const std::filesystem::path& path, std::string_view bytes) {
  const bool to_stdout = path == "-";
  const std::string name = to_stdout ? std::string("standard output") : path.string();
  std::FILE* out = to_stdout ? stdout : open_to_write_through(path);
  if (out == nullptr) throw std::runtime_error(path.string() + ": cannot write (" + std::strerror(errno) + ")");
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), out) == bytes.size();
  const bool flushed = to_stdout ? std::fflush(out) == 0 : std::fclose(out) == 0;
  if (!written || !flushed) {
    const int error = errno;
    if (frames::stop_requested()) throw_stopped_while_writing(name);  // a write waiting for the reader, ended
    throw std::runtime_error(name + ": write failed (" + std::strerror(error) + ")");
  }
}

}  // namespace

bool is_written_through(const std::filesystem::path& path) {
  std::error_code ec;
  const auto type = std::filesystem::status(path, ec).type();
  return type != std::filesystem::file_type::not_found && type != std::filesystem::file_type::regular &&
         type != std::filesystem::file_type::directory && type != std::filesystem::file_type::none;
}

void move_into_place(const std::filesystem::path& temporary, const std::filesystem::path& path) {
  std::error_code ec;
  if (!is_written_through(path)) {
    std::filesystem::rename(temporary, path, ec);
    if (!ec) return;
    std::filesystem::remove(temporary);
    throw std::runtime_error(path.string() + ": cannot rename into place (" + ec.message() + ")");
  }
  std::ifstream in(temporary, std::ios::binary);
  std::FILE* out = nullptr;
  try {
    out = open_to_write_through(path);
  } catch (const frames::Interrupted&) {
    std::filesystem::remove(temporary, ec);
    throw;
  }
  bool written = in && out != nullptr;
  const int open_errno = errno;
  std::vector<char> chunk(1 << 20);
  while (written && in) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    const auto count = static_cast<std::size_t>(in.gcount());
    written = std::fwrite(chunk.data(), 1, count, out) == count;
  }
  const bool closed = out != nullptr && std::fclose(out) == 0;
  const int write_errno = out == nullptr ? open_errno : errno;
  std::filesystem::remove(temporary, ec);
  if ((!written || !closed) && frames::stop_requested()) throw_stopped_while_writing(path.string());
  if (!written || !closed)
    throw std::runtime_error(path.string() + ": cannot write (" + std::strerror(write_errno) + ")");
}

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
  if (path == "-" || is_written_through(path)) {
    write_through(path, bytes);
    return;
  }
  if (!path.parent_path().empty()) std::filesystem::create_directories(path.parent_path());
  const std::filesystem::path temporary = temporary_path_for(path);
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(path.string() + ": cannot write (" + std::strerror(errno) + ")");
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) {
      std::filesystem::remove(temporary);
      throw std::runtime_error(path.string() + ": write failed (disk full?)");
    }
  }
  move_into_place(temporary, path);
}

}  // namespace output
