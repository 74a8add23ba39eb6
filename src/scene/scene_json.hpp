// Reading scene files: JSON with // comments, every key validated, --set overrides applied first.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "scene/scene.hpp"

namespace scene {

// Reads, overrides and validates a scene file. Throws softbody::InputError naming the file, the key
// path (e.g. "bodies.0.mass") and what was expected.
Scene load_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});

// Validates an already parsed document; `file` names it in messages and anchors relative mesh paths.
Scene scene_from_json(const nlohmann::json& document, const std::filesystem::path& file);

// Parses scene text (JSON, // and /* */ comments allowed).
nlohmann::json parse_scene_text(const std::string& text, const std::filesystem::path& file);

}  // namespace scene
