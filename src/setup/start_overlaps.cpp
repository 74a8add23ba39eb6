// Bodies that start inside one another (a sampled winding-number test per pair of overlapping boxes) or inside a
// collider.
#include "setup/start_overlaps.hpp"

#include <algorithm>
#include <cstdio>

#include "sim/contact/body_collision.hpp"
#include "sim/contact/collider_shape.hpp"

namespace setup {

namespace {

struct Box {
  softbody::Vec3 lo, hi;
  bool contains(const softbody::Vec3& p) const {
    return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
  }
  bool overlaps(const Box& other) const {
    return (lo.array() <= other.hi.array()).all() && (other.lo.array() <= hi.array()).all();
  }
};

Box box_of(std::span<const softbody::Vec3> x) {
  Box box{x.front(), x.front()};
  for (const softbody::Vec3& p : x) {
    box.lo = box.lo.cwiseMin(p);
    box.hi = box.hi.cwiseMax(p);
  }
  return box;
}

// The share of body a's vertices inside body b, estimated from a strided sample of those inside b's box.
// Spends samples × b's faces of `budget`.
double share_inside(const sim::Body& a, const sim::Body& b, const Box& b_box, const sim::State& state, double& budget) {
  const auto xa = sim::Model::of(a, state.x);
  const auto xb = sim::Model::of(b, state.x);
  std::vector<std::size_t> in_box;
  for (std::size_t i = 0; i < xa.size(); ++i) {
    if (b_box.contains(xa[i])) in_box.push_back(i);
  }
  if (in_box.empty()) return 0.0;
  const auto faces = static_cast<double>(b.topology.faces.size());
  const auto most = static_cast<std::size_t>(
      std::clamp(kOverlapFaceVisits / std::max(faces, 1.0), 16.0, static_cast<double>(kOverlapSamples)));
  const std::size_t samples = std::min(in_box.size(), most);
  budget -= static_cast<double>(samples) * faces;
  std::size_t inside = 0;
  for (std::size_t k = 0; k < samples; ++k) {
    const std::size_t i = in_box[k * in_box.size() / samples];
    if (sim::winding_number(xb, b.topology.faces, xa[i]) > 0.5) ++inside;
  }
  return static_cast<double>(inside) / static_cast<double>(samples) * static_cast<double>(in_box.size()) /
         static_cast<double>(xa.size());
}

}  // namespace

void note_overlapping_bodies(const sim::Model& model, const sim::State& state, std::span<const std::string> names,
                             std::vector<std::string>& notes, double budget) {
  const std::size_t n = model.bodies.size();
  if (n < 2) return;
  std::vector<Box> boxes;
  for (const sim::Body& body : model.bodies) boxes.push_back(box_of(sim::Model::of(body, state.x)));
  int notes_said = 0;
  long long overlapping = 0, unchecked = 0, unsaid = 0;
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      if (!boxes[a].overlaps(boxes[b])) continue;
      ++overlapping;
      if (budget <= 0.0) {
        ++unchecked;
        continue;
      }
      const double a_in_b = share_inside(model.bodies[a], model.bodies[b], boxes[b], state, budget);
      const double b_in_a = share_inside(model.bodies[b], model.bodies[a], boxes[a], state, budget);
      if (a_in_b <= 0.0 && b_in_a <= 0.0) continue;
      if (notes_said >= kOverlapNotes) {
        ++unsaid;
        continue;
      }
      char text[512];
      std::snprintf(text, sizeof text,
                    "%s and %s start inside each other (about %.2g %% of the first's vertices inside the second, "
                    "%.2g %% of the second's inside the first): the contact between bodies pushes a vertex out at "
                    "most collisions.push_speed (impulse) or with its stiff spring (smooth), so the overlap takes long "
                    "to undo or starts with a jolt; place the bodies apart",
                    names[a].c_str(), names[b].c_str(), 100.0 * a_in_b, 100.0 * b_in_a);
      notes.push_back(text);
      ++notes_said;
    }
  }
  if (unsaid > 0) notes.push_back(std::to_string(unsaid) + " more pairs of bodies start inside each other");
  if (unchecked > 0) {
    notes.push_back("the test for bodies that start inside each other stopped after " +
                    std::to_string(overlapping - unchecked) + " of the " + std::to_string(overlapping) +
                    " pairs whose boxes overlap (its budget of vertex-face tests)");
  }
}

void note_bodies_in_colliders(const sim::Model& model, const sim::State& state, std::span<const std::string> names,
                              std::vector<std::string>& notes) {
  for (std::size_t c = 0; c < model.colliders.size(); ++c) {
    const sim::ColliderGeometry geometry = sim::collider_at(model.colliders[c], 0.0);
    for (std::size_t b = 0; b < model.bodies.size(); ++b) {
      const auto x = sim::Model::of(model.bodies[b], state.x);
      std::size_t inside = 0;
      for (const softbody::Vec3& p : x) inside += sim::is_inside(geometry, p) ? 1 : 0;
      if (inside == 0) continue;
      char text[400];
      std::snprintf(text, sizeof text,
                    "%s starts inside colliders.%zu (%zu of its %zu vertices): a collider moves each vertex inside to "
                    "its nearest surface, which can hold the body inside it or throw it; place the body outside",
                    names[b].c_str(), c, inside, x.size());
      notes.push_back(text);
    }
  }
}

}  // namespace setup
