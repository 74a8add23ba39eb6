// FBX checks: an ASCII or a binary FBX file read once (a binary file's records checked as it is), its Models'
// properties checked, and its object graph searched for cycles and for chains deeper than assimp's recursion
// can follow.
#include "mesh/fbx_check.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/errors.hpp"
#include "mesh/mesh_limits.hpp"

namespace mesh {
namespace {

using softbody::InputError;

struct Connection {
  long long child = 0;   // the object connected...
  long long parent = 0;  // ...to this one ("OO": object to object, "OP": object to a property of it)
};

// What the checks look for in an FBX file's tree, by the names of the blocks around an entry (ASCII keys
// without their colon, binary record names): a connection, or a property of a Model.
enum class Entry { Other, Connection, ModelProperty };

Entry entry_at(const std::vector<std::string_view>& blocks, std::string_view name) {
  if (name == "C" && blocks.size() == 1 && blocks[0] == "Connections") return Entry::Connection;
  if (name == "P" && blocks.size() == 3 && blocks[0] == "Objects" && blocks[1] == "Model" &&
      blocks[2] == "Properties70") {
    return Entry::ModelProperty;
  }
  return Entry::Other;
}

// assimp 5.2's FBX converter copies a Model's properties into its node's metadata and aborts on an
// ai_assert(false) at a time (KTime) property, which it has no metadata type for (found by fuzz_mesh_fbx).
void check_model_property(std::string_view name, std::string_view type) {
  if (type != "KTime") return;
  throw InputError("is an FBX file with a Model whose property \"" + std::string(name.substr(0, 40)) +
                   "\" is a time (KTime), which assimp's reader cannot convert (it aborts)");
}

// assimp's FBX parser (ASCII and binary) reads a nested block or record by recursing: 50,000 levels overflowed
// its stack (SIGSEGV).
void check_nesting(std::size_t levels, const char* what) {
  if (levels <= static_cast<std::size_t>(kMostNestingLevels)) return;
  throw InputError(std::string("is an FBX file whose ") + what + " nest more than " +
                   std::to_string(kMostNestingLevels) + " levels deep, more than assimp's reader can follow");
}

// ---- ASCII FBX: tokens as assimp's tokenizer sees them (';' starts a comment, commas separate) ----

struct Token {
  std::string_view text;  // a "quoted string" without its quotes (maybe empty)
  bool quoted = false;
};

class AsciiTokens {
 public:
  explicit AsciiTokens(std::string_view text) : text_(text) {}

  // The next token ("Key:", "{", "}", a quoted string, a number or word); false at the end of the text.
  bool next(Token& token) {
    skip_blanks_and_comments();
    if (at_ >= text_.size()) return false;
    const std::size_t start = at_;
    const char c = text_[at_];
    token.quoted = c == '"';
    if (c == '{' || c == '}') {
      token.text = text_.substr(at_++, 1);
    } else if (token.quoted) {
      const std::size_t close = std::min(text_.find('"', start + 1), text_.size());
      at_ = close < text_.size() ? close + 1 : close;
      token.text = text_.substr(start + 1, close - start - 1);
    } else {
      while (at_ < text_.size() && !is_separator(text_[at_])) ++at_;
      if (at_ < text_.size() && text_[at_] == ':') ++at_;  // a key keeps its colon
      token.text = text_.substr(start, at_ - start);
    }
    return true;
  }

 private:
  static bool is_separator(char c) {
    return std::isspace(static_cast<unsigned char>(c)) || c == ',' || c == '{' || c == '}' || c == '"' || c == ';' ||
           c == ':';
  }
  void skip_blanks_and_comments() {
    while (at_ < text_.size()) {
      const char c = text_[at_];
      if (c == ';') {
        while (at_ < text_.size() && text_[at_] != '\n') ++at_;
      } else if (std::isspace(static_cast<unsigned char>(c)) || c == ',') {
        ++at_;
      } else {
        return;
      }
    }
  }

