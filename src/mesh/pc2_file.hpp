// Reading a PC2 point cache (3ds Max Point Cache 2, as Blender, Maya, Houdini and `softbody export --format pc2`
// write it): the positions of a mesh's vertices at evenly spaced frames.
#pragma once

#include <filesystem>
#include <vector>

#include "core/vec.hpp"
#include "mesh/mesh_limits.hpp"

namespace mesh {

// A PC2 file's content: little-endian; char[12] "POINTCACHE2\0", int32 version 1, int32 points, float start frame,
// float sample rate (frames between samples), int32 samples, then float x y z per point per sample.
struct Pc2Cache {
  int points = 0;                                    // vertices per sample
  double start_frame = 0.0;                          // the frame of the first sample
  double frames_per_sample = 1.0;                    // > 0
  std::vector<std::vector<softbody::Vec3>> samples;  // samples × points positions, in the file's units
};

// Reads `file`. Throws softbody::InputError naming the file and what is wrong: not a regular file, larger than
// `limits.max_file_bytes`, a bad header (magic, version, counts, a start or rate that is not finite, a rate ≤ 0),
// more points than `limits.max_vertices`, data shorter or longer than the header announces, or a coordinate that
// is not finite or beyond kMaxMeshCoordinate.
Pc2Cache read_pc2_file(const std::filesystem::path& file, const MeshLimits& limits = {});

}  // namespace mesh
