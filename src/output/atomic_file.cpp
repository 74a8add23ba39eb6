// Atomic file writes.
#include "output/atomic_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace output {

std::filesystem::path temporary_path_for(const std::filesystem::path& path) {
  std::string name = path.filename().string();
  name.insert(0, 1, '.');
  name += ".tmp";
  name += std::to_string(::getpid());
  return path.parent_path() / name;
}

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
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
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::filesystem::remove(temporary);
    throw std::runtime_error(path.string() + ": cannot rename into place (" + ec.message() + ")");
  }
}

}  // namespace output
