// Files that appear whole or not at all: written under a temporary name, then renamed into place.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string_view>

namespace output {

// Writes `bytes` to `path` atomically (temporary file in the same folder, then rename). Creates the
// folder if needed. Throws std::runtime_error naming the path on failure. A path that exists and is not a
// regular file (/dev/null, a FIFO, a terminal) is written through, never replaced; "-" is standard output.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

// Whether `path` exists and is not a regular file or a folder (a device, a FIFO): outputs write through it.
bool is_written_through(const std::filesystem::path& path);

// Puts the finished `temporary` in place of `path`: renamed onto it (from the same folder), or, when `path` is
// written through (is_written_through), its bytes copied into it and the temporary removed, so that a device
// is never replaced by a regular file. Throws std::runtime_error naming `path` on failure (the temporary is
// then removed).
void move_into_place(const std::filesystem::path& temporary, const std::filesystem::path& path);

// True while process `pid` runs on this machine (a zombie, killed but not yet reaped, does not run; nor does a
// process that is exiting, PF_EXITING).
bool process_runs(pid_t pid);

// The temporary name used for `path` (same folder, so that the rename is atomic): ".NAME.tmpPID".
std::filesystem::path temporary_path_for(const std::filesystem::path& path);

// Removes the temporaries (".NAME.tmpPID" and an ffmpeg log ".NAME.tmpPID.log") that killed processes left in
// `dir`: only those whose process no longer runs on this machine. Returns how many were removed.
int remove_stale_temporaries(const std::filesystem::path& dir);

}  // namespace output