  std::string_view text_;
  std::size_t at_ = 0;
};

bool parse_id(std::string_view word, long long& id) {
  if (word.empty() || word.size() > 24) return false;
  const std::string text(word);
  char* end = nullptr;
  id = std::strtoll(text.c_str(), &end, 10);
  return end == text.c_str() + text.size();
}

// One pass over an ASCII file: every `C: "TYPE", child, parent` of the top-level `Connections: { ... }`, and
// every `P: "name", "type", ...` of a Model's Properties70 checked.
std::vector<Connection> read_ascii(std::string_view text) {
  std::vector<Connection> connections;
  AsciiTokens tokens(text);
  std::vector<std::string_view> blocks;  // the key that opened each enclosing { }, without its colon
  std::string_view key;
  Token token;
  while (tokens.next(token)) {
    if (token.quoted) continue;
    if (token.text == "{") {
      blocks.push_back(key);
      check_nesting(blocks.size(), "{ } blocks");
    } else if (token.text == "}") {
      if (!blocks.empty()) blocks.pop_back();
    } else if (token.text.size() > 1 && token.text.back() == ':') {
      key = token.text.substr(0, token.text.size() - 1);
      const Entry entry = entry_at(blocks, key);
      Token first, second, third;
      if (entry == Entry::Connection && tokens.next(first) && tokens.next(second) && tokens.next(third)) {
        Connection c;  // first: the type, "OO", "OP", ...
        if (parse_id(second.text, c.child) && parse_id(third.text, c.parent)) connections.push_back(c);
      } else if (entry == Entry::ModelProperty && tokens.next(first) && tokens.next(second)) {
        check_model_property(first.text, second.text);
      }
    }
  }
  return connections;
}

// ---- Binary FBX: node records (Kaydara's layout, as assimp 5.2 reads it) ----

// assimp takes a file for binary when it starts with these 18 bytes (FBXImporter.cpp), whatever the 3 after them
// (found by fuzz_mesh_fbx: a file starting "Kaydara FBX Binary$ " passed the check as ASCII, then aborted assimp's
// binary tokenizer); the full magic is these and "  \0".
constexpr std::string_view kBinaryMagic{"Kaydara FBX Binary"};
constexpr std::size_t kFirstRecord = 27;  // the magic, 0x1A 0x00, the uint32 version

std::uint64_t read_le(std::string_view bytes, std::size_t at, std::size_t width) {
  std::uint64_t value = 0;
  for (std::size_t i = 0; i < width; ++i) value |= std::uint64_t{static_cast<unsigned char>(bytes[at + i])} << (8 * i);
  return value;
}

// The bytes of one property of type `type` at `at` (its type code already read), or 0 where it runs past `limit`
// or the type is unknown. Arrays (f d l i b) hold a length, an encoding (0 raw, 1 zlib) and their byte count.
std::size_t property_bytes_at(std::string_view bytes, std::size_t at, std::size_t limit, char type) {
  const std::size_t left = limit - at;
  std::size_t size = 0;
  switch (type) {
    case 'C': size = 1; break;
    case 'Y': size = 2; break;
    case 'I':
    case 'F': size = 4; break;
    case 'D':
    case 'L': size = 8; break;
    case 'S':
    case 'R':
      if (left < 4) return 0;
      size = 4 + static_cast<std::size_t>(std::min<std::uint64_t>(read_le(bytes, at, 4), left));
      break;
    case 'f':
    case 'd':
    case 'l':
    case 'i':
    case 'b':
      if (left < 12 || read_le(bytes, at + 4, 4) > 1) return 0;
      size = 12 + static_cast<std::size_t>(std::min<std::uint64_t>(read_le(bytes, at + 8, 4), left));
      break;
    default: return 0;
  }
  return size <= left ? size : 0;
}

// The first two strings (S) and the first two integers (L, or I in old files) of a record's properties: a P
// record's name and type, a C record's child and parent.
struct FirstProperties {
  std::string_view strings[2];
  long long integers[2] = {0, 0};
  int string_count = 0, integer_count = 0;

