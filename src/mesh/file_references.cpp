// A referenced file: a relative name that stays in the mesh file's folder and names a regular file there.
#include "mesh/file_references.hpp"

#include <cctype>
#include <system_error>

#include "core/errors.hpp"
#include "core/file_kind.hpp"
#include "core/one_line.hpp"

namespace mesh {
namespace {

constexpr const char* kExpected = " (expected the name of a regular file in the mesh file's folder or below it)";

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

std::string in_quotes(std::string_view text) {
  std::string quoted = "\"";  // appended, not "\"" + std::string&&: g++ 12's -Wrestrict misfires on that
  quoted += softbody::one_line(text.substr(0, 200));
  quoted += '"';
  return quoted;
}

// Where `target` really is (every symbolic link on its way followed) lies outside `folder`'s real place.
bool leads_out_of(const std::filesystem::path& target, const std::filesystem::path& folder,
                  std::filesystem::path& real_target) {
  std::error_code ec;
  real_target = std::filesystem::canonical(target, ec);
  if (ec) return false;  // vanished meanwhile: assimp's own open then fails
  const std::filesystem::path real_folder = std::filesystem::canonical(folder.empty() ? "." : folder, ec);
  if (ec) return false;
  const std::filesystem::path inside = real_target.lexically_relative(real_folder);
  return inside.empty() || *inside.begin() == "..";
}

// The checks of a relative name (already decoded), quoted in messages as `named`.
void check_name(std::string_view name, const std::filesystem::path& folder, const std::string& named) {
  if (name.empty()) throw softbody::InputError(named + " names no file" + kExpected);
  if (starts_with_a_scheme(name)) {
    throw softbody::InputError(named + " is a URL or drive letter; softbody reads no file from elsewhere" + kExpected);
  }
  if (name.front() == '/' || name.front() == '\\')
    throw softbody::InputError(named + " is an absolute path" + kExpected);
  if (has_parent_step(name)) throw softbody::InputError(named + " leaves the mesh file's folder" + kExpected);
  std::string relative(name);
  for (char& c : relative) c = c == '\\' ? '/' : c;
  const std::filesystem::path target = folder / relative;
  if (const std::string words = softbody::non_regular_file_words(target); !words.empty()) {
    throw softbody::InputError(named + " names " + softbody::one_line(target.string()) + ", which " + words +
                               kExpected);
  }
  // A symbolic link in the folder (the file's own, or a folder's on the way) may lead anywhere.
  if (std::filesystem::path real; leads_out_of(target, folder, real)) {
    throw softbody::InputError(named + " names " + softbody::one_line(target.string()) +
                               ", a symbolic link that leads out of the mesh file's folder (to " +
                               softbody::one_line(real.string()) + ")" + kExpected);
  }
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

void check_referenced_file(std::string_view reference, const std::filesystem::path& folder, const std::string& where) {
  check_name(reference, folder, where + " " + in_quotes(reference));
}

std::string percent_decoded(std::string_view uri, const std::string& where) {
  std::string decoded;
  decoded.reserve(uri.size());
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] != '%') {
      decoded += uri[i];
      continue;
    }
    const int high = i + 2 < uri.size() ? hex_digit(uri[i + 1]) : -1, low = high >= 0 ? hex_digit(uri[i + 2]) : -1;
    if (high < 0 || low < 0 || high * 16 + low == 0) {
      throw softbody::InputError(where + " " + in_quotes(uri) + " has a '%' at character " + std::to_string(i + 1) +
                                 " that is not a percent-encoded byte (expected '%' and two hexadecimal digits, not "
                                 "%00; a '%' in a file name is written %25)");
    }
    decoded += static_cast<char>(high * 16 + low);
    i += 2;
  }
  return decoded;
}

void check_referenced_uri(std::string_view uri, const std::filesystem::path& folder, const std::string& where) {
  const std::string decoded = percent_decoded(uri, where);
  check_name(decoded, folder,
             where + " " + in_quotes(uri) + (decoded == uri ? "" : " (decoded: " + in_quotes(decoded) + ")"));
}

}  // namespace mesh
