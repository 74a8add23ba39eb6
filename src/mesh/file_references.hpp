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
// it: a URL, an absolute path, a ".." step, a name that does not exist, a directory, FIFO or device, and a
// symbolic link (the file's or a folder's on its way) that leads out of `folder` are refused.
void check_referenced_file(std::string_view reference, const std::filesystem::path& folder, const std::string& where);

// The same for a URI relative to the file (glTF's uri, RFC 3986): it is percent-decoded first ("cube%2Ebin" names
// cube.bin, "..%2Fx.bin" leaves the folder), and its message quotes it as written. A '%' not followed by two
// hexadecimal digits, or one that decodes to a NUL, is refused.
void check_referenced_uri(std::string_view uri, const std::filesystem::path& folder, const std::string& where);

// `uri` with every %XX replaced by the byte it stands for; throws softbody::InputError (naming `where` and the
// uri) where a '%' is not followed by two hexadecimal digits or stands for a NUL.
std::string percent_decoded(std::string_view uri, const std::string& where);

}  // namespace mesh