  void take(std::string_view bytes, std::size_t at, char type) {
    if (type == 'S' && string_count < 2) {
      strings[string_count++] = bytes.substr(at + 4, static_cast<std::size_t>(read_le(bytes, at, 4)));
    } else if ((type == 'L' || type == 'I') && integer_count < 2) {
      const std::uint64_t raw = read_le(bytes, at, type == 'L' ? 8 : 4);
      integers[integer_count++] = type == 'L' ? static_cast<long long>(raw) : static_cast<std::int32_t>(raw);
    }
  }
};

// One pass over a binary file. Throws unless every record can be followed as assimp's tokenizer follows it:
// each ends after it starts and within its parent, its properties (known types, their lengths) fill exactly
// its property bytes, and its nested records are followed by a null record that ends exactly where it ends.
// (Found by fuzz_mesh_fbx: a record whose offsets ran backwards made assimp abort on an ai_assert in its
// binary tokenizer.) On the way, the C records of the top-level Connections record are collected and the P
// records of a Model's Properties70 checked. Iterative: nesting cannot overflow this stack.
std::vector<Connection> read_binary(std::string_view bytes) {
  if (bytes.size() < kFirstRecord) throw InputError("is a binary FBX file cut short inside its header");
  const std::size_t width = read_le(bytes, 23, 4) >= 7500 ? 8 : 4;
  const std::size_t header = 3 * width + 1;  // also the size of a null record
  auto refuse = [](std::size_t at, const std::string& what) {
    throw InputError("is a binary FBX file whose record at byte " + std::to_string(at) + " " + what +
                     " (assimp's reader cannot follow it safely)");
  };
  std::vector<Connection> connections;
  struct List {
    std::size_t at, stop;  // nested records from `at` up to `stop`, then a null record
  };
  std::vector<List> open;
  std::vector<std::string_view> blocks;  // the names of the records whose lists are open
  // One record at `at`, which must end by `limit`: checked, its nested list opened; returns where it ends.
  auto enter = [&](std::size_t at, std::size_t limit) {
    if (limit - at < header) refuse(at, "is cut short");
    const std::uint64_t end = read_le(bytes, at, width);
    const std::uint64_t properties = read_le(bytes, at + width, width);
    const std::uint64_t property_bytes = read_le(bytes, at + 2 * width, width);
    const std::size_t name_bytes = static_cast<unsigned char>(bytes[at + 3 * width]);
    if (end <= at || end > limit) refuse(at, "ends at byte " + std::to_string(end) + ", outside its parent");
    const std::size_t properties_at = at + header + name_bytes;
    if (properties_at > end || property_bytes > end - properties_at)
      refuse(at, "has more property bytes than it holds");
    const std::size_t nested_at = properties_at + static_cast<std::size_t>(property_bytes);
    FirstProperties first;
    std::size_t p = properties_at;
    for (std::uint64_t k = 0; k < properties; ++k) {
      if (p >= nested_at) refuse(at, "has fewer property bytes than its properties need");
      const std::size_t size = property_bytes_at(bytes, p + 1, nested_at, bytes[p]);
      if (size == 0) refuse(at, "has a property of an unknown type or beyond its bytes");
      first.take(bytes, p + 1, bytes[p]);
      p += 1 + size;
    }
    if (p != nested_at) refuse(at, "has property bytes that its properties do not fill");
    const std::string_view name = bytes.substr(at + header, name_bytes);
    const Entry entry = entry_at(blocks, name);
    if (entry == Entry::Connection && first.integer_count == 2) {
      connections.push_back({first.integers[0], first.integers[1]});
    } else if (entry == Entry::ModelProperty) {
      check_model_property(first.strings[0], first.strings[1]);
    }
    if (nested_at < end) {
      if (end - nested_at < header) refuse(at, "has no room for the null record after its nested records");
      open.push_back({nested_at, static_cast<std::size_t>(end) - header});
      blocks.push_back(name);
      check_nesting(blocks.size() + 1, "records");  // its nested records are one level deeper
    }
    return static_cast<std::size_t>(end);
  };
  for (std::size_t at = kFirstRecord; bytes.size() - at >= header && read_le(bytes, at, width) != 0;) {
    at = enter(at, bytes.size());
    while (!open.empty()) {
      const std::size_t list = open.size() - 1;
      if (open[list].at < open[list].stop) {
        const std::size_t child = open[list].at;
        if (read_le(bytes, child, width) == 0) refuse(child, "is a null record before the end of its list");
        const std::size_t child_end = enter(child, open[list].stop);
        open[list].at = child_end;  // by index: enter may have grown `open`
        continue;
      }
      const std::size_t stop = open[list].stop;
      if (open[list].at != stop) refuse(stop, "is overrun by the record before it");
      for (std::size_t b = stop; b < stop + header; ++b) {
        if (bytes[b] != 0) refuse(stop, "should be a null record");
      }
      open.pop_back();
      blocks.pop_back();
    }
  }
  return connections;
}

// ---- The object graph ----

// Throws if following child → parent links from any object comes back to it, or passes more than
// kMostFbxConnectionLevels links. Iterative (a crafted chain must not overflow this stack either).
void check_acyclic_and_shallow(const std::vector<Connection>& connections) {
  std::unordered_map<long long, std::vector<long long>> parents;
  for (const Connection& c : connections) parents[c.child].push_back(c.parent);
  enum class Mark { Unseen, OnPath, Done };
  std::unordered_map<long long, Mark> mark;
  std::unordered_map<long long, int> levels;  // the longest chain of links above an object
  struct Frame {
    long long object;
    std::size_t next_parent;
  };
  for (const Connection& start : connections) {
    if (mark[start.child] != Mark::Unseen) continue;
    std::vector<Frame> path{{start.child, 0}};
    mark[start.child] = Mark::OnPath;
    while (!path.empty()) {
      Frame& frame = path.back();
      const auto found = parents.find(frame.object);
      if (found != parents.end() && frame.next_parent < found->second.size()) {
        const long long parent = found->second[frame.next_parent++];
        const Mark parent_mark = mark[parent];
        if (parent_mark == Mark::OnPath) {
          std::size_t first = path.size() - 1;
          while (path[first].object != parent) --first;
          const std::size_t links = path.size() - first;
          throw InputError("is an FBX file whose object connections form a cycle (object " + std::to_string(parent) +
                           " is connected to itself through " + std::to_string(links) +
                           (links == 1 ? " link" : " links") + "), which assimp's reader cannot follow");
        }
        if (parent_mark == Mark::Unseen) {
          mark[parent] = Mark::OnPath;
          path.push_back({parent, 0});
        }
        continue;
      }
      int above = 0;
      if (found != parents.end()) {
        for (long long parent : found->second) above = std::max(above, levels[parent] + 1);
      }
      if (above > kMostFbxConnectionLevels) {
        throw InputError("is an FBX file whose object connections are nested more than " +
                         std::to_string(kMostFbxConnectionLevels) +
                         " levels deep, more than assimp's reader can follow");
      }
      levels[frame.object] = above;
      mark[frame.object] = Mark::Done;
      path.pop_back();
    }
  }
}

}  // namespace

bool looks_like_binary_fbx(std::string_view head) { return head.substr(0, kBinaryMagic.size()) == kBinaryMagic; }

void check_fbx_file(std::string_view file_text) {
  check_acyclic_and_shallow(looks_like_binary_fbx(file_text) ? read_binary(file_text) : read_ascii(file_text));
}

}  // namespace mesh
