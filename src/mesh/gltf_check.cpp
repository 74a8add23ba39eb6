// The glTF 2 document check: references resolve and every primitive has positions.
#include "mesh/gltf_check.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/errors.hpp"
#include "mesh/file_references.hpp"
#include "mesh/mesh_limits.hpp"

namespace mesh {
namespace {

using nlohmann::json;
using softbody::InputError;

// The number of entries of the top-level array `key` (0 when absent); refuses a value that is not an array.
std::size_t count_of(const json& document, const char* key) {
  const auto found = document.find(key);
  if (found == document.end()) return 0;
  if (!found->is_array()) throw InputError(std::string("is a glTF document whose \"") + key + "\" is not an array");
  return found->size();
}

// `reference` (at `where` in the document) is an index into an array of `count` entries.
void check_index(const json& reference, std::size_t count, const std::string& where, const char* array) {
  if (!reference.is_number_unsigned() || reference.get<std::size_t>() >= count) {
    throw InputError("is a glTF document whose " + where + " (" + reference.dump() + ") names none of its " +
                     std::to_string(count) + " " + array);
  }
}

void check_accessors(const json& document) {
  const std::size_t views = count_of(document, "bufferViews"), buffers = count_of(document, "buffers");
  for (std::size_t a = 0; a < count_of(document, "accessors"); ++a) {
    const json& accessor = document["accessors"][a];
    const std::string where = "accessors." + std::to_string(a);
    if (!accessor.is_object()) throw InputError("is a glTF document whose " + where + " is not an object");
    if (const auto view = accessor.find("bufferView"); view != accessor.end()) {
      check_index(*view, views, where + ".bufferView", "bufferViews");
    }
  }
  for (std::size_t v = 0; v < views; ++v) {
    const json& view = document["bufferViews"][v];
    const std::string where = "bufferViews." + std::to_string(v);
    if (!view.is_object() || !view.contains("buffer")) {
      throw InputError("is a glTF document whose " + where + " has no \"buffer\"");
    }
    check_index(view["buffer"], buffers, where + ".buffer", "buffers");
  }
}

void check_primitive(const json& primitive, const std::string& where, std::size_t accessors) {
  if (!primitive.is_object()) throw InputError("is a glTF document whose " + where + " is not an object");
  const auto attributes = primitive.find("attributes");
  if (attributes == primitive.end() || !attributes->is_object() || !attributes->contains("POSITION")) {
    throw InputError("is a glTF document whose " + where + " has no POSITION attribute (expected vertex positions)");
  }
  for (const auto& [name, accessor] : attributes->items()) {
    check_index(accessor, accessors, where + ".attributes." + name, "accessors");
  }
  if (const auto indices = primitive.find("indices"); indices != primitive.end()) {
    check_index(*indices, accessors, where + ".indices", "accessors");
  }
  if (const auto mode = primitive.find("mode"); mode != primitive.end()) {
    // glTF 2.0 §3.7.2.1: 0 points, 1 lines, 2 line loop, 3 line strip, 4 triangles, 5 strip, 6 fan.
    if (!mode->is_number_unsigned() || mode->get<unsigned long long>() > 6) {
      throw InputError("is a glTF document whose " + where + ".mode is " + mode->dump() + " (expected 0 to 6)");
    }
    // assimp 5.2 reads an indexed line loop's indices without checking them against the vertex count (found by
    // fuzz_mesh_glb: SEGV); a body uses triangle primitives only, so such a primitive is refused, not skipped.
    if (mode->get<unsigned long long>() == 2 && primitive.contains("indices")) {
      throw InputError("is a glTF document whose " + where +
                       " is an indexed line loop (mode 2), which assimp's glTF "
                       "reader cannot read safely; a body uses triangle primitives only (modes 4, 5, 6): remove it");
    }
  }
}

// assimp's JSON reader (rapidjson) recurses once per array or object: 200,000 nested arrays in an "extras"
// overflowed its stack (SIGSEGV). One pass over the brackets outside strings, before anything parses the text.
void check_json_nesting(std::string_view json_text) {
  int depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < json_text.size(); ++i) {
    const char c = json_text[i];
    if (in_string) {
      if (c == '\\')
        ++i;  // the escaped character cannot end the string
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMostNestingLevels) {
        throw InputError("is a glTF file whose JSON nests arrays and objects more than " +
                         std::to_string(kMostNestingLevels) + " levels deep (at byte " + std::to_string(i) +
                         "), more than assimp's reader can follow");
      }
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

// glTF 1.0 (2015, superseded by 2.0 in 2017) is not read: assimp 5.2's glTF 1 reader trusts the sizes a document
// gives (found by fuzz_mesh_gltf1 after 11,203 executions: an accessor past its buffer view's end aborted it on an
// ai_assert), and its reader is switched off (keep_only_accepted_readers). Its version may be a string or, for that
// reader, a number.
void refuse_gltf_1(const json& document) {
  const auto asset = document.find("asset");
  if (asset == document.end() || !asset->is_object() || !asset->contains("version")) return;
  const json& version = (*asset)["version"];
  const bool one = version.is_string() ? version.get_ref<const std::string&>().rfind('1', 0) == 0
                                       : version.is_number() && version.get<double>() >= 1 && version.get<double>() < 2;
  if (one) {
    throw InputError("is a glTF 1.0 file (asset.version " + version.dump().substr(0, 40) +
                     "), which softbody does not read (expected glTF 2.0: export the mesh again as glTF 2.0)");
  }
}

// Every buffer's uri (glTF 2: an array; glTF 1: an object of buffers) is embedded data ("data:") or a file in
// the document's folder; a buffer without a uri is a GLB file's binary chunk.
void check_buffer_files(const json& document, const std::filesystem::path& folder) {
  const auto buffers = document.find("buffers");
  if (buffers == document.end() || !buffers->is_structured()) return;
  for (const auto& [key, buffer] : buffers->items()) {
    if (!buffer.is_object() || !buffer.contains("uri")) continue;
    const json& uri = buffer["uri"];
    const std::string where = "is a glTF file whose buffers." + key + ".uri";
    if (!uri.is_string()) throw InputError(where + " is not a string");
    const std::string& name = uri.get_ref<const std::string&>();
    if (name.rfind("data:", 0) == 0) continue;
    check_referenced_uri(name, folder, where);
  }
}

// assimp's glTF readers, and its step that applies node transforms, recurse once per level of the node hierarchy:
// a chain of 100,000 nodes overflowed the stack (SIGSEGV). Nodes are an array (glTF 2) or an object of ids
// (glTF 1); children name nodes by index or id. Iterative: a crafted chain cannot overflow this stack either.
void check_node_hierarchy(const json& document) {
  const auto nodes = document.find("nodes");
  if (nodes == document.end() || !nodes->is_structured()) return;
  std::unordered_map<std::string, std::vector<std::string>> children;
  for (const auto& [key, node] : nodes->items()) {
    std::vector<std::string>& names = children[key];
    if (!node.is_object() || !node.contains("children") || !node["children"].is_array()) continue;
    for (const json& child : node["children"]) {
      if (child.is_number_unsigned()) names.push_back(std::to_string(child.get<unsigned long long>()));
      if (child.is_string()) names.push_back(child.get<std::string>());
    }
  }
  std::unordered_map<std::string, int> levels;  // a finished node: the levels of its subtree, itself included
  const auto refuse = [](const std::string& what) {
    throw InputError("is a glTF file whose nodes " + what + ", more than assimp's reader can follow");
  };
  struct Frame {
    const std::string* node;
    std::size_t next_child = 0;
    int below = 0;  // the deepest subtree of its children so far
  };
  std::unordered_map<std::string, bool> on_path;
  for (const auto& [root, unused] : children) {
    if (levels.count(root)) continue;
    std::vector<Frame> path{{&root}};
    on_path[root] = true;
    while (!path.empty()) {
      Frame& frame = path.back();
      const std::vector<std::string>& mine = children.at(*frame.node);
      if (frame.next_child < mine.size()) {
        const std::string& child = mine[frame.next_child++];
        if (!children.count(child)) continue;  // names no node: assimp reports it
        if (on_path[child]) refuse("form a cycle (node " + child.substr(0, 40) + " is its own descendant)");
        if (const auto done = levels.find(child); done != levels.end()) {
          frame.below = std::max(frame.below, done->second);
        } else {
          if (path.size() >= static_cast<std::size_t>(kMostNestingLevels)) {
            refuse("nest more than " + std::to_string(kMostNestingLevels) + " levels deep");
          }
          on_path[child] = true;
          path.push_back({&child});
        }
        continue;
      }
      const int mine_levels = frame.below + 1;
      if (path.size() + static_cast<std::size_t>(mine_levels) - 1 > static_cast<std::size_t>(kMostNestingLevels)) {
        refuse("nest more than " + std::to_string(kMostNestingLevels) + " levels deep");
      }
      levels[*frame.node] = mine_levels;
      on_path[*frame.node] = false;
      path.pop_back();
      if (!path.empty()) path.back().below = std::max(path.back().below, mine_levels);
    }
  }
}

}  // namespace

void check_gltf_document(std::string_view json_text, const std::filesystem::path& folder) {
  check_json_nesting(json_text);
  json document;
  try {
    document = json::parse(json_text.begin(), json_text.end());
  } catch (const json::exception& e) {
    // e.what() names the byte; glTF JSON must be UTF-8 (glTF 2.0 §3.2), which the parser checks too. A number
    // beyond the range of a double (2e22222) is nlohmann's out_of_range 406 (found by fuzz_mesh_gltf: it was
    // not caught, and std::terminate ended the program).
    throw InputError("is a glTF file whose JSON does not parse (" + std::string(e.what()) + ")");
  }
  if (!document.is_object()) throw InputError("is a glTF file whose JSON is not an object");
  check_buffer_files(document, folder);
  check_node_hierarchy(document);
  refuse_gltf_1(document);
  check_accessors(document);
  const std::size_t accessors = count_of(document, "accessors");
  for (std::size_t m = 0; m < count_of(document, "meshes"); ++m) {
    const json& mesh = document["meshes"][m];
    const std::string where = "meshes." + std::to_string(m);
    if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) {
      throw InputError("is a glTF document whose " + where + " has no \"primitives\" array");
    }
    for (std::size_t p = 0; p < mesh["primitives"].size(); ++p) {
      check_primitive(mesh["primitives"][p], where + ".primitives." + std::to_string(p), accessors);
    }
  }
}

}  // namespace mesh
