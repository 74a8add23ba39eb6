// Self-collision's neighbourhoods: the triangles of a body that a vertex of the same body never touches, because
// they are next to it on the surface (sim/contact/body_collision.hpp searches a vertex against its own body's
// triangles only outside this set).
#pragma once

#include <array>
#include <span>
#include <vector>

#include "sim/model/body.hpp"

namespace sim {

// Per vertex (local index), the triangles excluded from its self-contact search (compressed rows): its one-ring
// (the triangles that contain it) and every triangle joined to the one-ring across edges whose rest distance to
// the vertex is below `radius_m`. With radius_m above the contact's search distance, a body in its rest shape
// has no triangle within the search of any vertex except across a real gap (two parts of the surface that lie
// apart on the mesh but near in space), so it feels no self-contact at rest; a triangle next to a vertex on the
// surface (where the vertex lies in its plane, on no definite side) is never a contact.
struct SelfExclusion {
  std::vector<int> start;  // vertex count + 1 entries
  std::vector<int> faces;  // faces[start[v] .. start[v + 1]): the triangles vertex v skips
  std::span<const int> of(int vertex) const {
    return {faces.data() + start[static_cast<std::size_t>(vertex)],
            static_cast<std::size_t>(start[static_cast<std::size_t>(vertex) + 1] -
                                     start[static_cast<std::size_t>(vertex)])};
  }
};

// `across[f][k]`: the face across face f's edge opposite corner k (−1: none); `vertex_faces` the faces around each
// vertex (compressed rows `vertex_face_start`); `rest`: the rest positions (local indices).
SelfExclusion build_self_exclusion(std::span<const Triangle> faces, std::span<const std::array<int, 3>> across,
                                   std::span<const int> vertex_face_start, std::span<const int> vertex_faces,
                                   std::span<const Vec3> rest, double radius_m);

}  // namespace sim
