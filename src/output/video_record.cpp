// The video record: one checked line, "video SIZE XXH3-64 NAME" (the name last: it may hold spaces).
#include "output/video_record.hpp"

#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <system_error>

#include "output/atomic_file.hpp"
#include "output/checked_line.hpp"

namespace output {
namespace {

std::optional<std::string> read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::string bytes{std::istreambuf_iterator<char>(in), {}};
  if (in.bad()) return std::nullopt;
  return bytes;
}

// "SIZE XXH3-64" of the file at `path`, or nothing when it cannot be read.
std::optional<std::string> fingerprint(const std::filesystem::path& path) {
  const std::optional<std::string> bytes = read_bytes(path);
  if (!bytes) return std::nullopt;
  return std::to_string(bytes->size()) + " " + checksum_hex(*bytes);
}

}  // namespace

void record_video(const std::filesystem::path& dir, const std::filesystem::path& video) {
  const std::filesystem::path record = dir / kVideoRecordName;
  std::error_code ec;
  const std::string name = video.filename().string();
  const bool in_dir = std::filesystem::is_regular_file(video, ec) && !name.empty() &&
                      name.find('\n') == std::string::npos &&
                      std::filesystem::equivalent(video.parent_path().empty() ? "." : video.parent_path(), dir, ec);
  const std::optional<std::string> print = in_dir ? fingerprint(video) : std::nullopt;
  if (!print) {
    std::filesystem::remove(record, ec);
    return;
  }
  write_file_atomically(record, checked_line("video " + *print + " " + name));
}

std::string remove_recorded_video(const std::filesystem::path& dir) {
  const std::filesystem::path record = dir / kVideoRecordName;
  const std::optional<std::string> text = read_bytes(record);
  if (!text) return "";
  std::error_code ec;
  std::filesystem::remove(record, ec);
  const std::optional<std::string_view> line =
      text->empty() ? std::nullopt : checked_text(std::string_view(*text).substr(0, text->size() - 1));
  if (!line || line->rfind("video ", 0) != 0) return "";
  // "video SIZE CHECKSUM NAME": the name follows the third space.
  const std::size_t size_end = line->find(' ', 6);
  const std::size_t checksum_end = size_end == std::string_view::npos ? size_end : line->find(' ', size_end + 1);
  if (checksum_end == std::string_view::npos) return "";
  const std::string print(line->substr(6, checksum_end - 6)), name(line->substr(checksum_end + 1));
  const std::filesystem::path video = dir / name;
  if (name.find('/') != std::string::npos || !std::filesystem::is_regular_file(video, ec) ||
      fingerprint(video) != print)
    return "";
  return std::filesystem::remove(video, ec) ? video.string() : "";
}

}  // namespace output
