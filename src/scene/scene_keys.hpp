// Every key a scene file may hold, as one table: the parser (scene_json.cpp) reads its keys, types,
// ranges and defaults from it, and the JSON Schema and the guide's key reference are generated from it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace scene {

struct ObjectKeys;

// One shape a key's value may take. A key with several forms takes any one of them ("dt": 1e-4 or "auto").
enum class FormKind {
  Number,      // a finite number within the range
  Integer,     // a whole number within the range (and a multiple of multiple_of)
  Boolean,     // true or false
  String,      // a non-empty string
  Choice,      // one of the strings in `choices`
  Vector,      // an array of 3 numbers, each within the range (a point, a velocity, a direction)
  Color,       // an array of 3 numbers, each in [0, 1] (linear RGB)
  Null,        // null: as if the key were left out
  Object,      // an object of the keys in `object`
  ObjectList,  // an array of at least one object of the keys in `object`
  FrameList,   // an array of 1 to 64 distinct frame numbers (integers >= 0)
};

// A bound of a number's range.
struct Bound {
  double value = 0.0;
  bool exclusive = false;  // the value itself is outside the range
};

struct Form {
  FormKind kind = FormKind::Number;
  std::optional<Bound> minimum;
  std::optional<Bound> maximum;
  std::string range_words;           // how messages say the range (" > 0"); empty: made from the bounds
  int multiple_of = 0;               // Integer: values must be multiples of this (0: any)
  std::vector<long long> excluded;   // Integer: values refused although inside the range
  std::vector<std::string> choices;  // Choice: the accepted strings, in the order messages list them
  const ObjectKeys* object = nullptr;
};

// What a file name and a path may be: a file system's limits (NAME_MAX, PATH_MAX less its NUL). Names and paths
// hold no control character either (a NUL would cut the name short, a line break would split a message).
inline constexpr std::size_t kMaxFileNameBytes = 255;
inline constexpr std::size_t kMaxPathBytes = 4095;

// One key of an object.
struct Key {
  std::string name;
  std::vector<Form> forms;
  std::string unit;              // SI unit of a number ("m", "kg", "N/m"); empty: none
  std::string description;       // one or two sentences for the schema and the guide
  nlohmann::json default_value;  // what the parser fills in when the key is left out; null: none (see default_words)
  std::string default_words;     // a default that is not a constant ("the scene file's name"); empty: none
  bool required = false;
  std::string pattern;  // String: a regular expression (ECMA 262) the value matches (the schema's "pattern")
  std::vector<std::string> refused;  // String: values refused although they match
  std::size_t max_bytes = 0;         // String: the most bytes of UTF-8 (0: no bound); the schema's maxLength
  bool names_file = false;           // String: becomes a file or folder name: no control characters, and each
                                     // /-separated part at most kMaxFileNameBytes

  const Form& form(FormKind kind) const;  // throws std::logic_error when the key has no such form
  bool accepts(FormKind kind) const;
};

// The keys of one object (the top level, "solver", a body, ...).
struct ObjectKeys {
  std::string path;  // how the guide names the object: "solver", "bodies[]", "bodies[].stiffness"
  std::string description;
  std::vector<Key> keys;
  std::vector<std::string> exactly_one_of;  // of these keys, exactly one must be given (empty: no such rule)

  const Key& key(const std::string& name) const;  // throws std::logic_error for a key not in the table
};

// The top level of a scene file; every other object is reachable from it through Form::object.
const ObjectKeys& scene_keys();

// Every object of the table, the top level first, each once, in the order the guide lists them.
std::vector<const ObjectKeys*> all_objects();

// How a message says a number's range: " > 0", " >= 0", " in [0, 1]", " within +-1e6".
std::string range_words(const Form& form);

// A number as messages and the guide write it: 0.002, 1e-6, 1e6.
std::string short_number(double x);

}  // namespace scene
