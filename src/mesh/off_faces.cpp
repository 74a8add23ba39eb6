// The OFF body walked line by line as assimp's OFF reader does, so the indices checked are the ones it reads.
#include "mesh/off_faces.hpp"

#include <cstdint>
#include <string>

#include "core/errors.hpp"

namespace mesh {
namespace {

class OffText {
 public:
  explicit OffText(std::string_view text) : text_(text) {}

  bool at_end() const { return at_ >= text_.size() || text_[at_] == '\0'; }
  bool starts_with(std::string_view word) const { return text_.substr(at_, word.size()) == word; }
  void skip(std::size_t bytes) { at_ += bytes; }

  // Blanks and line ends, then whole lines that start with '#' or are empty (assimp's NextToken).
  void next_token() {
    skip_blanks_and_line_ends();
    while (!at_end() && (text_[at_] == '#' || text_[at_] == '\n' || text_[at_] == '\r')) {
      while (!at_end() && !is_line_end(text_[at_])) ++at_;
      skip_blanks_and_line_ends();
    }
  }

  // Decimal digits (none: 0), as assimp's strtoul10; `digits` tells how many.
  std::uint64_t number(int& digits) {
    std::uint64_t value = 0;
    digits = 0;
    while (at_ < text_.size() && text_[at_] >= '0' && text_[at_] <= '9') {
      if (digits < 19) value = value * 10 + static_cast<std::uint64_t>(text_[at_] - '0');
      ++digits;
      ++at_;
    }
    return value;
  }

  // The next line (assimp's GetNextLine: up to a line end, then every line end after it); false at the end.
  bool next_line(std::string_view& line) {
    if (at_end()) return false;
    const std::size_t start = at_;
    while (at_ < text_.size() && !is_line_end(text_[at_])) ++at_;
    line = text_.substr(start, at_ - start);
    while (at_ < text_.size() && is_line_end(text_[at_]) && text_[at_] != '\0') ++at_;
    return true;
  }

 private:
  static bool is_line_end(char c) { return c == '\n' || c == '\r' || c == '\0' || c == '\f'; }
  void skip_blanks_and_line_ends() {
    while (at_ < text_.size() && (text_[at_] == ' ' || text_[at_] == '\t' || is_line_end(text_[at_])) &&
           text_[at_] != '\0') {
      ++at_;
    }
  }

  std::string_view text_;
  std::size_t at_ = 0;
};

}  // namespace

void check_off_face_indices(std::string_view text) {
  OffText off(text);
  off.next_token();
  bool dimension = false;
  for (const std::string_view prefix : {"ST", "C", "N", "4", "n"}) {
    if (off.starts_with(prefix)) {
      off.skip(prefix.size());
      dimension = prefix == "n";
    }
  }
  if (off.starts_with("OFF")) off.skip(3);
  off.next_token();
  int digits = 0;
  if (dimension) {
    off.number(digits);
    off.next_token();
  }
  off.next_token();
  const std::uint64_t vertices = off.number(digits);
  off.next_token();
  const std::uint64_t faces = off.number(digits);
  off.next_token();
  off.number(digits);  // the edge count
  off.next_token();
  if (vertices == 0 || faces == 0) return;  // assimp refuses those itself
  std::string_view line;
  for (std::uint64_t v = 0; v < vertices; ++v) {
    if (!off.next_line(line)) return;  // too few lines: assimp says so
  }
  for (std::uint64_t f = 0; f < faces && off.next_line(line); ++f) {
    OffText face(line);
    face.next_token();
    const std::uint64_t corners = face.number(digits);
    if (corners == 0 || corners > 9) continue;  // assimp skips such a face
    for (std::uint64_t k = 0; k < corners; ++k) {
      face.next_token();
      const std::uint64_t index = face.number(digits);
      if (digits > 10 || index >= vertices) {
        const std::string named = digits > 10 ? "of more than 10 digits" : std::to_string(index);
        throw softbody::InputError("is an OFF file whose face " + std::to_string(f) + " names vertex index " + named +
                                   ", past its " + std::to_string(vertices) + " vertices (expected indices from 0 to " +
                                   std::to_string(vertices - 1) + ")");
      }
    }
  }
}

}  // namespace mesh
