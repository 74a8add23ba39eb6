// libFuzzer harness for the scene text: parse (depth limit, comments), --set overrides, validation. The input
// is the scene text, then after a NUL byte one --set assignment per line. Only softbody::InputError may
// come out: any other exception, a crash, a hang or a sanitizer finding is a bug.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "scene/overrides.hpp"
#include "scene/scene_json.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const std::size_t nul = input.find('\0');
  const std::string text(input.substr(0, nul));
  std::vector<std::string> assignments;
  if (nul != std::string_view::npos) {
    std::string_view rest = input.substr(nul + 1);
    while (!rest.empty()) {
      const std::size_t newline = rest.find('\n');
      assignments.emplace_back(rest.substr(0, newline));
      rest = newline == std::string_view::npos ? std::string_view() : rest.substr(newline + 1);
    }
  }
  try {
    // A file name whose folder holds no mesh files: mesh paths resolve under /nonexistent.
    nlohmann::json document = scene::parse_scene_text(text, "/nonexistent/fuzz.json");
    for (const std::string& assignment : assignments) scene::apply_override(document, assignment);
    scene::scene_from_json(document, "/nonexistent/fuzz.json");
  } catch (const softbody::InputError&) {
  }
  return 0;
}
