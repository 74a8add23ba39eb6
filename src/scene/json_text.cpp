// Depth-limited JSON parsing that tracks the key path, so that every parse error names where it is.
#include "scene/json_text.hpp"

#include <optional>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/errors.hpp"
#include "core/one_line.hpp"

namespace scene {
namespace {

using nlohmann::json;

// The largest length <= `at` that does not cut a UTF-8 sequence of `text`.
std::size_t utf8_boundary(const std::string& text, std::size_t at) {
  while (at > 0 && at < text.size() && (static_cast<unsigned char>(text[at]) & 0xC0) == 0x80) --at;
  return at;
}

// Where the parser is: one entry per open array or object, with the index or key being read, and for objects
// the keys read so far with their values as messages print them (a key given twice is refused with both).
struct PathTracker {
  struct Level {
    bool array = false;
    long long index = 0;                                  // arrays: the element being read
    std::string key;                                      // objects: the last key
    std::unordered_map<std::string, std::string> values;  // objects: each key read, and its value described
    std::optional<std::string> earlier_value;             // the last key was read before, with this value
  };
  std::vector<Level> levels;

  std::string path() const {
    std::string text;
    for (const Level& level : levels) {
      const std::string part = level.array ? std::to_string(level.index) : level.key;
      if (part.empty()) break;
      text += (text.empty() ? "" : ".") + part;
    }
    return text.empty() ? "(top level)" : message_text(text);
  }
  void key_read(const std::string& key);
  void element_done(const json& value);
};

struct TooDeep {};
struct DuplicateKey {
  std::string earlier, later;  // the two values, described
};

void PathTracker::key_read(const std::string& key) {
  Level& level = levels.back();
  level.key = key;
  const auto [earlier, fresh] = level.values.emplace(key, "");
  if (!fresh) level.earlier_value = earlier->second;
}

void PathTracker::element_done(const json& value) {
  if (levels.empty()) return;
  Level& level = levels.back();
  if (level.array) {
    ++level.index;
    return;
  }
  // Structured values are named by their type only: describing every object as it ends would cost.
  std::string described = value.is_structured() ? std::string("an ") + value.type_name() : describe_json(value);
  if (level.earlier_value) throw DuplicateKey{*level.earlier_value, described};
  level.values[level.key] = std::move(described);
}

}  // namespace

json parse_json_limited(const std::string& text, const std::string& what, bool comments) {
  PathTracker tracker;
  const json::parser_callback_t track = [&tracker](int, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        if (static_cast<int>(tracker.levels.size()) >= kMaxJsonDepth) throw TooDeep{};
        tracker.levels.push_back({event == json::parse_event_t::array_start, 0, "", {}, {}});
        break;
      case json::parse_event_t::key: tracker.key_read(parsed.get<std::string>()); break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        tracker.levels.pop_back();
        tracker.element_done(parsed);
        break;
      case json::parse_event_t::value: tracker.element_done(parsed); break;
    }
    return true;
  };
  try {
    return json::parse(text, track, /*allow_exceptions=*/true, /*ignore_comments=*/comments);
  } catch (const TooDeep&) {
    throw softbody::InputError(what + ": " + tracker.path() + ": nested deeper than " + std::to_string(kMaxJsonDepth) +
                               " levels of arrays and objects (expected a scene document)");
  } catch (const DuplicateKey& duplicate) {
    throw softbody::InputError(what + ": " + tracker.path() + ": expected each key once in an object, got it twice: " +
                               duplicate.earlier + ", then " + duplicate.later);
  } catch (const json::out_of_range& e) {
    // nlohmann reports a number beyond the range of a double (1e400) as out_of_range 406.
    std::string detail = e.what();
    const std::size_t quote = detail.find('\'');
    detail = quote == std::string::npos ? detail : detail.substr(quote);
    throw softbody::InputError(what + ": " + tracker.path() + ": expected a finite number, got " +
                               message_text(detail, 60) + " (beyond the range of a double)");
  } catch (const json::exception& e) {
    throw softbody::InputError(what + ": not valid JSON (at " + tracker.path() + "): " + message_text(e.what(), 200));
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
  if (text.size() > 40) {
    text = text.substr(0, utf8_boundary(text, 37)) + "...";
    if (value.is_string()) text += " (" + std::to_string(value.get_ref<const std::string&>().size()) + " bytes)";
    if (value.is_structured()) text += " (" + std::to_string(value.size()) + " elements)";
  }
  return value.type_name() + std::string(" ") + text;
}

std::string message_text(const std::string& text, std::size_t most) {
  // One more byte than fits: an escaped byte never shows shorter than itself, so the cut is decided by these.
  const std::string shown = softbody::one_line(std::string_view(text).substr(0, most + 1));
  if (text.size() <= most && shown.size() <= most) return shown;
  return shown.substr(0, utf8_boundary(shown, most - 3)) + "... (" + std::to_string(text.size()) + " bytes)";
}

}  // namespace scene
