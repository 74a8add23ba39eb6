// PLY triangle strips turned into a face element (see ply_strips.hpp).
#include "mesh/ply_strips.hpp"

#include <array>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <vector>

#include "core/errors.hpp"
#include "mesh/ply_format.hpp"

namespace mesh {
namespace {

struct Property {
  int bytes = 0;           // a scalar's bytes, or a list item's
  int count_bytes = 0;     // a list's count: its bytes; 0 for a scalar
  bool is_signed = false;  // a list item's type is a signed integer
  bool is_float = false;   // a list item's (or a list count's) type is floating-point: not walked
};

struct Element {
  std::string_view name;
  long long count = 0;
  std::vector<Property> properties;
  std::size_t header_line = 0, header_end = 0;  // its "element" line and where its last property line ends
};

struct Header {
  bool ascii = false, big_endian = false;
  std::vector<Element> elements;
  std::size_t body = 0;  // the first byte after "end_header" and its line end
};

// Bytes of a PLY scalar type (0: unknown); `is_signed` / `is_float` say what it holds.
int type_bytes(std::string_view type, bool* is_signed, bool* is_float) {
  char kind = 'u';
  const int bytes = ply::type_bytes(type, &kind);
  *is_signed = kind == 'i';
  *is_float = kind == 'f';
  return bytes;
}

std::optional<Header> parse_header(std::string_view whole) {
  Header header;
  std::size_t at = 0;
  bool format_seen = false;
  while (at < whole.size()) {
    const std::size_t end = whole.find('\n', at);
    if (end == std::string_view::npos) return std::nullopt;
    const std::vector<std::string_view> words = ply::words_of(whole.substr(at, end - at));
    const std::size_t line = at;
    at = end + 1;
    if (words.empty()) continue;
    if (words[0] == "end_header") {
      header.body = at;
      return format_seen ? std::optional<Header>(header) : std::nullopt;
    }
    if (words[0] == "format" && words.size() == 3) {
      format_seen = true;
      header.ascii = words[1] == "ascii";
      header.big_endian = words[1] == "binary_big_endian";
    } else if (words[0] == "element" && words.size() == 3) {
      Element e;
      e.name = words[1];
      if (words[2].size() > 18 || words[2].find_first_not_of("0123456789") != std::string_view::npos)
        return std::nullopt;
      e.count = std::stoll(std::string(words[2]));  // at most 18 digits: no overflow
      e.header_line = line;
      e.header_end = at;
      header.elements.push_back(e);
    } else if (words[0] == "property" && !header.elements.empty()) {
      Property p;
      bool count_signed = false, count_float = false;
      if (words.size() == 5 && words[1] == "list") {
        p.count_bytes = type_bytes(words[2], &count_signed, &count_float);
        p.bytes = type_bytes(words[3], &p.is_signed, &p.is_float);
        if (p.count_bytes == 0 || count_float) return std::nullopt;
      } else if (words.size() == 3) {
        p.bytes = type_bytes(words[1], &p.is_signed, &p.is_float);
      } else {
        return std::nullopt;
      }
      if (p.bytes == 0) return std::nullopt;
      header.elements.back().properties.push_back(p);
      header.elements.back().header_end = at;
    }
  }
  return std::nullopt;
}

// An integer of `bytes` bytes at `p` in the file's byte order.
long long integer_at(const unsigned char* p, int bytes, bool is_signed, bool big_endian) {
  const unsigned long long raw = ply::unsigned_at(p, bytes, big_endian);
  if (!is_signed) return static_cast<long long>(raw);
  const unsigned long long sign = 1ULL << (8 * bytes - 1);
  return static_cast<long long>(raw ^ sign) - static_cast<long long>(sign);
}

// Reads a body row by row: binary by the properties' sizes, ascii one whitespace-separated word per value
// (a row need not be one line). Every read is checked against the end of the body.
class BodyReader {
 public:
  BodyReader(std::string_view body, const Header& header) : body_(body), header_(header) {}
  std::size_t at() const { return at_; }

  // Skips one value of `bytes` bytes (binary) or one word (ascii).
  bool skip(int bytes) {
    if (header_.ascii) return word().has_value();
    if (body_.size() - at_ < static_cast<std::size_t>(bytes)) return false;
    at_ += static_cast<std::size_t>(bytes);
    return true;
  }
  // An integer value of `bytes` bytes (binary) or an integer word (ascii).
  std::optional<long long> integer(int bytes, bool is_signed) {
    if (header_.ascii) {
      const std::optional<std::string_view> w = word();
      if (!w || w->size() > 20) return std::nullopt;
      const std::string text(*w);
      char* stop = nullptr;
      const long long value = std::strtoll(text.c_str(), &stop, 10);
      if (*stop != '\0') return std::nullopt;
      return value;
    }
    if (body_.size() - at_ < static_cast<std::size_t>(bytes)) return std::nullopt;
    const long long value =
        integer_at(reinterpret_cast<const unsigned char*>(body_.data() + at_), bytes, is_signed, header_.big_endian);
    at_ += static_cast<std::size_t>(bytes);
    return value;
  }
  // Skips a whole row of `e`.
  bool skip_row(const Element& e) {
    for (const Property& p : e.properties) {
      if (p.count_bytes == 0) {
        if (!skip(p.bytes)) return false;
        continue;
      }
      const std::optional<long long> n = integer(p.count_bytes, false);
      if (!n || *n < 0) return false;
      if (!header_.ascii &&
          static_cast<unsigned long long>(*n) > (body_.size() - at_) / static_cast<std::size_t>(p.bytes))
        return false;
      for (long long i = 0; i < *n; ++i) {
        if (!skip(p.bytes)) return false;
      }
    }
    return true;
  }

