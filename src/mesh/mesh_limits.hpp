// The most a mesh file may hold before it is read: stated limits a scene can raise (scene key "limits").
#pragma once

#include <cstdint>

namespace mesh {

struct MeshLimits {
  std::uintmax_t max_file_bytes = 256u << 20;  // 256 MiB: larger files are refused before assimp reads them
  long long max_triangles = 2'000'000;         // triangles (and faces announced by a header) per mesh file
  long long max_vertices = 2'000'000;          // vertices per mesh file, as written (before welding)
};

// Largest |coordinate| a mesh file may hold, in its own units: far beyond any real mesh, far below the
// range where squares and cross products of coordinates overflow a double (~1e154).
inline constexpr double kMaxMeshCoordinate = 1e12;

}  // namespace mesh

namespace mesh {

// The deepest nesting of blocks (ASCII FBX), records (binary FBX) or arrays and objects (glTF's JSON) a mesh file
// may hold: assimp's readers recurse once per level, and 50,000 levels overflowed their stack (SIGSEGV). Real
// files nest a dozen levels.
inline constexpr int kMostNestingLevels = 256;

}  // namespace mesh
