// What render and export show of a body: the detailed mesh it carries (its skin) when it is simulated on a
// proxy, else its simulated surface. The CSV never uses this: it reports the simulation.
#pragma once

#include <span>
#include <vector>

#include "sim/step/world.hpp"

namespace output {

// The triangles shown for body `body`: the skin's own, or the body's faces.
std::span<const softbody::Triangle> shown_triangles(const sim::World& world, int body);

// The number of vertices shown for body `body`.
int shown_vertex_count(const sim::World& world, int body);

// This frame's shown positions, with the scratch a skin needs (kept between calls: no allocation per frame
// once sized).
class ShownPositions {
 public:
  // A view of the state for a body without skin; for one with a skin, the detailed vertices rebuilt from the
  // proxy's positions and normals (valid until the next call).
  std::span<const softbody::Vec3> of(const sim::World& world, int body);

  // The same for the body at rest (the placed mesh it was built from).
  std::span<const softbody::Vec3> at_rest(const sim::World& world, int body);

 private:
  std::vector<softbody::Vec3> normals_;
  std::vector<softbody::Vec3> detailed_;
};

}  // namespace output
