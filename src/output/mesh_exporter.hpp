// Per-frame mesh files (OBJ or PLY), numbered like the PNGs, so that the motion can be taken into
// Blender, Houdini or any tool that reads mesh sequences.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

#include "frames/frame_sink.hpp"

namespace output {

enum class MeshFormat { Obj, Ply };

class MeshExporter final : public frames::FrameSink {
 public:
  // Writes DIR/frame_%04d.obj (or .ply); each file whole (temporary name, then renamed).
  MeshExporter(std::filesystem::path dir, MeshFormat format);
  void on_frame(int index, double time_s, const sim::World& world) override;
  void finish(bool complete) override;

  std::filesystem::path frame_path(int index) const;
  // The frames' file names: "frame_%04d.obj" or "frame_%04d.ply".
  std::string frame_pattern() const;
  // Calls `stored(path, bytes)` after each frame's file is in place.
  void after_each_file(std::function<void(const std::filesystem::path&, std::string_view)> stored);

 private:
  std::filesystem::path dir_;
  MeshFormat format_;
  std::function<void(const std::filesystem::path&, std::string_view)> stored_;
};

// Appends body `body` of `world` as one OBJ object ("o body<N>", its vertices, its texture coordinates where
// the mesh file had UVs, its faces numbered from `first_index` and `first_uv_index`, OBJ's 1-based indices of
// the object's first vertex and first "vt" in the file). Returns the number of "vt" lines written.
int append_obj_object(std::string& text, const sim::World& world, int body, int first_index, int first_uv_index = 1);

// The text of one frame as OBJ: one object per body ("o body0", ...), 1-based indices.
std::string world_to_obj(const sim::World& world, double time_s);

// The bytes of one frame as binary little-endian PLY: all bodies in one vertex and one face list.
std::string world_to_ply(const sim::World& world, double time_s);

}  // namespace output
