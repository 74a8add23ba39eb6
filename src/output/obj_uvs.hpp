// Texture coordinates in OBJ files: per-corner UVs as "vt" lines (each distinct pair once) and faces that name
// them, so that Blender and other readers show the mesh file's UVs on an exported or prepared mesh.
#pragma once

#include <array>
#include <span>
#include <string>
#include <vector>

#include "core/vec.hpp"

namespace output {

// Appends "vt u v" (9 significant digits: a file's float UVs read back bit for bit) for each distinct (u, v)
// of `corner_uvs`, in the order of first use; returns each triangle's corners' 0-based indices among them and
// adds their number to `count`.
std::vector<std::array<int, 3>> append_obj_uvs(std::string& text, std::span<const softbody::CornerUvs> corner_uvs,
                                               int& count);

// Appends "f a b c" (`first_vertex`: the 1-based OBJ index of vertex 0), or with `uv` "f a/ta b/tb c/tc"
// (`first_uv`: the 1-based index of the object's first "vt").
void append_obj_face(std::string& text, const softbody::Triangle& face, int first_vertex, const std::array<int, 3>* uv,
                     int first_uv);

}  // namespace output
