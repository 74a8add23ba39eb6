// The scene's simulation hash.
#include "setup/scene_hash.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

#include <xxhash.h>

#include "core/errors.hpp"
#include "setup/build_fingerprint.hpp"
#include "setup/collider_point_caches.hpp"

namespace setup {

std::uint64_t simulation_hash(const scene::Scene& scene) {
  XXH3_state_t* state = XXH3_createState();
  XXH3_64bits_reset(state);
  const std::string version = SOFTBODY_VERSION;
  XXH3_64bits_update(state, version.data(), version.size() + 1);  // the terminating zero separates the parts
  const std::string build = build_fingerprint();
  XXH3_64bits_update(state, build.data(), build.size() + 1);
  XXH3_64bits_update(state, scene.simulation_json.data(), scene.simulation_json.size() + 1);
  std::vector<std::filesystem::path> files;
  for (const scene::Body& body : scene.bodies) files.push_back(body.mesh_file);
  for (const scene::ColliderMeshSource& collider : scene.collider_meshes) {
    files.push_back(collider.mesh_file);
    for (const std::filesystem::path& file : point_cache_files(collider)) files.push_back(file);
  }
  for (const std::filesystem::path& file : files) {
    if (file.empty()) continue;
    std::ifstream in(file, std::ios::binary);
    if (!in.is_open()) {
      XXH3_freeState(state);
      throw softbody::InputError(file.string() + ": cannot read the mesh file to hash the scene");
    }
    std::stringstream bytes;
    bytes << in.rdbuf();
    const std::string content = bytes.str();
    XXH3_64bits_update(state, content.data(), content.size());
  }
  const std::uint64_t hash = XXH3_64bits_digest(state);
  XXH3_freeState(state);
  return hash;
}

std::string hash_text(std::uint64_t hash) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

}  // namespace setup
