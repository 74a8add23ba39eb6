// References from a mesh file to other files (a glTF buffer's uri, an OBJ's mtllib), checked before assimp
// follows them: assimp opened a FIFO and blocked, and when a reference did not resolve it quietly opened a file
// of the same name beside the mesh file instead.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace mesh {

// Throws softbody::InputError (message without the mesh file's name) unless `reference`, as written at `where`
// ("whose buffers.0.uri"), names a regular file inside `folder` (the folder of the file that names it) or below
// it: a URL, an absolute path, a ".." step, a name that does not exist, a directory, FIFO or device are refused.
void check_referenced_file(std::string_view reference, const std::filesystem::path& folder, const std::string& where);

}  // namespace mesh
