// The surface a body is simulated on when it asks for a "resolution": its mesh remeshed isotropically.
#pragma once

#include <string>
#include <vector>

#include "mesh/trimesh.hpp"
#include "scene/scene.hpp"

namespace setup {

// True when the body asks to be simulated on a proxy ("resolution" in either form).
bool wants_proxy(const scene::Body& spec);

// `detailed` (validated, closed, in mesh units) remeshed to the body's resolution: about
// spec.resolution_vertices vertices, or edges of about spec.resolution_edge_length_m once placed (divided by
// spec.scale in mesh units). Validated like a loaded mesh; a note says what it became. Throws
// softbody::InputError naming `key_path`.resolution when the remesh cannot be used.
mesh::TriMesh simulation_proxy(const mesh::TriMesh& detailed, const scene::Body& spec, const std::string& key_path,
                               std::vector<std::string>& notes);

}  // namespace setup
