// Contact between bodies: the vertices of each body against the triangles of every other body whose
// bounding box overlaps it. Broad phase: bounding boxes, then a uniform grid of triangles (a dense cell
// table over the pair's overlap region, counting-sorted, rebuilt each step without allocating). Narrow
// phase: closest point on the nearest triangle, each triangle tested once per vertex; inside or outside by the
// angle-weighted pseudonormal at that point (surface_pseudonormal).
// The impulse model is applied after each step, like the floor; the smooth model adds penalty forces inside
// the force evaluation (sim::Dynamics). A single body costs nothing (no search at all).
// Self-collision (Body::self_collision): the body is also its own surface body, each vertex against its own
// triangles outside its rest neighbourhood (sim/contact/self_exclusion.hpp), with the same search, models and
// momentum balance.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "sim/contact/self_exclusion.hpp"
#include "sim/contact/smooth_contact.hpp"
#include "sim/model/body.hpp"
#include "sim/model/settings.hpp"
#include "sim/model/state.hpp"

namespace sim {

// How far the impulse model moves a vertex out of another body after a step (or an xpbd substep) of `step_s`:
// at most the depth that step carried it in (its approach speed relative to the triangle, with the velocities
// before this call's impulses, times the step) plus `push_speed_m_per_s` times the step of any depth it had
// before (an overlap it started with, or one that contacts left). With `edge_capped` (velocity-based
// integrators) also at most a twentieth of the surface's mean edge. Position-based integrators resolve their
// contacts in every substep as constraints, so they push out all of a substep's travel, however fast.
// A push moves a vertex without a force, against its springs and gas, so an old overlap leaves at
// push_speed_m_per_s: pushing it out at once makes bodies started pressed together fly apart
// (docs/physics/contact.md, "Contact between bodies"; docs/notes/2026-12-03-body-contact.md).
// Built from the model for each step (sim/step/step.cpp): collisions.push_speed's default lives in sim::BodyContact.
struct PushLimit {
  double step_s = 0.0;
  double push_speed_m_per_s = 0.0;
  bool edge_capped = true;
};

// True when the bodies need a contact search: there are several, or one collides with itself.
bool searches_body_contact(const std::vector<Body>& bodies);

// The distance from p to triangle (a, b, c) [m].
double distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

// A self-colliding body's exclusion radius over its mean rest edge: twice the contact's search (half an edge), so
// that a neighbour squeezed to half its rest distance is still outside the search.
inline constexpr double kSelfExclusionFraction = 1.0;
// The self search's candidate margin over the search, and the share of it the displacements may use before the
// candidates are rebuilt (the rest is slack for the impulse pass's own pushes within one call).
inline constexpr double kSelfMarginFraction = 1.0;
inline constexpr double kSelfMarginUse = 0.5;

class BodyCollider {
 public:
  // Resolves the contacts of every pair of bodies; returns how many vertex–triangle contacts it resolved.
  // `inverse_mass`: per vertex of `state`, all bodies (the model's inverse_mass); `push`: how far a vertex is
  // moved out in this call.
  int resolve(const std::vector<Body>& bodies, std::span<const double> inverse_mass, State& state,
              const ContactMaterial& material, const PushLimit& push);

  // The smooth model: for every vertex of each body within the contact's skin δ of the nearest triangle of
  // another body (or inside it, up to half an edge deep), a penalty spring-damper on the penetration
  // d = δ − s (s the signed distance to that triangle, along the direction from its closest point) with
  // regularised Coulomb friction on the relative velocity, the same force law as the smooth floor
  // (sim/contact/smooth_contact.hpp) on the vertex's mass: +F on the vertex, −w_k F on the triangle's corners by
  // barycentric weight, so momentum is conserved exactly. Adds to `force` (every vertex of x).
  // Returns the contacts found.
  int add_smooth_forces(const std::vector<Body>& bodies, std::span<const double> mass_kg, std::span<const Vec3> x,
                        std::span<const Vec3> v, const SmoothResponse& contact, std::span<Vec3> force);

