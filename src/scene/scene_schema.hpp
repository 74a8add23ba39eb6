// The JSON Schema (draft 2020-12) of scene files and the guide's key reference, both generated from the table
// of scene keys (scene_keys.hpp) that the parser reads.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace scene {

// The schema, keys in the order the parser reads them: `softbody schema` prints it.
nlohmann::ordered_json scene_schema();

// The key reference in Markdown, one table per object: `softbody schema --markdown`, docs/guide/scene-keys.md.
std::string scene_key_reference();

}  // namespace scene