 private:
  std::optional<std::string_view> word() {
    while (at_ < body_.size() && std::isspace(static_cast<unsigned char>(body_[at_]))) ++at_;
    const std::size_t start = at_;
    while (at_ < body_.size() && !std::isspace(static_cast<unsigned char>(body_[at_]))) ++at_;
    if (at_ == start) return std::nullopt;
    return body_.substr(start, at_ - start);
  }

  std::string_view body_;
  const Header& header_;
  std::size_t at_ = 0;
};

// The strips' triangles (see ply_strips.hpp): a strip ends at -1 and at the end of its row.
void add_strip_triangles(const std::vector<long long>& strip, std::vector<std::array<long long, 3>>& triangles) {
  for (std::size_t k = 0; k + 2 < strip.size(); ++k) {
    std::array<long long, 3> t{strip[k], strip[k + 1], strip[k + 2]};
    if (k % 2 == 1) std::swap(t[0], t[1]);
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) triangles.push_back(t);
  }
}

void append_integer(std::string& out, long long value, int bytes, bool big_endian) {
  const auto raw = static_cast<unsigned long long>(value);
  for (int i = 0; i < bytes; ++i) {
    const int shift = 8 * (big_endian ? bytes - 1 - i : i);
    out.push_back(static_cast<char>((raw >> shift) & 0xFF));
  }
}

}  // namespace

std::string faces_from_strips(std::string_view whole, long long max_triangles) {
  const std::optional<Header> header = parse_header(whole);
  if (!header) return "";
  std::size_t strips = header->elements.size(), strip_elements = 0;
  for (std::size_t e = 0; e < header->elements.size(); ++e) {
    // A row without properties reads nothing: its count would bound no loop by the file's size.
    if (header->elements[e].properties.empty() && header->elements[e].count > 0) return "";
    if (header->elements[e].name == "tristrips") {
      strips = e;
      ++strip_elements;
    }
  }
  if (strip_elements != 1) return "";  // none, or more than one (which check_ply_header refuses)
  const Element& strip_element = header->elements[strips];
  if (strip_element.properties.size() != 1 || strip_element.properties[0].count_bytes == 0 ||
      strip_element.properties[0].is_float) {
    return "";
  }
  const std::string_view body = whole.substr(header->body);
  BodyReader reader(body, *header);
  for (std::size_t e = 0; e < strips; ++e) {
    for (long long row = 0; row < header->elements[e].count; ++row) {
      if (!reader.skip_row(header->elements[e])) return "";
    }
  }
  const std::size_t strips_start = reader.at();
  const Property& list = strip_element.properties[0];
  std::vector<std::array<long long, 3>> triangles;
  std::vector<long long> strip;
  for (long long row = 0; row < strip_element.count; ++row) {
    const std::optional<long long> n = reader.integer(list.count_bytes, false);
    if (!n || *n < 0 || static_cast<unsigned long long>(*n) > body.size()) return "";
    strip.clear();
    for (long long i = 0; i < *n; ++i) {
      const std::optional<long long> index = reader.integer(list.bytes, list.is_signed);
      if (!index || *index < -1 || *index > INT32_MAX) return "";
      if (*index == -1) {
        add_strip_triangles(strip, triangles);
        strip.clear();
      } else {
        strip.push_back(*index);
      }
      if (static_cast<long long>(triangles.size() + strip.size()) >
          max_triangles + 2) {  // a strip of n: n − 2 triangles
        throw softbody::InputError("holds triangle strips of more than " + std::to_string(max_triangles) +
                                   " triangles, the limit (raise it with the scene key limits.max_triangles)");
      }
    }
    add_strip_triangles(strip, triangles);
  }
  // The file again: its header with the strips' element and property lines as a face element, the rows
  // before the strips, the faces, the rows after them.
  const std::size_t strips_end = reader.at();
  std::string out(whole.substr(0, strip_element.header_line));
  out += "element face " + std::to_string(triangles.size()) + "\nproperty list uchar int vertex_indices\n";
  out += whole.substr(strip_element.header_end, header->body - strip_element.header_end);
  out += body.substr(0, strips_start);
  if (header->ascii) {
    if (!out.empty() && out.back() != '\n') out += '\n';
    for (const auto& [a, b, c] : triangles)
      out += "3 " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + "\n";
  } else {
    for (const auto& t : triangles) {
      out.push_back(3);
      for (long long v : t) append_integer(out, v, 4, header->big_endian);
    }
  }
  out += body.substr(strips_end);
  return out;
}

}  // namespace mesh
