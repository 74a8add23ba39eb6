// One TriMesh written as an OBJ, PLY or STL file, the format chosen by the file's extension (`softbody prepare`).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "mesh/trimesh.hpp"

namespace output {

enum class MeshFileFormat { Obj, Ply, Stl };

// .obj, .ply or .stl (any case); nullopt for any other extension.
std::optional<MeshFileFormat> mesh_file_format_of(const std::filesystem::path& path);

// OBJ text: "v x y z" with 17 significant digits (the doubles read back bit for bit), "f a b c" 1-based.
std::string trimesh_to_obj(const mesh::TriMesh& mesh, const std::string& comment);

// Binary little-endian PLY with double coordinates (read back bit for bit) and int vertex indices.
std::string trimesh_to_ply(const mesh::TriMesh& mesh, const std::string& comment);

// Binary STL: float coordinates (the format has no others), each triangle's unit normal, no shared vertices
// (a reader welds them again).
std::string trimesh_to_stl(const mesh::TriMesh& mesh, const std::string& comment);

// Writes `mesh` to `path` whole or not at all (output/atomic_file.hpp) in the format its extension names.
// Throws softbody::InputError for an extension other than .obj, .ply or .stl.
void write_mesh_file(const std::filesystem::path& path, const mesh::TriMesh& mesh, const std::string& comment);

}  // namespace output
