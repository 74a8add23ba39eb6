// Applies `--set PATH=VALUE` assignments to a scene document.
#include "scene/overrides.hpp"

#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "scene/json_text.hpp"

namespace scene {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& assignment, const std::string& what) {
  throw softbody::InputError("--set " + message_text(assignment) + ": " + what);
}

std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = path.find('.', start);
    parts.push_back(path.substr(start, dot - start));
    if (dot == std::string::npos) return parts;
    start = dot + 1;
  }
}

bool is_index(const std::string& part) {
  return !part.empty() && part.find_first_not_of("0123456789") == std::string::npos;
}

json parse_value(const std::string& assignment, const std::string& text) {
  if (!json::accept(text)) return json(text);  // a bare word such as euler (or 1e400: refused as not a number)
  // Nesting limited, and a key given twice refused.
  return parse_json_limited(text, "--set " + message_text(assignment), /*comments=*/false);
}

}  // namespace

void apply_override(json& document, const std::string& assignment) {
  const std::size_t eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) fail(assignment, "expected PATH=VALUE, e.g. bodies.0.mass=2");
  const std::string path = assignment.substr(0, eq);
  const std::vector<std::string> parts = split_path(path);

  json* node = &document;
  std::string walked;
  for (const std::string& part : parts) {
    if (part.empty()) fail(assignment, "empty key in path '" + message_text(path) + "'");
    walked += (walked.empty() ? "" : ".") + part;
    if (node->is_array()) {
      if (!is_index(part))
        fail(assignment, message_text(walked) + ": expected an array index, got '" + message_text(part) + "'");
      // At most 9 digits before converting: no index that large can exist (and stoul could overflow).
      const std::size_t index = part.size() > 9 ? node->size() : std::stoul(part);
      if (index >= node->size()) {
        fail(assignment, message_text(walked) + ": index out of range (the array has " + std::to_string(node->size()) +
                             " elements)");
      }
      node = &(*node)[index];
    } else {
      if (node->is_null()) *node = json::object();
      if (!node->is_object())
        fail(assignment, message_text(walked) + ": cannot set a key inside a " + node->type_name());
      node = &(*node)[part];
    }
  }
  *node = parse_value(assignment, assignment.substr(eq + 1));
}

}  // namespace scene
