// Run manifests: a text file of checked lines.
//   softbody run manifest 1
//   scene 1b6df5f72703e973
//   setting render.width = 160            (one line per output setting, in order)
//   file frame_0000.png 8966 5d0c...      (name, size in bytes, XXH3-64 of the bytes)
#include "output/run_manifest.hpp"

#include <fstream>
#include <stdexcept>

#include "core/errors.hpp"
#include "output/atomic_file.hpp"
#include "output/checked_line.hpp"

namespace output {
namespace {

constexpr std::string_view kFormatLine = "softbody run manifest 1";

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

bool starts_with(std::string_view text, std::string_view prefix) { return text.substr(0, prefix.size()) == prefix; }

}  // namespace

RunManifest::RunManifest(RunManifest&& other) noexcept { *this = std::move(other); }

RunManifest& RunManifest::operator=(RunManifest&& other) noexcept {
  if (this == &other) return *this;
  if (append_) std::fclose(append_);
  path_ = std::move(other.path_);
  intact_ = other.intact_;
  scene_ = std::move(other.scene_);
  settings_ = std::move(other.settings_);
  files_ = std::move(other.files_);
  append_ = std::exchange(other.append_, nullptr);
  return *this;
}

RunManifest::~RunManifest() {
  if (append_) std::fclose(append_);
}

RunManifest RunManifest::read(const std::filesystem::path& path, const std::string& scene) {
  RunManifest manifest;
  manifest.path_ = path;
  const std::string text = read_bytes(path);
  bool header = true;  // the format, scene and setting lines come first; all must hold
  int line_number = 0;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) break;  // a line cut short: dropped
    const std::optional<std::string_view> line = checked_text(std::string_view(text).substr(start, end - start));
    start = end + 1;
    ++line_number;
    if (line_number == 1) {
      if (!line || *line != kFormatLine) return manifest;
      continue;
    }
    if (header && (!line || starts_with(*line, "scene ") || starts_with(*line, "setting "))) {
      if (!line) return manifest;  // a damaged header vouches for nothing
      if (starts_with(*line, "scene ")) {
        manifest.scene_ = line->substr(6);
      } else {
        const std::string_view setting = line->substr(8);
        const std::size_t equals = setting.find(" = ");
        if (equals == std::string_view::npos) return manifest;
        manifest.settings_.emplace_back(setting.substr(0, equals), setting.substr(equals + 3));
      }
      continue;
    }
    header = false;
    if (!line || !starts_with(*line, "file ")) continue;
    // "file NAME SIZE CHECKSUM": the name may hold spaces, the last two fields do not.
    const std::string_view fields = line->substr(5);
    const std::size_t last = fields.rfind(' ');
    const std::size_t middle = last == std::string_view::npos ? last : fields.rfind(' ', last - 1);
    if (middle == std::string_view::npos || middle == 0) continue;
    FileEntry entry;
    entry.size = std::stoull(std::string(fields.substr(middle + 1, last - middle - 1)));
    entry.checksum = fields.substr(last + 1);
    manifest.files_[std::string(fields.substr(0, middle))] = entry;
  }
  manifest.intact_ = line_number > 0 && manifest.scene_ == scene;
  return manifest;
}

void RunManifest::check_settings(const Settings& settings) const {
  const auto value_in = [](const Settings& list, const std::string& key) -> std::optional<std::string> {
    for (const auto& [k, v] : list)
      if (k == key) return v;
    return std::nullopt;
  };
  const auto refuse = [&](const std::string& key, const std::optional<std::string>& now,
                          const std::optional<std::string>& then) {
    throw softbody::InputError(path_.string() + ": --resume: " + key + " is " + now.value_or("not set") + " now but " +
                               then.value_or("not set") +
                               " in the run it continues; resume with the same settings, or run without --resume "
                               "to start again");
  };
  for (const auto& [key, value] : settings) {
    const std::optional<std::string> then = value_in(settings_, key);
    if (then != value) refuse(key, value, then);
  }
  for (const auto& [key, value] : settings_) {
    if (!value_in(settings, key)) refuse(key, std::nullopt, value);
  }
}

bool RunManifest::vouches_for(const std::filesystem::path& dir, const std::string& name) const {
  const auto entry = files_.find(name);
  if (!intact_ || entry == files_.end()) return false;
  std::error_code ec;
  if (std::filesystem::file_size(dir / name, ec) != entry->second.size || ec) return false;
  return checksum_hex(read_bytes(dir / name)) == entry->second.checksum;
}

std::string RunManifest::file_line(const std::string& name, const FileEntry& entry) {
  return checked_line("file " + name + " " + std::to_string(entry.size) + " " + entry.checksum);
}

void RunManifest::start(const std::filesystem::path& path, const std::string& scene, const Settings& settings,
                        const std::vector<std::string>& keep) {
  std::string text = checked_line(kFormatLine) + checked_line("scene " + scene);
  for (const auto& [key, value] : settings) text += checked_line("setting " + key + " = " + value);
  std::map<std::string, FileEntry> kept;
  for (const std::string& name : keep) {
    const auto entry = files_.find(name);
    if (entry == files_.end()) continue;
    text += file_line(name, entry->second);
    kept.insert(*entry);
  }
  write_file_atomically(path, text);
  if (append_) std::fclose(append_);
  append_ = std::fopen(path.c_str(), "ab");
  if (!append_) throw std::runtime_error(path.string() + ": cannot open the run manifest for appending");
  path_ = path;
  intact_ = true;
  scene_ = scene;
  settings_ = settings;
  files_ = std::move(kept);
}

void RunManifest::add(const std::string& name, std::string_view bytes) {
  const FileEntry entry{bytes.size(), checksum_hex(bytes)};
  const std::string line = file_line(name, entry);
  if (!append_ || std::fwrite(line.data(), 1, line.size(), append_) != line.size() || std::fflush(append_) != 0)
    throw std::runtime_error(path_.string() + ": cannot append to the run manifest");
  files_[name] = entry;
}

}  // namespace output
