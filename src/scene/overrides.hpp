// `--set PATH=VALUE` overrides: change one key of a scene document before it is validated.
#pragma once

#include <string>

#include <nlohmann/json_fwd.hpp>

namespace scene {

// Applies "a.b.0.c=VALUE" to the document. VALUE is read as JSON when it parses as JSON
// (numbers, true/false, [1,2,3], {"k": 1}) and as a plain string otherwise (e.g. euler).
// Objects on the path are created when missing; array indices must exist.
// Throws softbody::InputError naming the override and what is wrong.
void apply_override(nlohmann::json& document, const std::string& assignment);

}  // namespace scene
