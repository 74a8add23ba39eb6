// The guide's key reference (docs/guide/scene-keys.md), generated from the table of scene keys.
#include <sstream>

#include "scene/scene_keys.hpp"
#include "scene/scene_schema.hpp"

namespace scene {
namespace {

// How the guide names the object a form reads: a link to its own section.
std::string object_link(const ObjectKeys& keys) {
  std::string anchor;
  for (const char c : keys.path) {
    if (c == '[' || c == ']' || c == '.') continue;
    anchor += c;
  }
  return "[object](#" + anchor + ")";
}

std::string quoted_choices(const Form& form) {
  std::string text;
  for (const std::string& choice : form.choices) text += (text.empty() ? "" : ", ") + ("`\"" + choice + "\"`");
  return text;
}

std::string integer_range(const Form& form) {
  std::string text = std::to_string(static_cast<long long>(form.minimum->value)) + " to " +
                     std::to_string(static_cast<long long>(form.maximum->value));
  if (form.multiple_of != 0) text += ", a multiple of " + std::to_string(form.multiple_of);
  for (const long long x : form.excluded) text += ", not " + std::to_string(x);
  return text;
}

// One form as the table's type column says it, with its range or values.
std::string form_words(const Form& form) {
  switch (form.kind) {
    case FormKind::Number: {
      const std::string range = range_words(form);
      return range.empty() ? "number" : "number" + range;
    }
    case FormKind::Integer: return "integer " + integer_range(form);
    case FormKind::Boolean: return "boolean";
    case FormKind::String: return "string";
    case FormKind::Choice: return form.choices.size() == 1 ? quoted_choices(form) : "one of " + quoted_choices(form);
    case FormKind::Vector: return "[x, y, z], each" + range_words(form);
    case FormKind::Color: return "[r, g, b], each in [0, 1]";
    case FormKind::Null: return "null";
    case FormKind::Object: return object_link(*form.object);
    case FormKind::ObjectList: return "array of at least one " + object_link(*form.object);
    case FormKind::FrameList: return "array of 1 to 64 distinct frame numbers";
  }
  return "";
}

std::string type_words(const Key& key) {
  std::string text;
  for (const Form& form : key.forms) text += (text.empty() ? "" : "; or ") + form_words(form);
  return text;
}

// A default value as a scene file would write it: 1e-4 rather than 0.0001.
std::string value_words(const nlohmann::json& value) {
  if (value.is_number_float()) return short_number(value.get<double>());
  if (!value.is_array()) return value.dump();
  std::string text;
  for (const nlohmann::json& item : value) text += (text.empty() ? "" : ", ") + value_words(item);
  return "[" + text + "]";
}

std::string default_words(const Key& key) {
  if (key.required) return "required";
  if (!key.default_value.is_null()) {
    std::string text = "`";
    text += value_words(key.default_value);
    return text + "`";
  }
  return key.default_words.empty() ? "—" : key.default_words;
}

// Text for a table cell: a | would end the cell.
std::string cell(const std::string& text) {
  std::string escaped;
  for (const char c : text) escaped += c == '|' ? std::string("\\|") : std::string(1, c);
  return escaped;
}

void write_object(std::ostringstream& out, const ObjectKeys& keys) {
  out << "\n## " << keys.path << "\n\n" << keys.description << "\n\n";
  if (!keys.exactly_one_of.empty()) {
    out << "Exactly one of";
    for (std::size_t i = 0; i < keys.exactly_one_of.size(); ++i) {
      out << (i == 0 ? " `" : i + 1 == keys.exactly_one_of.size() ? " and `" : ", `") << keys.exactly_one_of[i] << "`";
    }
    out << " must be given.\n\n";
  }
  out << "| Key | Type and range | Unit | Default | Description |\n";
  out << "|---|---|---|---|---|\n";
  for (const Key& key : keys.keys) {
    out << "| `" << key.name << "` | " << type_words(key) << " | " << key.unit << " | " << default_words(key) << " | "
        << cell(key.description) << " |\n";
  }
}

}  // namespace

std::string scene_key_reference() {
  std::ostringstream out;
  out << "# Scene keys\n\n"
      << "Every key a scene file may hold, generated from the table the parser reads its keys from "
      << "(`softbody schema --markdown`; `softbody schema` prints the same as a JSON Schema). Unknown keys are "
      << "refused. Numbers must be finite. `--set PATH=VALUE` changes a key on the command line, e.g. "
      << "`--set bodies.0.mass=2`.\n";
  for (const ObjectKeys* keys : all_objects()) write_object(out, *keys);
  return out.str();
}

}  // namespace scene
