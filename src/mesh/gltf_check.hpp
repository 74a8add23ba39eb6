// glTF documents checked before assimp reads them: assimp 5.2's glTF 2 reader dereferences what a document
// promises (a primitive's POSITION accessor, an accessor's buffer view), so every reference is checked here.
#pragma once

#include <string_view>

namespace mesh {

// Throws softbody::InputError (message without the file name) unless `json_text`, the JSON of a glTF 2
// document (a .gltf file or a GLB file's JSON chunk), parses, and every mesh primitive has a POSITION
// attribute, a drawing mode of 0..6, and attribute and index accessors that exist, whose buffer views and
// buffers exist too. A glTF 1.0 document (asset.version "1.x") is not checked.
void check_gltf_document(std::string_view json_text);

}  // namespace mesh
