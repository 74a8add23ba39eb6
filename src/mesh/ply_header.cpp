// PLY and OFF header checks, done on the file's first bytes before assimp sees the file.
#include "mesh/ply_header.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "mesh/ply_format.hpp"

namespace mesh {
namespace {

using ply::type_bytes;
using ply::words_of;
using softbody::InputError;

// A decimal count of at most 18 digits, or -1.
long long count_of(std::string_view word) {
  if (word.empty() || word.size() > 18) return -1;
  long long n = 0;
  for (char c : word) {
    if (c < '0' || c > '9') return -1;
    n = 10 * n + (c - '0');
  }
  return n;
}

struct Property {
  int bytes = 0;                // a scalar's bytes, or a list item's
  int count_bytes = 0;          // a list's count: 1, 2 or 4 bytes; 0 for a scalar
  bool vertex_indices = false;  // a face's vertex_index (or vertex_indices) list
  char item_kind = 'u';         // a list item's kind (type_bytes)
};

struct Element {
  std::string name;
  long long count = 0;
  long long row_min_bytes = 0;  // binary: scalars plus list counts (a list may be empty)
  long long properties = 0;
  std::vector<Property> layout;
};

// An unsigned list count of `bytes` bytes at `p` (a negative signed count reads as huge: refused as such).
unsigned long long list_count(const unsigned char* p, int bytes, bool big_endian) {
  return ply::unsigned_at(p, bytes, big_endian);
}

// A binary list item as a double (exact for integers of up to 32 bits).
double item_value(const unsigned char* p, int bytes, char kind, bool big_endian) {
  const unsigned long long raw = list_count(p, bytes, big_endian);  // its bytes as an unsigned integer
  if (kind == 'u') return static_cast<double>(raw);
  if (kind == 'i') {
    const unsigned long long sign = 1ULL << (8 * bytes - 1);
    return static_cast<double>(static_cast<long long>(raw ^ sign) - static_cast<long long>(sign));
  }
  if (bytes == 4) {
    float f;
    const auto bits = static_cast<std::uint32_t>(raw);
    std::memcpy(&f, &bits, sizeof f);
    return f;
  }
  double d;
  std::memcpy(&d, &raw, sizeof d);
  return d;
}

// Throws unless `index`, an item of face `row`'s vertex list, names one of the `vertices` the header announces:
// every format's indices are checked after assimp reads the file, a PLY's before too, so that assimp's PLY
// reader never holds one past its vertices (a fuzz_mesh_ply_binary run that ended on a corrupted heap had
// such a face as its last input; alone it corrupts nothing, and the cause is not found).
void check_vertex_index(double index, long long row, long long vertices) {
  if (index >= 0.0 && index < static_cast<double>(vertices) && index == std::floor(index)) return;
  char text[160];
  std::snprintf(text, sizeof text,
                "has face %lld with the vertex index %.17g, not one of the %lld vertices its header announces", row,
                index, vertices);
  throw InputError(text);
}

// Which of assimp 5.2's two mesh arrays an element fills: "vertex", "face" (for "face" and "tristrips"), or none ("").
std::string_view assimp_array_of(std::string_view element) {
  if (element == "vertex") return "vertex";
  if (element == "face" || element == "tristrips") return "face";
  return "";
}

// Walks a binary body row by row: every list's count must fit in the bytes that remain (assimp reads past
// the end of the file otherwise), and every face's vertex index must name a vertex.
void check_binary_body(std::string_view body, const std::vector<Element>& elements, bool big_endian,
                       long long vertices) {
  std::size_t at = 0;
  for (const Element& e : elements) {
    for (long long row = 0; row < e.count; ++row) {
      for (const Property& p : e.layout) {
        const std::size_t left = body.size() - at;
        if (p.count_bytes == 0) {
          if (left < static_cast<std::size_t>(p.bytes)) {
            throw InputError("ends inside " + e.name + " " + std::to_string(row) + " (its header announces more)");
          }
          at += static_cast<std::size_t>(p.bytes);
          continue;
        }
        if (left < static_cast<std::size_t>(p.count_bytes)) {
          throw InputError("ends inside " + e.name + " " + std::to_string(row) + " (its header announces more)");
        }
        const unsigned long long n =
            list_count(reinterpret_cast<const unsigned char*>(body.data() + at), p.count_bytes, big_endian);
        at += static_cast<std::size_t>(p.count_bytes);
        if (p.vertex_indices && n < 3) {
          throw InputError("has face " + std::to_string(row) + " of " + std::to_string(n) +
                           " vertices (expected 3 or more)");
        }
        if (n > (body.size() - at) / static_cast<std::size_t>(p.bytes)) {
          throw InputError("has " + e.name + " " + std::to_string(row) + " with a list of " + std::to_string(n) +
                           " items, more than the rest of the file holds");
        }
        if (p.vertex_indices) {
          for (unsigned long long i = 0; i < n; ++i) {
            const auto* item =
                reinterpret_cast<const unsigned char*>(body.data() + at + i * static_cast<std::size_t>(p.bytes));
            check_vertex_index(item_value(item, p.bytes, p.item_kind, big_endian), row, vertices);
          }
        }
        at += static_cast<std::size_t>(n) * static_cast<std::size_t>(p.bytes);
      }
    }
  }
}

void check_counts(const std::string& what, long long count, long long limit, const char* limit_key) {
  if (count > limit) {
    throw InputError("announces " + std::to_string(count) + " " + what + ", more than the limit of " +
                     std::to_string(limit) + " (raise it with the scene key limits." + limit_key + ")");
  }
}

void check_body_size(std::uintmax_t body_bytes, long double needed_bytes, const std::string& announced) {
  if (static_cast<long double>(body_bytes) < needed_bytes) {
    throw InputError("is too short for its header: the elements it announces (" + announced + ") need at least " +
                     std::to_string(static_cast<unsigned long long>(needed_bytes)) + " bytes, the file has " +
                     std::to_string(body_bytes) + " after its header");
  }
}

// Where the line that is exactly "end_header" starts (a comment may contain the word), or npos.
std::size_t end_header_line(std::string_view head) {
  for (std::size_t start = 0; start < head.size();) {
    const std::size_t end = head.find('\n', start);
    const std::vector<std::string_view> words = words_of(head.substr(start, end - start));
    if (words.size() == 1 && words[0] == "end_header") return start;
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  return std::string_view::npos;
}

// A number as PLY text holds it: an optional sign, digits, '.', an exponent (and inf/nan, which are refused
// later as coordinates); its value in `value` when given.
bool is_number_word(std::string_view word, double* value = nullptr) {
  if (word.empty() || word.size() > 64) return false;
  const std::string text(word);
  char* end = nullptr;
  const double number = std::strtod(text.c_str(), &end);
  if (value) *value = number;
  return end == text.c_str() + text.size();
}

// Walks an ASCII body line by line, as assimp reads it (one element per line): every line holds exactly the
// values its element announces, every value a number, every list count a whole number, every face of at
// least 3 vertices, each of which it names. (A row split over two lines, or a face count that is not a number, made
// assimp's triangulation abort on an ai_assert.)
void check_ascii_body(std::string_view body, const std::vector<Element>& elements, long long vertices) {
  std::size_t at = 0;
  for (const Element& e : elements) {
    for (long long row = 0; row < e.count; ++row) {
      auto bad = [&](const std::string& what) {
        throw InputError("has " + e.name + " " + std::to_string(row) + " with " + what);
      };
      if (at >= body.size())
        throw InputError("ends inside " + e.name + " " + std::to_string(row) + " (its header announces more)");
      const std::size_t end = std::min(body.find('\n', at), body.size());
      const std::vector<std::string_view> words = words_of(body.substr(at, end - at));
      at = end + 1;
      std::size_t w = 0;
      for (const Property& p : e.layout) {
        if (w >= words.size()) bad("fewer values on its line than its header announces");
        const std::string_view word = words[w++];
        if (p.count_bytes == 0) {
          if (!is_number_word(word)) bad("a value that is not a number: \"" + std::string(word.substr(0, 20)) + "\"");
          continue;
        }
        const long long n = count_of(word);
        if (n < 0) bad("a list count that is not a whole number: \"" + std::string(word.substr(0, 20)) + "\"");
        if (p.vertex_indices && n < 3) bad("a face of " + std::to_string(n) + " vertices (expected 3 or more)");
        if (n > static_cast<long long>(words.size() - w))
          bad("a list of " + std::to_string(n) + " items, more than its line holds");
        for (long long i = 0; i < n; ++i) {
          const std::string_view item = words[w++];
          double value = 0.0;
          if (!is_number_word(item, &value)) bad("a list item that is not a number");
          if (p.vertex_indices) check_vertex_index(value, row, vertices);
        }
      }
      if (w != words.size()) bad("more values on its line than its header announces");
    }
  }
}

// Throws unless `text` (a PLY header, or an ASCII body) holds no control character but tabs and line ends (LF,
// or CR LF). assimp's line reader also ends a line at a lone CR, a form feed or a NUL, where the walks above
// see one line: a vertex row "1 <CR>1 1" is one row here and two to assimp, which then shifts every later row
// and aborts in its triangulation (found by fuzz_mesh_ply_text).
// `first_line` is the file's line number of text's first line.
void check_text_characters(std::string_view text, long long first_line, const char* part) {
  long long line = first_line;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n') {
      ++line;
      continue;
    }
    if (c >= 0x20 || c == '\t' || (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n')) continue;
    char code[8];
    std::snprintf(code, sizeof code, "0x%02x", c);
    throw InputError("is a PLY file with the control character " + std::string(code) + " in line " +
                     std::to_string(line) + " (in its " + part +
                     "; a PLY text line holds printable characters and tabs, and ends with LF or CR LF)");
  }
}

}  // namespace

bool looks_like_ply(std::string_view head) { return head.substr(0, 3) == "ply"; }

std::size_t check_ply_header(std::string_view head, std::uintmax_t file_bytes, const MeshLimits& limits) {
  const std::size_t end = end_header_line(head);
  if (end == std::string_view::npos)
    throw InputError("is a PLY file without an end_header line in its first " + std::to_string(head.size()) + " bytes");
  std::size_t header_bytes = head.find('\n', end);
  header_bytes = header_bytes == std::string_view::npos ? head.size() : header_bytes + 1;
  const std::string_view header = head.substr(0, header_bytes);
  check_text_characters(header, 1, "header");
  std::string format;
  std::vector<Element> elements;
  std::size_t line_start = 0;
  int line_number = 0;
  while (line_start < end) {
    std::size_t line_end = head.find('\n', line_start);
    const std::vector<std::string_view> words = words_of(head.substr(line_start, line_end - line_start));
    line_start = line_end + 1;
    ++line_number;
    auto bad = [&](const std::string& what) {
      throw InputError("has a malformed PLY header (line " + std::to_string(line_number) + ": " + what + ")");
    };
    if (words.empty() || words[0] == "comment" || words[0] == "obj_info") continue;
    if (line_number == 1) {
      if (words.size() != 1 || words[0] != "ply") bad("expected \"ply\"");
    } else if (words[0] == "format") {
      if (words.size() != 3 || words[2] != "1.0" ||
          (words[1] != "ascii" && words[1] != "binary_little_endian" && words[1] != "binary_big_endian")) {
        bad("expected format ascii|binary_little_endian|binary_big_endian 1.0");
      }
      format = std::string(words[1]);
    } else if (words[0] == "element") {
      if (words.size() != 3 || count_of(words[2]) < 0) bad("expected element NAME COUNT with a decimal COUNT");
      // assimp reads a name that starts with digits as a count (found by fuzz_mesh_ply_binary: "element
      // 99999999999vertex 0" made it allocate 103 GB).
      const auto first = static_cast<unsigned char>(words[1][0]);
      if (!std::isalpha(first) && first != '_')
        bad("expected element NAME COUNT with a NAME that starts with a letter");
      // assimp keeps one vertex array and one face array, sized by the first element that fills each, and writes
      // a later one's rows past their end (a heap overwrite, shown by an assimp built with ASan,
      // scripts/build-assimp-asan; most likely the fuzzers' earlier heap corruption).
      if (const std::string_view array = assimp_array_of(words[1]); !array.empty()) {
        const auto same_array = [&](const Element& e) { return assimp_array_of(e.name) == array; };
        if (const auto before = std::find_if(elements.begin(), elements.end(), same_array); before != elements.end()) {
          bad("a second element of vertices or faces (\"" + std::string(words[1]) + "\" after \"" + before->name +
              "\"): a PLY file has one of each");
        }
      }
      elements.push_back({std::string(words[1]), count_of(words[2]), 0, 0, {}});
    } else if (words[0] == "property") {
      if (elements.empty()) bad("a property before any element");
      Element& element = elements.back();
      char count_kind = 'f', item_kind = 'f';
      if (words.size() == 5 && words[1] == "list") {
        const int count_bytes = type_bytes(words[2], &count_kind);
        if (count_bytes == 0 || count_kind == 'f')
          bad("expected property list COUNT_TYPE ITEM_TYPE NAME with an integer COUNT_TYPE");
        const int item_bytes = type_bytes(words[3], &item_kind);
        if (item_bytes == 0) bad("unknown item type \"" + std::string(words[3]) + "\"");
        element.row_min_bytes += count_bytes;
        element.layout.push_back(
            {item_bytes, count_bytes, words[4] == "vertex_index" || words[4] == "vertex_indices", item_kind});
      } else if (words.size() == 3) {
        const int bytes = type_bytes(words[1], nullptr);
        if (bytes == 0) bad("unknown property type \"" + std::string(words[1]) + "\"");
        element.row_min_bytes += bytes;
        element.layout.push_back({bytes, 0, false});
      } else {
        bad("expected property TYPE NAME or property list COUNT_TYPE ITEM_TYPE NAME");
      }
      ++element.properties;
    } else {
      bad("unknown keyword \"" + std::string(words[0]) + "\"");
    }
    if (line_end == std::string_view::npos) break;
  }
  if (format.empty()) throw InputError("has a malformed PLY header (no format line)");
  long double needed = 0.0L;
  std::string announced;
  for (const Element& e : elements) {
    if (e.properties == 0 && e.count > 0)
      throw InputError("has a malformed PLY header (element " + e.name + " has no properties)");
    if (e.name == "vertex") {
      check_counts("vertices", e.count, limits.max_vertices, "max_vertices");
    } else if (e.name == "face") {
      check_counts("faces", e.count, limits.max_triangles, "max_triangles");
    } else {
      check_counts("\"" + e.name + "\" elements", e.count, limits.max_vertices, "max_vertices");
    }
    // ASCII: every value is at least one character and a separator; binary: the scalars' bytes.
    const long double row =
        format == "ascii" ? 2.0L * static_cast<long double>(e.properties) : static_cast<long double>(e.row_min_bytes);
    needed += row * static_cast<long double>(e.count);
    if (e.count > 0) announced += (announced.empty() ? "" : ", ") + std::to_string(e.count) + " \"" + e.name + "\"";
  }
  if (format == "ascii") needed -= 1.0L;  // the last value needs no separator after it
  const std::uintmax_t body = file_bytes > header_bytes ? file_bytes - header_bytes : 0;
  if (needed > 0.0L) check_body_size(body, needed, announced);
  if (head.size() < file_bytes) throw InputError("is a PLY file that could not be read whole");
  long long vertices = 0;  // the vertex element's count: what a face's indices may name
  for (const Element& e : elements) {
    if (e.name == "vertex") vertices = e.count;
  }
  if (format == "ascii") {
    const auto header_lines = static_cast<long long>(std::count(header.begin(), header.end(), '\n'));
    check_text_characters(head.substr(header_bytes), header_lines + 1, "body");
    check_ascii_body(head.substr(header_bytes), elements, vertices);
  } else {
    check_binary_body(head.substr(header_bytes), elements, format == "binary_big_endian", vertices);
    // assimp 5.2 drops a line feed that starts the binary data, meant for the LF of an "end_header" CR LF, also
    // after a plain LF, and reads every value one byte off (found by fuzz_mesh_ply_binary: a face list then
    // aborted its triangulation on an ai_assert; about 1 in 256 real files written with LF starts so).
    const bool ends_with_cr_lf = header_bytes >= 2 && head[header_bytes - 2] == '\r';
    if (!ends_with_cr_lf && header_bytes < head.size() && head[header_bytes] == '\n') return header_bytes;
  }
  return std::string_view::npos;
}

bool looks_like_off(std::string_view head) {
  std::size_t i = 0;
  while (i < head.size() && std::isupper(static_cast<unsigned char>(head[i]))) ++i;
  if (i < 3 || head.substr(i - 3, 3) != "OFF") return false;
  return i < head.size() && std::isspace(static_cast<unsigned char>(head[i]));
}

void check_off_header(std::string_view head, std::uintmax_t file_bytes, const MeshLimits& limits) {
  // "OFF" (optional) then the vertex, face and edge counts, '#' comments skipped.
  std::vector<long long> counts;
  std::size_t i = 0;
  if (looks_like_off(head)) {
    while (i < head.size() && !std::isspace(static_cast<unsigned char>(head[i]))) ++i;
  }
  while (i < head.size() && counts.size() < 2) {
    const char c = head[i];
    if (c == '#') {
      while (i < head.size() && head[i] != '\n') ++i;
      continue;
    }
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
      continue;
    }
    const std::size_t start = i;
    while (i < head.size() && !std::isspace(static_cast<unsigned char>(head[i]))) ++i;
    const long long n = count_of(head.substr(start, i - start));
    if (n < 0) throw InputError("has a malformed OFF header (expected decimal vertex and face counts)");
    counts.push_back(n);
  }
  if (counts.size() < 2) return;  // too short to say: assimp reports it
  check_counts("vertices", counts[0], limits.max_vertices, "max_vertices");
  check_counts("faces", counts[1], limits.max_triangles, "max_triangles");
  // Each vertex is at least "0 0 0\n" (6 bytes), each face at least its count and a separator (2 bytes).
  const long double needed =
      6.0L * static_cast<long double>(counts[0]) + 2.0L * static_cast<long double>(counts[1]) - 1.0L;
  const std::uintmax_t body = file_bytes > i ? file_bytes - i : 0;
  if (needed > 0.0L) {
    check_body_size(body, needed, std::to_string(counts[0]) + " vertices and " + std::to_string(counts[1]) + " faces");
  }
}

}  // namespace mesh
