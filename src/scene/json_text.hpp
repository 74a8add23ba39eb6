// JSON text read with limits: a nesting depth limit, and parse errors that name the key path they occur at.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace scene {

// Deeper nesting of arrays and objects is refused (a scene needs 4 levels; the limit leaves room).
inline constexpr int kMaxJsonDepth = 64;

// Parses `text` (// and /* */ comments allowed when `comments`). Throws softbody::InputError that starts
// with `what` ("scene.json" or "--set a.b=...") and names the key path at the error: nesting beyond
// kMaxJsonDepth, numbers beyond the range of a double (1e400), malformed JSON.
nlohmann::json parse_json_limited(const std::string& text, const std::string& what, bool comments);

// The value for a message ("number 1e400", "array [1,2,3]"): at most about 40 characters, and values
// nested deeper than a few levels are not printed at all (no recursion on hostile values).
std::string describe_json(const nlohmann::json& value);

}  // namespace scene
