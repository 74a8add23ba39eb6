// Telling regular files from directories, FIFOs and devices before anything reads them.
#include "core/file_kind.hpp"

#include "core/errors.hpp"

namespace softbody {

std::string non_regular_file_words(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  switch (status.type()) {
    case fs::file_type::regular: return "";
    case fs::file_type::not_found: return "does not exist";
    case fs::file_type::directory: return "is a directory";
    case fs::file_type::fifo: return "is a FIFO (named pipe)";
    case fs::file_type::character: return "is a character device";
    case fs::file_type::block: return "is a block device";
    case fs::file_type::socket: return "is a socket";
    default: return ec ? "cannot be examined (" + ec.message() + ")" : "is not a regular file";
  }
}

void require_regular_file(const std::filesystem::path& path, std::uintmax_t max_bytes, const std::string& what,
                          const std::string& raise_hint) {
  if (const std::string words = non_regular_file_words(path); !words.empty()) {
    throw InputError(path.string() + ": cannot open the " + what + " (it " + words + "; expected a regular file)");
  }
  std::error_code ec;
  const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
  if (ec) throw InputError(path.string() + ": cannot open the " + what + " (" + ec.message() + ")");
  if (bytes > max_bytes) {
    throw InputError(path.string() + ": the " + what + " has " + std::to_string(bytes) +
                     " bytes, more than the limit of " + std::to_string(max_bytes) +
                     (raise_hint.empty() ? "" : " (" + raise_hint + ")"));
  }
}

}  // namespace softbody
