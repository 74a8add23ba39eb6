// Contact between bodies: the vertices of each body against the triangles of every other body whose
// bounding box overlaps it. Broad phase: bounding boxes, then a uniform grid of triangles (sorted cell
// keys, rebuilt each step without allocating). Narrow phase: closest point on the nearest triangle.
// Applied after each step, like the floor; a single body costs nothing (no search at all).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sim/body.hpp"

namespace sim {

struct BodyContactSettings {
  double restitution = 0.3;            // normal speed kept after an impact
  double friction = 0.5;               // Coulomb μ
  double resting_speed_m_per_s = 0.05; // slower approaches are resting contact: no bounce
};

class BodyCollider {
 public:
  // Resolves the contacts of every pair of bodies; returns how many vertex–triangle contacts it resolved.
  // `inverse_mass`: per vertex of `state`, all bodies (the world's own array).
  int resolve(const std::vector<Body>& bodies, std::span<const double> inverse_mass, State& state,
              const BodyContactSettings& settings);

 private:
  struct Box {
    Vec3 lo, hi;
  };
  struct Cell {
    std::uint64_t key;
    int triangle;
    bool operator<(const Cell& other) const { return key < other.key || (key == other.key && triangle < other.triangle); }
  };

  void build_grid(const Body& body, const State& state, const Box& box, double cell_size);
  int resolve_vertices_against_triangles(const Body& moving, const Body& surface, std::span<const double> inverse_mass,
                                         State& state, const BodyContactSettings& settings);
  static constexpr int kMaxCellIndex = (1 << 21) - 1;  // 21 bits per axis in a cell key
  Eigen::Vector3i cell_of(const Vec3& p) const;         // clamped to the key's range
  static std::uint64_t cell_key(const Eigen::Vector3i& cell);

  std::vector<Box> boxes_;          // per body, this step
  std::size_t moving_index_ = 0;    // the body whose vertices are tested
  std::size_t surface_index_ = 0;   // the body whose triangles the grid holds
  std::vector<double> mean_edge_m_;  // per body, its mean rest edge (bodies never change): sets the search
  std::vector<Cell> cells_;
  std::vector<Box> triangle_boxes_;   // per surface triangle in the grid
  Vec3 grid_origin_ = Vec3::Zero();
  double cell_size_ = 1.0;
};

// Generalised winding number of point p with respect to a closed surface (1 inside, 0 outside),
// from the solid angles of its triangles (Van Oosterom & Strackee 1983). For tests and checks.
double winding_number(std::span<const Vec3> x, std::span<const Triangle> faces, const Vec3& p);

}  // namespace sim
