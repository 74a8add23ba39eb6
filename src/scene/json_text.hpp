// JSON text read with limits: a nesting depth limit, and parse errors that name the key path they occur at.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace scene {

// Deeper nesting of arrays and objects is refused (a scene needs 4 levels; the limit leaves room).
inline constexpr int kMaxJsonDepth = 64;

// Parses `text` (// and /* */ comments allowed when `comments`). Throws softbody::InputError that starts
// with `what` ("scene.json" or "--set a.b=...") and names the key path at the error: nesting beyond
// kMaxJsonDepth, numbers beyond the range of a double (1e400), a key given twice in one object (JSON readers
// differ on which value wins, so a scene says each key once), malformed JSON.
nlohmann::json parse_json_limited(const std::string& text, const std::string& what, bool comments);

// The value for a message ("number 1e400", "array [1,2,3]"): at most about 40 characters (a longer one is cut
// and says its size: "string \"aaaa...\" (300 bytes)"), and values nested deeper than a few levels are not
// printed at all (no recursion on hostile values).
std::string describe_json(const nlohmann::json& value);

// Text from the input (a key path, a --set assignment) as a message may echo it: control characters escaped as
// softbody::one_line does (\x00, \n), and beyond `most` bytes cut with an ellipsis and the length
// ("aaaa... (10485760 bytes)").
std::string message_text(const std::string& text, std::size_t most = 100);

}  // namespace scene
