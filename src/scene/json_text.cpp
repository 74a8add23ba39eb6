// Depth-limited JSON parsing that tracks the key path, so that every parse error names where it is.
#include "scene/json_text.hpp"

#include <vector>

#include "core/errors.hpp"

namespace scene {
namespace {

using nlohmann::json;

// Where the parser is: one entry per open array or object, with the index or key being read.
struct PathTracker {
  struct Level {
    bool array = false;
    long long index = 0;  // arrays: the element being read
    std::string key;      // objects: the last key
  };
  std::vector<Level> levels;

  std::string path() const {
    std::string text;
    for (const Level& level : levels) {
      const std::string part = level.array ? std::to_string(level.index) : level.key;
      if (part.empty()) break;
      text += (text.empty() ? "" : ".") + part;
    }
    return text.empty() ? "(top level)" : text;
  }
  void element_done() {
    if (!levels.empty() && levels.back().array) ++levels.back().index;
  }
};

struct TooDeep {};

}  // namespace

json parse_json_limited(const std::string& text, const std::string& what, bool comments) {
  PathTracker tracker;
  const json::parser_callback_t track = [&tracker](int, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        if (static_cast<int>(tracker.levels.size()) >= kMaxJsonDepth) throw TooDeep{};
        tracker.levels.push_back({event == json::parse_event_t::array_start, 0, ""});
        break;
      case json::parse_event_t::key: tracker.levels.back().key = parsed.get<std::string>(); break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        tracker.levels.pop_back();
        tracker.element_done();
        break;
      case json::parse_event_t::value: tracker.element_done(); break;
    }
    return true;
  };
  try {
    return json::parse(text, track, /*allow_exceptions=*/true, /*ignore_comments=*/comments);
  } catch (const TooDeep&) {
    throw softbody::InputError(what + ": " + tracker.path() + ": nested deeper than " + std::to_string(kMaxJsonDepth) +
                               " levels of arrays and objects (expected a scene document)");
  } catch (const json::out_of_range& e) {
    // nlohmann reports a number beyond the range of a double (1e400) as out_of_range 406.
    std::string detail = e.what();
    const std::size_t quote = detail.find('\'');
    detail = quote == std::string::npos ? detail : detail.substr(quote);
    throw softbody::InputError(what + ": " + tracker.path() + ": expected a finite number, got " + detail +
                               " (beyond the range of a double)");
  } catch (const json::exception& e) {
    throw softbody::InputError(what + ": not valid JSON (at " + tracker.path() + "): " + e.what());
  }
}

std::string describe_json(const json& value) {
  // Depth first with an explicit stack, stopping once a value is found to be deeper than kPrintDepth.
  constexpr int kPrintDepth = 8;
  std::vector<std::pair<const json*, int>> stack{{&value, 0}};
  while (!stack.empty()) {
    const auto [node, depth] = stack.back();
    stack.pop_back();
    if (!node->is_structured()) continue;
    if (depth >= kPrintDepth)
      return value.type_name() + std::string(" nested deeper than ") + std::to_string(kPrintDepth) + " levels";
    for (const json& child : *node) stack.emplace_back(&child, depth + 1);
    if (stack.size() > 4096)
      return value.type_name() + std::string(" of ") + std::to_string(value.size()) + " elements";
  }
  // Invalid UTF-8 (a --set value is taken as bytes) is replaced, not thrown about.
  std::string text = value.dump(-1, ' ', false, json::error_handler_t::replace);
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return value.type_name() + std::string(" ") + text;
}

}  // namespace scene
