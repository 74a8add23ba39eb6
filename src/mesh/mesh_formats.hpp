// The mesh file formats softbody reads, by file name extension, and an assimp importer limited to their readers.
#pragma once

#include <filesystem>
#include <string>

namespace Assimp {
class Importer;
}

namespace mesh {

// ".obj", ".ply", ... for `file` (lower case; "" without an extension).
std::string lower_case_extension(const std::filesystem::path& file);

// Throws softbody::InputError (message without the file name) unless `file`'s extension is one of the documented
// formats: OBJ, PLY, STL, glTF (.gltf, .glb), OFF and FBX. assimp 5.2 reads some forty more, most of them rarely
// used and never fuzzed here (deeply nested X3D, COLLADA or AMF crash its recursive XML readers), so they are
// refused by name before assimp sees the file.
void check_format_is_accepted(const std::filesystem::path& file);

// Unregisters (and deletes) every reader of `importer` except those of the accepted formats, so that assimp's
// detection by content can never hand a file to another reader; the glTF 1.0 reader goes too (glTF 2.0 only).
void keep_only_accepted_readers(Assimp::Importer& importer);

}  // namespace mesh
