// A fingerprint of what a scene simulates: a state cache made from one scene is refused for another.
#pragma once

#include <cstdint>
#include <string>

#include "scene/scene.hpp"

namespace setup {

// XXH3-64 over the program's version and build (setup::build_fingerprint), the scene's simulation JSON
// (scene::Scene::simulation_json: every key but name, render, camera, light and output, with --set applied) and
// the bytes of every mesh file it loads. Two scenes with the same hash simulate the same states. Throws
// softbody::InputError when a mesh file cannot be read.
std::uint64_t simulation_hash(const scene::Scene& scene);

// The hash as 16 lower-case hexadecimal digits.
std::string hash_text(std::uint64_t hash);

}  // namespace setup