  // The smooth model's contact springs' potential energy of the vertices of body `moving` against every other
  // body: Σ m ω² δ² R(d/δ) over its vertices at penetration d > 0 (the same search and depth as
  // add_smooth_forces, whose spring part is minus its gradient) [J].
  double smooth_energy(const std::vector<Body>& bodies, std::span<const double> mass_kg, std::span<const Vec3> x,
                       const SmoothResponse& contact, std::size_t moving);

  // Where the smooth model looks (the same search as add_smooth_forces): one vertex near another body's surface.
  struct SmoothFrame {
    int vertex = 0;                  // world index
    std::array<int, 3> corners{};    // the nearest triangle's corners, world indices
    Vec3 weights = Vec3::Zero();     // barycentric weights of the closest point q on it
    Vec3 direction = Vec3::Zero();   // unit: the way the contact pushes the vertex, ±(x − q)/|x − q| (outward)
    double signed_distance_m = 0.0;  // direction·(x − q): < 0 inside the surface body
  };
  // Every vertex of each body with a triangle of another body within the contact's search (half the surface's
  // mean edge), nearest triangle first found, in the order add_smooth_forces visits them; `frames` is overwritten.
  void find_smooth_frames(const std::vector<Body>& bodies, std::span<const Vec3> x, std::vector<SmoothFrame>& frames);

 private:
  struct Box {
    Vec3 lo, hi;
  };
  // The nearest triangle of a surface body to a vertex: its index, closest point and barycentric weights.
  struct Nearest {
    int triangle = -1;
    Vec3 point = Vec3::Zero();
    Vec3 weights = Vec3::Zero();
  };

  void compute_boxes(const std::vector<Body>& bodies, std::span<const Vec3> x);
  // Calls visit(pair) for every ordered pair of bodies whose boxes (grown by the surface's search) overlap,
  // with moving_index_ and surface_index_ set.
  template <class Visit>
  int for_each_touching_pair(const std::vector<Body>& bodies, Visit visit);
  void build_grid(const Body& body, std::span<const Vec3> x, const Box& region, double search, double cell_size);
  // Builds the pair's grid and calls visit(vertex, nearest) for each vertex of `moving` with a triangle of
  // `surface` within `search`, in vertex order. `x` may change under it (the vertex visited only).
  template <class Visit>
  void for_each_nearest(const Body& moving, const Body& surface, std::span<const Vec3> x, double search, Visit visit);
  // Self-contact's side for the impulse model: +1 when `vertex` was on the side of triangle `t` (corners at
  // first + t[k], closest point's `weights`) that `normal` points to at the step's start (x − h v, the velocities
  // before this call's impulses), −1 when on the other.
  double side_at_step_start(int vertex, int first, const Triangle& t, const Vec3& weights, const Vec3& normal,
                            std::span<const Vec3> x, const PushLimit& push) const;
  int resolve_vertices_against_triangles(const Body& moving, const Body& surface, std::span<const double> inverse_mass,
                                         State& state, const ContactMaterial& material, const PushLimit& push);
  // The frame of `vertex` against its nearest triangle `best` of `surface` (the body at surface_index_), its side
  // from the closest point's angle-weighted pseudonormal (surface_pseudonormal): the smooth model's, and the
  // impulse model's where the closest point is on an edge or a corner.
  SmoothFrame contact_frame(const Body& surface, std::span<const Vec3> x, int vertex, const Nearest& best,
                            double search);
  // The outward direction whose sign test tells inside from outside at the closest point of triangle `face` with
  // barycentric `weights` (Bærentzen & Aanæs 2005, angle-weighted pseudonormals): on the face, its normal; on an
  // edge, the sum of the two faces' normals; at a corner, Σ α_f n_f over the faces around it (α_f: the face's
  // angle there). A face normal alone gives the wrong side next to a sharp edge or corner (a point in front of
  // an edge is as near to both faces; on the far face's side it is behind the near face's plane).
  // Not unit length. `x_surface`: the surface body's positions.
  Vec3 surface_pseudonormal(const Body& surface, std::span<const Vec3> x_surface, int face, const Vec3& weights);
  // Per body (built on first use; the topology is fixed): the face across each face's edge k (the edge opposite
  // corner k), and each vertex's faces (compressed rows).
  struct Adjacency {
    std::vector<std::array<int, 3>> across;
    std::vector<int> vertex_face_start, vertex_faces;
  };
  const Adjacency& adjacency(std::size_t body_index, const Body& body);
  std::vector<Adjacency> adjacency_;
  // Per self-colliding body (built on first use): the triangles each of its vertices skips.
  const SelfExclusion& self_exclusion(std::size_t body_index, const Body& body);
  std::vector<SelfExclusion> self_exclusions_;
  // Per self-colliding body: every vertex's triangles (outside its exclusion) within the search plus a margin at the
  // reference positions, ascending (a Verlet list). While no vertex has moved more than half the margin relative to
  // the body's mean displacement since, every triangle within the search of a vertex is among them, so the nearest
  // is found among them alone: the body's search costs a pass over its candidates instead of a grid per call.
  struct SelfCandidates {
    std::vector<Vec3> reference;  // the body's positions when the list was built
    double search_m = 0.0;
    std::vector<int> start, triangles;  // compressed rows per vertex (local index)
  };
  std::vector<SelfCandidates> self_candidates_;
  // The self pair's for_each_nearest (the body at surface_index_), from its candidates.
  template <class Visit>
  void for_each_nearest_self(const Body& body, std::span<const Vec3> x, double search, Visit visit);
  // The candidates of the body at surface_index_ for `search`, rebuilt when the positions have moved too far.
  const SelfCandidates& self_candidates(const Body& body, std::span<const Vec3> x, double search);
  void collect_self_candidates(const Body& body, std::span<const Vec3> x, double reach, SelfCandidates& c);
  int add_smooth_pair_forces(const Body& moving, const Body& surface, std::span<const double> mass_kg,
                             std::span<const Vec3> x, std::span<const Vec3> v, const SmoothResponse& contact,
                             std::span<Vec3> force);
  static constexpr int kMaxGridCells = 1 << 21;  // dense table size cap: past it the cells grow
  // The cell holding p, each index clamped to [0, kMaxGridCells - 1]: a table never has more cells along an axis,
  // and the clamp keeps a far point's index from overflowing an int.
  Eigen::Vector3i cell_of(const Vec3& p) const;
  // Calls visit(f) once for each triangle f in the grid cells that the box of half side `reach` around p touches,
  // skipping those already stamped with `stamp` in tested_by_ (and stamping the rest).
  template <class Visit>
  void for_each_grid_triangle(const Vec3& p, double reach, int stamp, Visit&& visit);
  int cell_index(int cx, int cy, int cz) const { return (cx * grid_cells_.y() + cy) * grid_cells_.z() + cz; }

