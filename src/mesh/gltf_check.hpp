// glTF documents checked before assimp reads them: assimp 5.2's glTF 2 reader dereferences what a document
// promises (a primitive's POSITION accessor, an accessor's buffer view), so every reference is checked here.
#pragma once

#include <filesystem>
#include <string_view>

namespace mesh {

// Throws softbody::InputError (message without the file name) unless `json_text`, the JSON of a glTF
// document (a .gltf file or a GLB file's JSON chunk), nests at most kMostNestingLevels deep, parses, and every
// buffer's uri is embedded data or a regular file inside `folder` (the document's folder, see
// check_referenced_file); and, for glTF 2, every mesh primitive has a POSITION attribute, a drawing mode of 0..6,
// and attribute and index accessors that exist, whose buffer views and buffers exist too.
void check_gltf_document(std::string_view json_text, const std::filesystem::path& folder);

}  // namespace mesh
