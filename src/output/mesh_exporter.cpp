// OBJ and PLY writers for frame sequences.
#include "output/mesh_exporter.hpp"

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "output/atomic_file.hpp"

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

std::filesystem::path MeshExporter::frame_path(int index) const {
  char name[64];
  std::snprintf(name, sizeof name, "frame_%04d.%s", index, format_ == MeshFormat::Obj ? "obj" : "ply");
  return dir_ / name;
}

void MeshExporter::on_frame(int index, double time_s, const sim::World& world) {
  write_file_atomically(frame_path(index), format_ == MeshFormat::Obj ? world_to_obj(world, time_s) : world_to_ply(world, time_s));
}

void MeshExporter::finish(bool /*complete*/) {}

void append_obj_object(std::string& text, const sim::World& world, int body_index, int first_index) {
  const sim::Body& body = world.model.bodies[static_cast<std::size_t>(body_index)];
  char line[160];
  std::snprintf(line, sizeof line, "o body%d\n", body_index);
  text += line;
  for (const softbody::Vec3& p : world.model.of(body, world.state.x)) {
    std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p.x(), p.y(), p.z());
    text += line;
  }
  for (const softbody::Triangle& f : body.topology.faces) {
    std::snprintf(line, sizeof line, "f %d %d %d\n", f[0] + first_index, f[1] + first_index, f[2] + first_index);
    text += line;
  }
}

std::string world_to_obj(const sim::World& world, double time_s) {
  std::string text;
  char line[160];
  std::snprintf(line, sizeof line, "# softbody frame at t = %.9g s\n", time_s);
  text += line;
  int first_index = 1;
  for (std::size_t b = 0; b < world.model.bodies.size(); ++b) {
    append_obj_object(text, world, static_cast<int>(b), first_index);
    first_index += world.model.bodies[b].vertex_count;
  }
  return text;
}

std::string world_to_ply(const sim::World& world, double time_s) {
  std::size_t vertices = 0, faces = 0;
  for (const sim::Body& body : world.model.bodies) {
    vertices += static_cast<std::size_t>(body.vertex_count);
    faces += body.topology.faces.size();
  }
  char header[512];
  std::snprintf(header, sizeof header,
                "ply\nformat binary_little_endian 1.0\ncomment softbody frame at t = %.9g s\n"
                "element vertex %zu\nproperty float x\nproperty float y\nproperty float z\n"
                "element face %zu\nproperty list uchar int vertex_indices\nend_header\n",
                time_s, vertices, faces);
  std::string bytes = header;
  bytes.reserve(bytes.size() + vertices * 12 + faces * 13);
  for (const sim::Body& body : world.model.bodies) {
    for (const softbody::Vec3& p : world.model.of(body, world.state.x)) {
      for (int axis = 0; axis < 3; ++axis) append_binary(bytes, static_cast<float>(p[axis]));
    }
  }
  for (const sim::Body& body : world.model.bodies) {
    for (const softbody::Triangle& f : body.topology.faces) {
      append_binary(bytes, static_cast<std::uint8_t>(3));
      for (int corner : f) append_binary(bytes, static_cast<std::int32_t>(corner + body.first_vertex));
    }
  }
  return bytes;
}

}  // namespace output
