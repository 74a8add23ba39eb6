// OBJ and PLY writers for frame sequences.
#include "output/mesh_exporter.hpp"

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "core/profile.hpp"
#include "output/atomic_file.hpp"
#include "output/frame_pattern.hpp"
#include "output/obj_uvs.hpp"
#include "output/shown_surface.hpp"

namespace output {
namespace {

static_assert(std::endian::native == std::endian::little, "binary PLY is written in native (little) endianness");

template <typename T>
void append_binary(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

}  // namespace

MeshExporter::MeshExporter(std::filesystem::path dir, MeshFormat format) : dir_(std::move(dir)), format_(format) {
  std::filesystem::create_directories(dir_);
}

std::string MeshExporter::frame_pattern() const {
  return format_ == MeshFormat::Obj ? "frame_%04d.obj" : "frame_%04d.ply";
}

std::filesystem::path MeshExporter::frame_path(int index) const {
  return dir_ / frame_file_name(frame_pattern(), index);
}

void MeshExporter::on_frame(int index, double time_s, const sim::World& world) {
  const softbody::ProfileScope profile(softbody::ProfilePhase::mesh_write);
  const std::string bytes = format_ == MeshFormat::Obj ? world_to_obj(world, time_s) : world_to_ply(world, time_s);
  write_file_atomically(frame_path(index), bytes);
  if (stored_) stored_(frame_path(index), bytes);
}

void MeshExporter::after_each_file(std::function<void(const std::filesystem::path&, std::string_view)> stored) {
  stored_ = std::move(stored);
}

void MeshExporter::finish(bool /*complete*/) {}

int append_obj_object(std::string& text, const sim::World& world, int body_index, int first_index, int first_uv_index) {
  char line[160];
  std::snprintf(line, sizeof line, "o body%d\n", body_index);
  text += line;
  ShownPositions shown;
  for (const softbody::Vec3& p : shown.of(world, body_index)) {
    std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p.x(), p.y(), p.z());
    text += line;
  }
  int uv_count = 0;
  const std::vector<std::array<int, 3>> uv = append_obj_uvs(text, world.model.shown_corner_uvs(body_index), uv_count);
  const std::span<const softbody::Triangle> faces = shown_triangles(world, body_index);
  for (std::size_t f = 0; f < faces.size(); ++f)
    append_obj_face(text, faces[f], first_index, uv.empty() ? nullptr : &uv[f], first_uv_index);
  return uv_count;
}

std::string world_to_obj(const sim::World& world, double time_s) {
  std::string text;
  char line[160];
  std::snprintf(line, sizeof line, "# softbody frame at t = %.9g s\n", time_s);
  text += line;
  int first_index = 1, first_uv_index = 1;
  for (std::size_t b = 0; b < world.model.bodies.size(); ++b) {
    first_uv_index += append_obj_object(text, world, static_cast<int>(b), first_index, first_uv_index);
    first_index += shown_vertex_count(world, static_cast<int>(b));
  }
  return text;
}

std::string world_to_ply(const sim::World& world, double time_s) {
  const int bodies = static_cast<int>(world.model.bodies.size());
  std::size_t vertices = 0, faces = 0;
  for (int b = 0; b < bodies; ++b) {
    vertices += static_cast<std::size_t>(shown_vertex_count(world, b));
    faces += shown_triangles(world, b).size();
  }
  char header[512];
  std::snprintf(header, sizeof header,
                "ply\nformat binary_little_endian 1.0\ncomment softbody frame at t = %.9g s\n"
                "element vertex %zu\nproperty float x\nproperty float y\nproperty float z\n"
                "element face %zu\nproperty list uchar int vertex_indices\nend_header\n",
                time_s, vertices, faces);
  std::string bytes = header;
  bytes.reserve(bytes.size() + vertices * 12 + faces * 13);
  ShownPositions shown;
  for (int b = 0; b < bodies; ++b) {
    for (const softbody::Vec3& p : shown.of(world, b)) {
      for (int axis = 0; axis < 3; ++axis) append_binary(bytes, static_cast<float>(p[axis]));
    }
  }
  int first_vertex = 0;  // the body's first vertex in the file's one vertex list
  for (int b = 0; b < bodies; ++b) {
    for (const softbody::Triangle& f : shown_triangles(world, b)) {
      append_binary(bytes, static_cast<std::uint8_t>(3));
      for (int corner : f) append_binary(bytes, static_cast<std::int32_t>(corner + first_vertex));
    }
    first_vertex += shown_vertex_count(world, b);
  }
  return bytes;
}

}  // namespace output
