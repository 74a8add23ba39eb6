// A referenced file: a relative name that stays in the mesh file's folder and names a regular file there.
#include "mesh/file_references.hpp"

#include <cctype>

#include "core/errors.hpp"
#include "core/file_kind.hpp"
#include "core/one_line.hpp"

namespace mesh {
namespace {

// "http:", "file:", "C:": a URI scheme (RFC 3986 §3.1: a letter, then letters, digits, '+', '-', '.'), then ':'.
bool starts_with_a_scheme(std::string_view reference) {
  const std::size_t colon = reference.find(':');
  if (colon == std::string_view::npos || colon == 0 || !std::isalpha(static_cast<unsigned char>(reference[0]))) {
    return false;
  }
  for (std::size_t i = 1; i < colon; ++i) {
    const char c = reference[i];
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '+' && c != '-' && c != '.') return false;
  }
  return true;
}

// True when one of the names between '/' or '\' (assimp takes both as separators) is "..".
bool has_parent_step(std::string_view reference) {
  std::size_t start = 0;
  while (start <= reference.size()) {
    std::size_t end = reference.find_first_of("/\\", start);
    if (end == std::string_view::npos) end = reference.size();
    if (reference.substr(start, end - start) == "..") return true;
    start = end + 1;
  }
  return false;
}

}  // namespace

void check_referenced_file(std::string_view reference, const std::filesystem::path& folder, const std::string& where) {
  const std::string named = where + " \"" + softbody::one_line(reference.substr(0, 200)) + "\"";
  const std::string expected = " (expected the name of a regular file in the mesh file's folder or below it)";
  if (reference.empty()) throw softbody::InputError(named + " names no file" + expected);
  if (starts_with_a_scheme(reference)) {
    throw softbody::InputError(named + " is a URL or drive letter; softbody reads no file from elsewhere" + expected);
  }
  if (reference.front() == '/' || reference.front() == '\\') {
    throw softbody::InputError(named + " is an absolute path" + expected);
  }
  if (has_parent_step(reference)) throw softbody::InputError(named + " leaves the mesh file's folder" + expected);
  std::string relative(reference);
  for (char& c : relative) c = c == '\\' ? '/' : c;
  const std::filesystem::path target = folder / relative;
  if (const std::string words = softbody::non_regular_file_words(target); !words.empty()) {
    throw softbody::InputError(named + " names " + softbody::one_line(target.string()) + ", which " + words + expected);
  }
}

}  // namespace mesh
