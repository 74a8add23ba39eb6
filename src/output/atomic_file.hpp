// Files that appear whole or not at all: written under a temporary name, then renamed into place.
#pragma once

#include <filesystem>
#include <string_view>

namespace output {

// Writes `bytes` to `path` atomically (temporary file in the same folder, then rename). Creates the
// folder if needed. Throws std::runtime_error naming the path on failure.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

// The temporary name used for `path` (same folder, so that the rename is atomic): ".NAME.tmpPID".
std::filesystem::path temporary_path_for(const std::filesystem::path& path);

// Removes the temporaries (".NAME.tmpPID" and an ffmpeg log ".NAME.tmpPID.log") that killed processes left in
// `dir`: only those whose process no longer runs on this machine. Returns how many were removed.
int remove_stale_temporaries(const std::filesystem::path& dir);

}  // namespace output
