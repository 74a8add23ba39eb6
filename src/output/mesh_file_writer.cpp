// OBJ, PLY and STL writers for a single TriMesh.
#include "output/mesh_file_writer.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "core/errors.hpp"
#include "output/atomic_file.hpp"
#include "output/obj_uvs.hpp"

namespace output {
namespace {

static_assert(std::endian::native == std::endian::little,
              "binary PLY and STL are written in native (little) endianness");

template <typename T>
void append_binary(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

// A comment fit for one header line: no line breaks.
std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  return text;
}

}  // namespace

std::optional<MeshFileFormat> mesh_file_format_of(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".obj") return MeshFileFormat::Obj;
  if (extension == ".ply") return MeshFileFormat::Ply;
  if (extension == ".stl") return MeshFileFormat::Stl;
  return std::nullopt;
}

std::string trimesh_to_obj(const mesh::TriMesh& mesh, const std::string& comment) {
  std::string text = "# " + one_line(comment) + "\n";
  text.reserve(text.size() + mesh.vertices.size() * 64 + mesh.triangles.size() * 24);
  char line[128];
  for (const mesh::Vec3& p : mesh.vertices) {
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", p.x(), p.y(), p.z());
    text += line;
  }
  int uv_count = 0;
  const std::vector<std::array<int, 3>> uv = append_obj_uvs(text, mesh.corner_uvs, uv_count);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    append_obj_face(text, mesh.triangles[f], 1, uv.empty() ? nullptr : &uv[f], 1);
  return text;
}

std::string trimesh_to_ply(const mesh::TriMesh& mesh, const std::string& comment) {
  std::string bytes = "ply\nformat binary_little_endian 1.0\ncomment " + one_line(comment) + "\nelement vertex " +
                      std::to_string(mesh.vertices.size()) +
                      "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
                      std::to_string(mesh.triangles.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  bytes.reserve(bytes.size() + mesh.vertices.size() * 24 + mesh.triangles.size() * 13);
  for (const mesh::Vec3& p : mesh.vertices) {
    for (int axis = 0; axis < 3; ++axis) append_binary(bytes, p[axis]);
  }
  for (const mesh::Triangle& t : mesh.triangles) {
    append_binary(bytes, static_cast<std::uint8_t>(3));
    for (int corner : t) append_binary(bytes, static_cast<std::int32_t>(corner));
  }
  return bytes;
}

std::string trimesh_to_stl(const mesh::TriMesh& mesh, const std::string& comment) {
  std::string header = one_line(comment).substr(0, 79);  // 80 bytes, and never starting with "solid" (ASCII STL's mark)
  if (header.rfind("solid", 0) == 0) header = "mesh " + header.substr(0, 74);
  header.resize(80, ' ');
  std::string bytes = header;
  bytes.reserve(84 + mesh.triangles.size() * 50);
  append_binary(bytes, static_cast<std::uint32_t>(mesh.triangles.size()));
  for (const mesh::Triangle& t : mesh.triangles) {
    const mesh::Vec3& a = mesh.vertices[static_cast<std::size_t>(t[0])];
    const mesh::Vec3& b = mesh.vertices[static_cast<std::size_t>(t[1])];
    const mesh::Vec3& c = mesh.vertices[static_cast<std::size_t>(t[2])];
    const mesh::Vec3 normal = (b - a).cross(c - a).normalized();  // right-hand rule: outward for CCW from outside
    for (int axis = 0; axis < 3; ++axis) append_binary(bytes, static_cast<float>(normal[axis]));
    for (const mesh::Vec3* p : {&a, &b, &c}) {
      for (int axis = 0; axis < 3; ++axis) append_binary(bytes, static_cast<float>((*p)[axis]));
    }
    append_binary(bytes, static_cast<std::uint16_t>(0));  // attribute byte count
  }
  return bytes;
}

void write_mesh_file(const std::filesystem::path& path, const mesh::TriMesh& mesh, const std::string& comment) {
  const std::optional<MeshFileFormat> format = mesh_file_format_of(path);
  if (!format) {
    throw softbody::InputError(path.string() + ": expected a file name ending in .obj, .ply or .stl, got \"" +
                               path.extension().string() + "\"");
  }
  switch (*format) {
    case MeshFileFormat::Obj: write_file_atomically(path, trimesh_to_obj(mesh, comment)); break;
    case MeshFileFormat::Ply: write_file_atomically(path, trimesh_to_ply(mesh, comment)); break;
    case MeshFileFormat::Stl: write_file_atomically(path, trimesh_to_stl(mesh, comment)); break;
  }
}

}  // namespace output