  std::vector<Box> boxes_;           // per body, this step
  std::vector<Vec3> step_velocity_;  // every vertex's velocity before this call's impulses: its travel is v h
  std::size_t moving_index_ = 0;     // the body whose vertices are tested
  std::size_t surface_index_ = 0;    // the body whose triangles the grid holds
  // The grid over the pair's overlap region, dense and compressed (counting sort): cell c holds the surface
  // triangles cell_triangles_[cell_start_[c] .. cell_start_[c + 1]), in ascending index order.
  std::vector<int> cell_start_;  // grid_cells_ product + 1 entries
  std::vector<int> cell_triangles_;
  struct TriangleCells {
    int triangle;
    Eigen::Vector3i first, last;  // the cells its box covers (inclusive)
  };
  std::vector<TriangleCells> grid_triangles_;  // the surface triangles whose boxes meet the region
  std::vector<Box> triangle_boxes_;            // per surface triangle in the grid
  std::vector<int> tested_by_;                 // per surface triangle: the last moving vertex that tested it (-1: none)
  Eigen::Vector3i grid_cells_ = Eigen::Vector3i::Ones();  // cells per axis
  Vec3 grid_origin_ = Vec3::Zero();
  double cell_size_ = 1.0;
};

// Generalised winding number of point p with respect to a closed surface (1 inside, 0 outside),
// from the solid angles of its triangles (Van Oosterom & Strackee 1983). For tests and checks.
double winding_number(std::span<const Vec3> x, std::span<const Triangle> faces, const Vec3& p);

}  // namespace sim
