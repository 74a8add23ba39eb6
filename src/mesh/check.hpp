// Validation of a mesh that is to hold gas: closed, manifold, consistently wound, no degenerate faces.
#pragma once

#include <string>
#include <vector>

#include "core/errors.hpp"
#include "mesh/trimesh.hpp"

namespace mesh {

// What validation found wrong, so that the caller can say which repair step would fix it.
enum class MeshDefect { TooSmall, Degenerate, Open, NonManifold, Winding, NoVolume };

class MeshDefectError : public softbody::InputError {
 public:
  MeshDefectError(MeshDefect defect, const std::string& what) : softbody::InputError(what), defect_(defect) {}
  MeshDefect defect() const { return defect_; }

 private:
  MeshDefect defect_;
};

struct EdgeCounts {
  std::size_t edges = 0;         // unique undirected edges
  std::size_t boundary = 0;      // used by one triangle only (a hole)
  std::size_t non_manifold = 0;  // used by three or more triangles
  std::size_t misoriented = 0;   // used twice in the same direction (inconsistent winding)
};

// Counts the edge kinds above.
EdgeCounts count_edges(const TriMesh& mesh);

// Checks the mesh and fixes what can be fixed without guessing: a globally inverted winding (negative
// volume) is flipped, and a note says so in `notes`. Throws MeshDefectError saying what is wrong
// (boundary or non-manifold edge counts, inconsistent winding, degenerate faces, zero volume).
void validate_closed(TriMesh& mesh, std::vector<std::string>& notes);

}  // namespace mesh
