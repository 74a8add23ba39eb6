// FBX connection checks: the "Connections" section read from an ASCII or a binary FBX file, and its object graph
// searched for cycles and for chains deeper than assimp's recursion can follow.
#include "mesh/fbx_check.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/errors.hpp"

namespace mesh {
namespace {

using softbody::InputError;

struct Connection {
  long long child = 0;   // the object connected...
  long long parent = 0;  // ...to this one ("OO": object to object, "OP": object to a property of it)
};

// ---- ASCII FBX: tokens as assimp's tokenizer sees them (';' starts a comment, commas separate) ----

class AsciiTokens {
 public:
  explicit AsciiTokens(std::string_view text) : text_(text) {}

  // The next token ("Key:", "{", "}", a "quoted string" without its quotes (maybe empty), a number or word);
  // false at the end of the text.
  bool next(std::string_view& token) {
    skip_blanks_and_comments();
    if (at_ >= text_.size()) return false;
    const std::size_t start = at_;
    const char c = text_[at_];
    if (c == '{' || c == '}') {
      token = text_.substr(at_++, 1);
    } else if (c == '"') {
      const std::size_t close = std::min(text_.find('"', start + 1), text_.size());
      at_ = close < text_.size() ? close + 1 : close;
      token = text_.substr(start + 1, close - start - 1);
    } else {
      while (at_ < text_.size() && !is_separator(text_[at_])) ++at_;
      if (at_ < text_.size() && text_[at_] == ':') ++at_;  // a key keeps its colon
      token = text_.substr(start, at_ - start);
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

// assimp 5.2's FBX converter copies a Model's properties into its node's metadata and aborts on an
// ai_assert(false) at a time (KTime) property, which it has no metadata type for (found by fuzz_mesh_fbx).
[[noreturn]] void refuse_model_time_property(std::string_view name) {
  throw InputError("is an FBX file with a Model whose property \"" + std::string(name.substr(0, 40)) +
                   "\" is a time (KTime), which assimp's reader cannot convert (it aborts)");
}

// Throws at a `P: "name", "KTime", ...` inside `Objects: { Model: ... { Properties70: { ... } } }`.
void check_ascii_model_properties(std::string_view text) {
  AsciiTokens tokens(text);
  std::vector<std::string_view> blocks;  // the key that opened each enclosing { }
  std::string_view key, token;
  while (tokens.next(token)) {
    if (token == "{") {
      blocks.push_back(key);
    } else if (token == "}") {
      if (!blocks.empty()) blocks.pop_back();
    } else if (!token.empty() && token.back() == ':' && (token.size() < 2 || token[0] != '"')) {
      key = token;
      if (token == "P:" && blocks.size() == 3 && blocks[0] == "Objects:" && blocks[1] == "Model:" &&
          blocks[2] == "Properties70:") {
        std::string_view name, type;
        if (tokens.next(name) && tokens.next(type) && type == "KTime") refuse_model_time_property(name);
      }
    }
  }
}

// Every `C: "TYPE", child, parent` inside the top-level `Connections: { ... }` of an ASCII file.
std::vector<Connection> ascii_connections(std::string_view text) {
  std::vector<Connection> connections;
  AsciiTokens tokens(text);
  int depth = 0;
  bool in_connections = false;
  std::string_view previous, token;
  while (tokens.next(token)) {
    if (token == "{") {
      ++depth;
      if (depth == 1 && previous == "Connections:") in_connections = true;
    } else if (token == "}") {
      if (depth == 1) in_connections = false;
      if (depth > 0) --depth;
    } else if (in_connections && depth == 1 && token == "C:") {
      std::string_view type, child, parent;  // the type: "OO", "OP", ...
      Connection c;
      if (tokens.next(type) && tokens.next(child) && tokens.next(parent) && parse_id(child, c.child) &&
          parse_id(parent, c.parent)) {
        connections.push_back(c);
      }
    }
    previous = token;
  }
  return connections;
}

// ---- Binary FBX: node records (Kaydara's layout, as assimp 5.2 reads it) ----

constexpr std::string_view kBinaryMagic{"Kaydara FBX Binary  \0", 21};
constexpr std::size_t kFirstRecord = 27;  // the magic, 0x1A 0x00, the uint32 version

std::uint64_t read_le(std::string_view bytes, std::size_t at, std::size_t width) {
  std::uint64_t value = 0;
  for (std::size_t i = 0; i < width; ++i) value |= std::uint64_t{static_cast<unsigned char>(bytes[at + i])} << (8 * i);
  return value;
}

// One node record's layout: where its properties and its nested records lie, and where it ends.
struct Record {
  std::size_t end = 0;         // 0: the null record that ends a list
  std::uint64_t properties = 0;
  std::size_t properties_at = 0, nested_at = 0;
  std::string_view name;
};

// The record at `at`, or false where it runs outside [at, limit) (a file that cannot be followed).
bool read_record(std::string_view bytes, std::size_t at, std::size_t limit, std::size_t width, Record& record) {
  const std::size_t header = 3 * width + 1;
  if (limit > bytes.size() || at > limit || limit - at < header) return false;
  const std::uint64_t end = read_le(bytes, at, width);
  record.properties = read_le(bytes, at + width, width);
  const std::uint64_t property_bytes = read_le(bytes, at + 2 * width, width);
  const std::size_t name_bytes = static_cast<unsigned char>(bytes[at + 3 * width]);
  if (end == 0) {
    record.end = 0;
    return true;
  }
  if (end <= at || end > limit) return false;
  record.end = static_cast<std::size_t>(end);
  record.name = bytes.substr(at + header, std::min(name_bytes, record.end - (at + header)));
  record.properties_at = at + header + name_bytes;
  if (record.properties_at > record.end || property_bytes > record.end - record.properties_at) return false;
  record.nested_at = record.properties_at + static_cast<std::size_t>(property_bytes);
  return true;
}

// The properties of a "C" record: its type string, then two integer ids ('L', or 'I' in old files).
bool connection_of(std::string_view bytes, const Record& record, Connection& c) {
  std::size_t at = record.properties_at;
  long long ids[2] = {0, 0};
  int found = 0;
  for (std::uint64_t p = 0; p < record.properties && at < record.nested_at && found < 2; ++p) {
    const char type = bytes[at++];
    const std::size_t left = record.nested_at - at;
    if (type == 'S' || type == 'R') {
      if (left < 4) return false;
      const std::uint64_t length = read_le(bytes, at, 4);
      if (length > left - 4) return false;
      at += 4 + static_cast<std::size_t>(length);
    } else if (type == 'L' || type == 'I') {
      const std::size_t width = type == 'L' ? 8 : 4;
      if (left < width) return false;
      const std::uint64_t raw = read_le(bytes, at, width);
      ids[found++] = type == 'L' ? static_cast<long long>(raw) : static_cast<long long>(static_cast<std::int32_t>(raw));
      at += width;
    } else {
      return false;  // no other type in a connection
    }
  }
  if (found < 2) return false;
  c = {ids[0], ids[1]};
  return true;
}

// The bytes of one property of type `type` at `at` (its type code already read), or 0 where it runs past `limit`
// or the type is unknown. Arrays (f d l i b) hold a length, an encoding (0 raw, 1 zlib) and their byte count.
std::size_t property_bytes_at(std::string_view bytes, std::size_t at, std::size_t limit, char type) {
  const std::size_t left = limit - at;
  std::size_t size = 0;
  switch (type) {
    case 'C': size = 1; break;
    case 'Y': size = 2; break;
    case 'I': case 'F': size = 4; break;
    case 'D': case 'L': size = 8; break;
    case 'S': case 'R':
      if (left < 4) return 0;
      size = 4 + static_cast<std::size_t>(std::min<std::uint64_t>(read_le(bytes, at, 4), left));
      break;
    case 'f': case 'd': case 'l': case 'i': case 'b':
      if (left < 12 || read_le(bytes, at + 4, 4) > 1) return 0;
      size = 12 + static_cast<std::size_t>(std::min<std::uint64_t>(read_le(bytes, at + 8, 4), left));
      break;
    default: return 0;
  }
  return size <= left ? size : 0;
}

// Throws unless every record of a binary file can be followed as assimp's tokenizer follows it: each ends after
// it starts and within its parent, its properties (known types, their lengths) fill exactly its property
// bytes, and its nested records are followed by a null record that ends exactly where it ends. (Found by
// fuzz_mesh_fbx: a record whose offsets ran backwards made assimp abort on an ai_assert in its binary
// tokenizer.) Iterative: nesting cannot overflow this stack.
void check_binary_records(std::string_view bytes, std::size_t width) {
  const std::size_t header = 3 * width + 1;  // also the size of a null record
  auto refuse = [](std::size_t at, const std::string& what) {
    throw InputError("is a binary FBX file whose record at byte " + std::to_string(at) + " " + what +
                     " (assimp's reader cannot follow it safely)");
  };
  struct List {
    std::size_t at, stop;  // nested records from `at` up to `stop`, then a null record
  };
  std::vector<List> open;
  // One record at `at`, which must end by `limit`: checked, its nested list opened; returns where it ends.
  auto enter = [&](std::size_t at, std::size_t limit) {
    if (limit - at < header) refuse(at, "is cut short");
    const std::uint64_t end = read_le(bytes, at, width);
    const std::uint64_t properties = read_le(bytes, at + width, width);
    const std::uint64_t property_bytes = read_le(bytes, at + 2 * width, width);
    const std::size_t name_bytes = static_cast<unsigned char>(bytes[at + 3 * width]);
    if (end <= at || end > limit) refuse(at, "ends at byte " + std::to_string(end) + ", outside its parent");
    const std::size_t properties_at = at + header + name_bytes;
    if (properties_at > end || property_bytes > end - properties_at) refuse(at, "has more property bytes than it holds");
    const std::size_t nested_at = properties_at + static_cast<std::size_t>(property_bytes);
    std::size_t p = properties_at;
    for (std::uint64_t k = 0; k < properties; ++k) {
      if (p >= nested_at) refuse(at, "has fewer property bytes than its properties need");
      const std::size_t size = property_bytes_at(bytes, p + 1, nested_at, bytes[p]);
      if (size == 0) refuse(at, "has a property of an unknown type or beyond its bytes");
      p += 1 + size;
    }
    if (p != nested_at) refuse(at, "has property bytes that its properties do not fill");
    if (nested_at < end) {
      if (end - nested_at < header) refuse(at, "has no room for the null record after its nested records");
      open.push_back({nested_at, static_cast<std::size_t>(end) - header});
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
    }
  }
}

// Every "C" record nested in the top-level "Connections" record of a binary file; what cannot be followed ends
// the search (check_binary_records refuses such a file first).
std::vector<Connection> binary_connections(std::string_view bytes) {
  std::vector<Connection> connections;
  if (bytes.size() < kFirstRecord) return connections;
  const std::size_t width = read_le(bytes, 23, 4) >= 7500 ? 8 : 4;
  Record top;
  for (std::size_t at = kFirstRecord; read_record(bytes, at, bytes.size(), width, top) && top.end != 0; at = top.end) {
    if (top.name != "Connections") continue;
    Record child;
    for (std::size_t c = top.nested_at; read_record(bytes, c, top.end, width, child) && child.end != 0; c = child.end) {
      Connection connection;
      if (child.name == "C" && connection_of(bytes, child, connection)) connections.push_back(connection);
    }
  }
  return connections;
}

// The first two string properties of a record (a P record's name and type), empty where it has none.
std::pair<std::string_view, std::string_view> first_two_strings(std::string_view bytes, const Record& record) {
  std::string_view found[2];
  std::size_t at = record.properties_at;
  for (int k = 0; k < 2 && at + 5 <= record.nested_at && (bytes[at] == 'S' || bytes[at] == 'R'); ++k) {
    const std::uint64_t length = read_le(bytes, at + 1, 4);
    if (length > record.nested_at - at - 5) break;
    found[k] = bytes.substr(at + 5, static_cast<std::size_t>(length));
    at += 5 + static_cast<std::size_t>(length);
  }
  return {found[0], found[1]};
}

// The binary form of check_ascii_model_properties: Objects / Model / Properties70 / P records.
void check_binary_model_properties(std::string_view bytes, std::size_t width) {
  auto each_child = [&](const Record& parent, auto&& use) {
    Record child;
    for (std::size_t c = parent.nested_at; read_record(bytes, c, parent.end, width, child) && child.end != 0; c = child.end) {
      use(child);
    }
  };
  Record top;
  for (std::size_t at = kFirstRecord; read_record(bytes, at, bytes.size(), width, top) && top.end != 0; at = top.end) {
    if (top.name != "Objects") continue;
    each_child(top, [&](const Record& model) {
      if (model.name != "Model") return;
      each_child(model, [&](const Record& table) {
        if (table.name != "Properties70") return;
        each_child(table, [&](const Record& property) {
          const auto [name, type] = first_two_strings(bytes, property);
          if (property.name == "P" && type == "KTime") refuse_model_time_property(name);
        });
      });
    });
  }
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
                           " is connected to itself through " + std::to_string(links) + (links == 1 ? " link" : " links") +
                           "), which assimp's reader cannot follow");
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
                         std::to_string(kMostFbxConnectionLevels) + " levels deep, more than assimp's reader can follow");
      }
      levels[frame.object] = above;
      mark[frame.object] = Mark::Done;
      path.pop_back();
    }
  }
}

}  // namespace

bool looks_like_binary_fbx(std::string_view head) { return head.substr(0, kBinaryMagic.size()) == kBinaryMagic; }

void check_fbx_connections(std::string_view file_text) {
  if (!looks_like_binary_fbx(file_text)) {
    check_ascii_model_properties(file_text);
    check_acyclic_and_shallow(ascii_connections(file_text));
    return;
  }
  if (file_text.size() < kFirstRecord) throw InputError("is a binary FBX file cut short inside its header");
  const std::size_t width = read_le(file_text, 23, 4) >= 7500 ? 8 : 4;
  check_binary_records(file_text, width);
  check_binary_model_properties(file_text, width);
  check_acyclic_and_shallow(binary_connections(file_text));
}

}  // namespace mesh
