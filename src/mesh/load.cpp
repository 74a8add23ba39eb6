// Generator or file → weld → validate: the closed surface a body is built from.
#include "mesh/load.hpp"

#include "core/errors.hpp"
#include "mesh/check.hpp"
#include "mesh/generators.hpp"
#include "mesh/import.hpp"
#include "mesh/weld.hpp"

namespace mesh {

LoadedMesh load_closed_mesh(const std::string& spec, const std::filesystem::path& file, const std::string& context) {
  const std::string what = file.empty() ? spec : file.string();
  try {
    LoadedMesh loaded;
    loaded.mesh = file.empty() ? generate(spec) : weld(import_mesh_file(file));
    validate_closed(loaded.mesh, loaded.notes);
    for (std::string& note : loaded.notes) note = context + ": " + what + ": " + note;
    return loaded;
  } catch (const softbody::InputError& e) {
    throw softbody::InputError(context + ": mesh " + what + " " + e.what());
  }
}

}  // namespace mesh
