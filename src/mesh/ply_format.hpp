// What the PLY header check and the strip reader both read: a header line's words, a scalar type's size and
// kind, and an integer in the file's byte order.
#pragma once

#include <array>
#include <cctype>
#include <string_view>
#include <vector>

namespace mesh::ply {

// `line` split into whitespace-separated words.
inline std::vector<std::string_view> words_of(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const std::size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

// Bytes of a PLY scalar type, 0 for an unknown name; `kind` (when given) says what it holds: 'i' a signed
// integer, 'u' an unsigned one, 'f' a floating-point number.
inline int type_bytes(std::string_view type, char* kind) {
  struct Type {
    std::string_view name;
    int bytes;
    char kind;
  };
  static constexpr std::array<Type, 16> kTypes{{{"char", 1, 'i'},
                                                {"uchar", 1, 'u'},
                                                {"short", 2, 'i'},
                                                {"ushort", 2, 'u'},
                                                {"int", 4, 'i'},
                                                {"uint", 4, 'u'},
                                                {"float", 4, 'f'},
                                                {"double", 8, 'f'},
                                                {"int8", 1, 'i'},
                                                {"uint8", 1, 'u'},
                                                {"int16", 2, 'i'},
                                                {"uint16", 2, 'u'},
                                                {"int32", 4, 'i'},
                                                {"uint32", 4, 'u'},
                                                {"float32", 4, 'f'},
                                                {"float64", 8, 'f'}}};
  for (const Type& t : kTypes) {
    if (t.name == type) {
      if (kind) *kind = t.kind;
      return t.bytes;
    }
  }
  return 0;
}

// The `bytes` bytes at `p` as an unsigned integer in the file's byte order.
inline unsigned long long unsigned_at(const unsigned char* p, int bytes, bool big_endian) {
  unsigned long long n = 0;
  for (int i = 0; i < bytes; ++i) n = (n << 8) | p[big_endian ? i : bytes - 1 - i];
  return n;
}

}  // namespace mesh::ply
