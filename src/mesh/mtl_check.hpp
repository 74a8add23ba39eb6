// An OBJ's material library (MTL), checked before assimp's OBJ reader parses it: assimp 5.2 writes through a null
// material when a texture statement (map_Kd, bump, disp, norm, ...) comes before the library's first newmtl
// (SIGSEGV; found by fuzz_mesh_mtl).
#pragma once

#include <string>
#include <string_view>

namespace mesh {

// Throws softbody::InputError ("`where` has ... on line N ...") unless every line of `text` before its first
// "newmtl" statement is blank or a comment. Lines end where assimp ends them (LF, CR, form feed, NUL); blanks
// before a statement are skipped, a UTF-8 byte order mark at the start too.
void check_material_library(std::string_view text, const std::string& where);

}  // namespace mesh
