// The manifest of a resumable run: the scene's hash, the output settings and, as each lands, every output
// file's size and checksum, so that --resume keeps only files that are exactly what the run wrote, and refuses
// to continue a run whose output settings differ. Every line carries its checksum (output/checked_line.hpp):
// the header is written whole (atomically), each file's line appended with one write once the file is in place.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace output {

class RunManifest {
 public:
  using Settings = std::vector<std::pair<std::string, std::string>>;

  // Reads the manifest at `path`. A missing one, one whose header is damaged, or one of a scene other than
  // `scene` (its hash) reads as not intact(): it vouches for no file. A damaged file line is dropped (that file
  // is not vouched for).
  static RunManifest read(const std::filesystem::path& path, const std::string& scene);

  RunManifest() = default;
  RunManifest(RunManifest&& other) noexcept;
  RunManifest& operator=(RunManifest&& other) noexcept;
  RunManifest(const RunManifest&) = delete;
  RunManifest& operator=(const RunManifest&) = delete;
  ~RunManifest();

  bool intact() const { return intact_; }

  // Throws softbody::InputError naming the manifest and the first key whose value differs between the
  // manifest's settings and `settings` (a key only one of them has counts as differing).
  void check_settings(const Settings& settings) const;

  // Whether `dir / name` holds the bytes this manifest lists for it (size and checksum).
  bool vouches_for(const std::filesystem::path& dir, const std::string& name) const;

  // Writes a new manifest at `path` (atomically): the scene, the settings and the lines of the files in `keep`
  // that this manifest lists; later files are added with add().
  void start(const std::filesystem::path& path, const std::string& scene, const Settings& settings,
             const std::vector<std::string>& keep);

  // Appends the line of file `name` holding `bytes` (after start()). Throws std::runtime_error on failure.
  void add(const std::string& name, std::string_view bytes);

 private:
  struct FileEntry {
    std::uint64_t size = 0;
    std::string checksum;  // 16 hexadecimal digits
  };
  static std::string file_line(const std::string& name, const FileEntry& entry);

  std::filesystem::path path_;
  bool intact_ = false;
  std::string scene_;
  Settings settings_;
  std::map<std::string, FileEntry> files_;
  std::FILE* append_ = nullptr;
};

}  // namespace output
