// The JSON Schema of scene files, generated from the table of scene keys.
#include "scene/scene_schema.hpp"

#include "scene/scene_keys.hpp"

namespace scene {
namespace {

using nlohmann::ordered_json;

ordered_json object_schema(const ObjectKeys& keys);

void add_bounds(ordered_json& schema, const Form& form) {
  if (form.minimum) schema[form.minimum->exclusive ? "exclusiveMinimum" : "minimum"] = form.minimum->value;
  if (form.maximum) schema[form.maximum->exclusive ? "exclusiveMaximum" : "maximum"] = form.maximum->value;
}

ordered_json number_schema(const Form& form, const char* type) {
  ordered_json schema{{"type", type}};
  add_bounds(schema, form);
  return schema;
}

ordered_json triple_schema(const Form& form) {
  return {{"type", "array"}, {"items", number_schema(form, "number")}, {"minItems", 3}, {"maxItems", 3}};
}

ordered_json integer_schema(const Form& form) {
  ordered_json schema{{"type", "integer"}};
  if (form.minimum) schema["minimum"] = static_cast<long long>(form.minimum->value);
  if (form.maximum) schema["maximum"] = static_cast<long long>(form.maximum->value);
  if (form.multiple_of != 0) schema["multipleOf"] = form.multiple_of;
  if (!form.excluded.empty()) schema["not"] = {{"enum", form.excluded}};
  return schema;
}

ordered_json string_schema(const Key& key) {
  ordered_json schema{{"type", "string"}, {"minLength", 1}};
  // maxLength counts characters, the parser bytes: the schema's bound is the necessary one.
  if (key.max_bytes != 0) schema["maxLength"] = key.max_bytes;
  if (!key.pattern.empty()) schema["pattern"] = key.pattern;
  if (!key.refused.empty()) schema["not"] = {{"enum", key.refused}};
  return schema;
}

// 1 to 64 distinct frame numbers (render.figure_frames).
ordered_json frame_list_schema() {
  return {{"type", "array"},
          {"items", {{"type", "integer"}, {"minimum", 0}, {"maximum", 1000000000}}},
          {"minItems", 1},
          {"maxItems", 64},
          {"uniqueItems", true}};
}

ordered_json form_schema(const Key& key, const Form& form) {
  switch (form.kind) {
    case FormKind::Number: return number_schema(form, "number");
    case FormKind::Integer: return integer_schema(form);
    case FormKind::Boolean: return {{"type", "boolean"}};
    case FormKind::String: return string_schema(key);
    case FormKind::Choice: return {{"enum", form.choices}};
    case FormKind::Vector:
    case FormKind::Color: return triple_schema(form);
    case FormKind::Null: return {{"type", "null"}};
    case FormKind::Object: return object_schema(*form.object);
    case FormKind::ObjectList: return {{"type", "array"}, {"items", object_schema(*form.object)}, {"minItems", 1}};
    case FormKind::FrameList: return frame_list_schema();
  }
  return {};
}

// The description with the unit and a default that is not a constant.
std::string described(const Key& key) {
  std::string text = key.description;
  if (!key.unit.empty()) text += " Unit: " + key.unit + ".";
  if (!key.default_words.empty()) text += " Default: " + key.default_words + ".";
  return text;
}

ordered_json key_schema(const Key& key) {
  ordered_json schema{{"description", described(key)}};
  if (!key.default_value.is_null()) schema["default"] = key.default_value;
  if (key.forms.size() == 1) {
    schema.update(form_schema(key, key.forms[0]));
    return schema;
  }
  ordered_json any_of = ordered_json::array();
  for (const Form& form : key.forms) any_of.push_back(form_schema(key, form));
  schema["anyOf"] = any_of;
  return schema;
}

ordered_json object_schema(const ObjectKeys& keys) {
  ordered_json schema{{"type", "object"}, {"description", keys.description}};
  ordered_json properties = ordered_json::object();
  ordered_json required = ordered_json::array();
  for (const Key& key : keys.keys) {
    properties[key.name] = key_schema(key);
    if (key.required) required.push_back(key.name);
  }
  schema["properties"] = properties;
  if (!required.empty()) schema["required"] = required;
  if (!keys.exactly_one_of.empty()) {
    ordered_json one_of = ordered_json::array();
    for (const std::string& name : keys.exactly_one_of) one_of.push_back({{"required", ordered_json::array({name})}});
    schema["oneOf"] = one_of;
  }
  schema["additionalProperties"] = false;
  return schema;
}

}  // namespace

ordered_json scene_schema() {
  ordered_json schema{{"$schema", "https://json-schema.org/draft/2020-12/schema"}, {"title", "softbody scene file"}};
  schema.update(object_schema(scene_keys()));
  return schema;
}

}  // namespace scene
