// What a path names when it is not a regular file (a directory, a FIFO, a device), for messages that say so.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace softbody {

// "" for a regular file (symbolic links followed); otherwise the words for what it is: "does not exist",
// "is a directory", "is a FIFO (named pipe)", "is a character device", "is a block device", "is a socket",
// "is not a regular file".
std::string non_regular_file_words(const std::filesystem::path& path);

// Throws InputError("PATH: cannot open the `what` (it is a directory; ...)") unless `path` is a regular file
// of at most `max_bytes` bytes; the message names the limit and how to raise it (`raise_hint`, may be empty).
void require_regular_file(const std::filesystem::path& path, std::uintmax_t max_bytes, const std::string& what,
                          const std::string& raise_hint);

}  // namespace softbody
