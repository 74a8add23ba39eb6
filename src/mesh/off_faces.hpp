// OFF face indices checked against the file's own vertex count: assimp 5.2's OFF reader clamps an index past the
// vertices to the last vertex (logging an error nobody sees), which turned a wrong file into a wrong mesh.
#pragma once

#include <string_view>

namespace mesh {

// Throws softbody::InputError (message without the file name) when a face of the OFF file `text` (whole) names a
// vertex index at or past the vertex count of its header. The file is walked as assimp's reader walks it (its
// header keywords, counts, then one vertex or face per non-empty line); a file it cannot walk is left to assimp.
void check_off_face_indices(std::string_view text);

}  // namespace mesh
