// Body–body contact: broad phase by boxes and a triangle grid, impulses split by barycentric weights.
#include "sim/contact/body_collision.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "sim/contact/contact_response.hpp"
#include "sim/model/model.hpp"

namespace sim {
namespace {

// Search range around a vertex and contact thickness, as fractions of the surface body's mean rest edge.
constexpr double kSearchFraction = 0.5;      // deepest penetration still pushed back out
constexpr double kThicknessFraction = 0.02;  // gap kept between a vertex and another body's surface

constexpr double kCellFraction = 1.0;  // grid cell size over the surface body's mean rest edge

struct ClosestPoint {
  Vec3 point;
  Vec3 weights;  // barycentric weights of the triangle's corners
};

// The unit normal of triangle t (counter-clockwise seen from outside).
Vec3 face_normal(std::span<const Vec3> x, const Triangle& t) {
  return (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).normalized();
}

// Closest point of triangle (a, b, c) to p, by the Voronoi region p falls in (vertex, edge or face).
ClosestPoint closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {a, {1, 0, 0}};
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {b, {0, 1, 0}};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double t = d1 / (d1 - d3);
    return {a + t * ab, {1 - t, t, 0}};
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {c, {0, 0, 1}};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double t = d2 / (d2 - d6);
    return {a + t * ac, {1 - t, 0, t}};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {b + t * (c - b), {0, 1 - t, t}};
  }
  const double denominator = 1.0 / (va + vb + vc);
  const double v = vb * denominator, w = vc * denominator;
  return {a + v * ab + w * ac, {1 - v - w, v, w}};
}

}  // namespace

bool searches_body_contact(const std::vector<Body>& bodies) {
  return bodies.size() > 1 || std::any_of(bodies.begin(), bodies.end(), [](const Body& b) { return b.self_collision; });
}

double distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  return (p - closest_point_on_triangle(p, a, b, c).point).norm();
}

// Cell k along an axis holds [origin + k·size, origin + (k + 1)·size): k = ⌊(p − origin) / size⌋ clamped to
// [0, kMaxGridCells - 1]; for s = (p − origin) / size ≥ 0 the floor is the truncation, and s < 0 gives 0.
inline Eigen::Vector3i BodyCollider::cell_of(const Vec3& p) const {
  Eigen::Vector3i cell;
  for (int k = 0; k < 3; ++k) {
    const double scaled = (p[k] - grid_origin_[k]) / cell_size_;
    constexpr int kLast = kMaxGridCells - 1;
    cell[k] = scaled <= 0.0 ? 0 : scaled >= double{kLast} ? kLast : static_cast<int>(scaled);
  }
  return cell;
}

void BodyCollider::build_grid(const Body& surface, std::span<const Vec3> x_all, const Box& region, double search,
                              double cell_size) {
  grid_origin_ = region.lo;
  // Vertices tested lie in the region, so a query never reaches past the cell of region.hi + search: the
  // table ends there and triangle boxes are clipped to it. Past kMaxGridCells the cells double in size
  // (only for a huge overlap of fine meshes; the same contacts, found among more candidates).
  const Vec3 top_corner = region.hi + Vec3::Constant(search);
  Eigen::Vector3i top;
  for (cell_size_ = cell_size;; cell_size_ *= 2) {
    top = cell_of(top_corner);
    const std::int64_t cells = std::int64_t{top.x() + 1} * (top.y() + 1) * (top.z() + 1);
    if (cells <= kMaxGridCells) break;
  }
  grid_cells_ = top + Eigen::Vector3i::Ones();
  const std::size_t face_count = surface.topology.faces.size();
  triangle_boxes_.resize(face_count);
  tested_by_.assign(face_count, -1);
  grid_triangles_.clear();
  cell_start_.assign(static_cast<std::size_t>(grid_cells_.prod()) + 1, 0);
  // Pass 1: each triangle's box and cells, counted per cell (in cell_start_[c + 1]).
  const std::span<const Vec3> x = Model::of(surface, x_all);
  for (std::size_t f = 0; f < face_count; ++f) {
    const Triangle& t = surface.topology.faces[f];
    const Vec3 lo = x[t[0]].cwiseMin(x[t[1]]).cwiseMin(x[t[2]]);
    const Vec3 hi = x[t[0]].cwiseMax(x[t[1]]).cwiseMax(x[t[2]]);
    if ((hi.array() < region.lo.array()).any() || (lo.array() > region.hi.array()).any()) continue;
    triangle_boxes_[f] = {lo, hi};
    const Eigen::Vector3i first = cell_of(lo), last = cell_of(hi).cwiseMin(top);
    grid_triangles_.push_back({static_cast<int>(f), first, last});
    for (int cx = first.x(); cx <= last.x(); ++cx) {
      for (int cy = first.y(); cy <= last.y(); ++cy) {
        for (int cz = first.z(); cz <= last.z(); ++cz)
          ++cell_start_[static_cast<std::size_t>(cell_index(cx, cy, cz)) + 1];
      }
    }
  }
  // Pass 2: counts → starts (prefix sum), then the triangles placed in ascending index order per cell.
  for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
  cell_triangles_.resize(static_cast<std::size_t>(cell_start_.back()));
  for (const TriangleCells& g : grid_triangles_) {
    for (int cx = g.first.x(); cx <= g.last.x(); ++cx) {
      for (int cy = g.first.y(); cy <= g.last.y(); ++cy) {
        for (int cz = g.first.z(); cz <= g.last.z(); ++cz) {
          // cell_start_[c] runs ahead as the cell fills; shifted back below.
          cell_triangles_[static_cast<std::size_t>(cell_start_[static_cast<std::size_t>(cell_index(cx, cy, cz))]++)] =
              g.triangle;
        }
      }
    }
  }
  for (std::size_t c = cell_start_.size() - 1; c > 0; --c) cell_start_[c] = cell_start_[c - 1];
  cell_start_[0] = 0;
}

namespace {

struct Contact {
  int vertex;                  // global index of the vertex of the moving body
  std::array<int, 3> corners;  // global indices of the surface triangle's corners
  Vec3 weights;                // barycentric weights of the closest point
  Vec3 normal;                 // the surface's outward unit normal
  double depth;                // how far the vertex must move along the normal to sit `thickness` outside
};

// Applies one contact: the vertex moved out along the normal (within the push limit, sim::PushLimit, and for an
// edge-capped push `edge_cap_m`; `step_velocity`: every vertex's velocity before this call) and a normal
// (restitution) plus tangential (Coulomb) impulse, both split between the vertex and the triangle's corners by
// inverse mass and barycentric weight. The vertex gets +J, the corners
// −w_k J, so momentum is conserved exactly.
void apply_contact(const Contact& c, std::span<const double> inverse_mass, State& state,
                   std::span<const Vec3> step_velocity, const ContactMaterial& material, const PushLimit& push,
                   double edge_cap_m) {
  const double inv_p = inverse_mass[c.vertex];
  double denominator = inv_p;  // 1 / effective mass of the relative normal motion
  for (int k = 0; k < 3; ++k) denominator += c.weights[k] * c.weights[k] * inverse_mass[c.corners[k]];

  Vec3 surface_velocity = Vec3::Zero();
  for (int k = 0; k < 3; ++k) surface_velocity += c.weights[k] * state.v[c.corners[k]];
  const Vec3 relative = state.v[c.vertex] - surface_velocity;
  const double normal_speed = relative.dot(c.normal);  // < 0: approaching

  // This step's travel into the surface, (−v_n) h with the velocities before this call's impulses (those of
  // earlier contacts change v, not the step's travel), and the push speed's share of what was there before [m].
  Vec3 surface_step_velocity = Vec3::Zero();
  for (int k = 0; k < 3; ++k) surface_step_velocity += c.weights[k] * step_velocity[c.corners[k]];
  const double step_normal_speed = (step_velocity[c.vertex] - surface_step_velocity).dot(c.normal);
  const double allowed = (std::max(-step_normal_speed, 0.0) + push.push_speed_m_per_s) * push.step_s;
  state.x[c.vertex] += std::min({c.depth, allowed, push.edge_capped ? edge_cap_m : c.depth}) * c.normal;

  if (normal_speed >= 0.0) return;  // separating already
  const double target = separating_speed(normal_speed, material);
  const double normal_impulse = (target - normal_speed) / denominator;  // kg·m/s
  const Vec3 tangential = relative - normal_speed * c.normal;
  const double tangential_speed = tangential.norm();
  Vec3 impulse = normal_impulse * c.normal;
  if (tangential_speed > 0.0) {
    const double stopping_impulse = tangential_speed / denominator;
    impulse -= friction_impulse(material, normal_impulse, stopping_impulse) / tangential_speed * tangential;
  }
  state.v[c.vertex] += inv_p * impulse;
  for (int k = 0; k < 3; ++k) state.v[c.corners[k]] -= c.weights[k] * inverse_mass[c.corners[k]] * impulse;
}

bool boxes_overlap(const Vec3& lo_a, const Vec3& hi_a, const Vec3& lo_b, const Vec3& hi_b, double margin) {
  return (lo_a.array() <= hi_b.array() + margin).all() && (lo_b.array() <= hi_a.array() + margin).all();
}

}  // namespace

template <class Visit>
void BodyCollider::for_each_grid_triangle(const Vec3& p, double reach, int stamp, Visit&& visit) {
  const Eigen::Vector3i lo = cell_of(p - Vec3::Constant(reach));
  const Eigen::Vector3i hi = cell_of(p + Vec3::Constant(reach)).cwiseMin(grid_cells_ - Eigen::Vector3i::Ones());
  for (int cx = lo.x(); cx <= hi.x(); ++cx) {
    for (int cy = lo.y(); cy <= hi.y(); ++cy) {
      for (int cz = lo.z(); cz <= hi.z(); ++cz) {
        const auto cell = static_cast<std::size_t>(cell_index(cx, cy, cz));
        for (int k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
          const int f = cell_triangles_[static_cast<std::size_t>(k)];
          // A triangle in several of these cells is visited once: a second test gives the same distance, which
          // can neither beat the best nor tie it with a lower index.
          if (tested_by_[static_cast<std::size_t>(f)] == stamp) continue;
          tested_by_[static_cast<std::size_t>(f)] = stamp;
          visit(f);
        }
      }
    }
  }
}

template <class Visit>
void BodyCollider::for_each_nearest(const Body& moving, const Body& surface, std::span<const Vec3> x, double search,
                                    Visit visit) {
  if (moving_index_ == surface_index_) {
    for_each_nearest_self(surface, x, search, visit);
    return;
  }
  const double edge = surface.rest.mean_edge_m;
  // Only the overlap of the two bodies' boxes (grown by the search distance) can hold contacts: the grid
  // holds the surface triangles there, and only moving vertices there are tested.
  const Box& moving_box = boxes_[moving_index_];
  const Box& surface_box = boxes_[surface_index_];
  const Box region{moving_box.lo.cwiseMax(surface_box.lo) - Vec3::Constant(search),
                   moving_box.hi.cwiseMin(surface_box.hi) + Vec3::Constant(search)};
  build_grid(surface, x, region, search, std::max(2 * search, kCellFraction * edge));
  const std::span<const Vec3> x_surface = Model::of(surface, x);
  for (int i = 0; i < moving.vertex_count; ++i) {
    const int vertex = moving.first_vertex + i;
    const Vec3 p = x[vertex];
    if ((p.array() < region.lo.array()).any() || (p.array() > region.hi.array()).any()) continue;
    // Nearest triangle among those in the grid cells that the search sphere's box touches.
    double best_distance = search;
    Nearest best;
    for_each_grid_triangle(p, search, i, [&](int f) {
      const Box& box = triangle_boxes_[static_cast<std::size_t>(f)];  // cheap reject: the box is farther than the best
      if ((p - p.cwiseMax(box.lo).cwiseMin(box.hi)).squaredNorm() > best_distance * best_distance) return;
      const Triangle& t = surface.topology.faces[static_cast<std::size_t>(f)];
      const ClosestPoint q = closest_point_on_triangle(p, x_surface[t[0]], x_surface[t[1]], x_surface[t[2]]);
      const double distance = (p - q.point).norm();
      if (distance < best_distance || (distance == best_distance && f < best.triangle)) {
        best_distance = distance;
        best = Nearest{f, q.point, q.weights};
      }
    });
    if (best.triangle >= 0) visit(vertex, best);
  }
}

double BodyCollider::side_at_step_start(int vertex, int first, const Triangle& t, const Vec3& weights,
                                        const Vec3& normal, std::span<const Vec3> x, const PushLimit& push) const {
  // The relative position r = x_p − Σ w_k x_k taken back along the step's velocities: r − h (v_p − Σ w_k v_k).
  Vec3 start = x[vertex] - push.step_s * step_velocity_[vertex];
  for (int k = 0; k < 3; ++k) start -= weights[k] * (x[first + t[k]] - push.step_s * step_velocity_[first + t[k]]);
  return start.dot(normal) < 0.0 ? -1.0 : 1.0;
}

template <class Visit>
void BodyCollider::for_each_nearest_self(const Body& body, std::span<const Vec3> x, double search, Visit visit) {
  const SelfCandidates& candidates = self_candidates(body, x, search);
  const std::span<const Vec3> x_body = Model::of(body, x);
  for (int i = 0; i < body.vertex_count; ++i) {
    const auto first = static_cast<std::size_t>(candidates.start[static_cast<std::size_t>(i)]);
    const auto last = static_cast<std::size_t>(candidates.start[static_cast<std::size_t>(i) + 1]);
    if (first == last) continue;
    const int vertex = body.first_vertex + i;
    const Vec3 p = x[vertex];
    double best_distance = search;
    Nearest best;
    for (std::size_t k = first; k < last; ++k) {  // ascending triangle index: ties go to the lowest, as in the grid
      const int f = candidates.triangles[k];
      const Triangle& t = body.topology.faces[static_cast<std::size_t>(f)];
      const ClosestPoint q = closest_point_on_triangle(p, x_body[t[0]], x_body[t[1]], x_body[t[2]]);
      const double distance = (p - q.point).norm();
      if (distance < best_distance) {
        best_distance = distance;
        best = Nearest{f, q.point, q.weights};
      }
    }
    if (best.triangle >= 0) visit(vertex, best);
  }
}

const BodyCollider::SelfCandidates& BodyCollider::self_candidates(const Body& body, std::span<const Vec3> x,
                                                                  double search) {
  if (self_candidates_.size() <= surface_index_) self_candidates_.resize(surface_index_ + 1);
  SelfCandidates& c = self_candidates_[surface_index_];
  const std::span<const Vec3> x_body = Model::of(body, x);
  const double margin = kSelfMarginFraction * search;
  if (c.reference.size() == x_body.size() && c.search_m == search) {
    // A pair's distance changes by at most the vertex's and the farthest corner's displacements relative to any
    // common one u (a translation changes no distance): u = the mean displacement.
    Vec3 u = Vec3::Zero();
    for (std::size_t i = 0; i < x_body.size(); ++i) u += x_body[i] - c.reference[i];
    u /= static_cast<double>(x_body.size());
    double largest2 = 0.0;
    for (std::size_t i = 0; i < x_body.size(); ++i)
      largest2 = std::max(largest2, (x_body[i] - c.reference[i] - u).squaredNorm());
    if (2.0 * std::sqrt(largest2) <= kSelfMarginUse * margin) return c;
  }
  collect_self_candidates(body, x, search + margin, c);
  c.reference.assign(x_body.begin(), x_body.end());
  c.search_m = search;
  return c;
}

void BodyCollider::collect_self_candidates(const Body& body, std::span<const Vec3> x, double reach, SelfCandidates& c) {
  const Box& box = boxes_[surface_index_];
  const Box region{box.lo - Vec3::Constant(reach), box.hi + Vec3::Constant(reach)};
  build_grid(body, x, region, reach, std::max(2 * reach, kCellFraction * body.rest.mean_edge_m));
  const SelfExclusion& exclusion = self_exclusion(surface_index_, body);
  const std::span<const Vec3> x_body = Model::of(body, x);
  c.start.assign(1, 0);
  c.triangles.clear();
  for (int i = 0; i < body.vertex_count; ++i) {
    const Vec3 p = x_body[static_cast<std::size_t>(i)];
    for (const int f : exclusion.of(i)) tested_by_[static_cast<std::size_t>(f)] = i;  // its neighbourhood: skipped
    const std::size_t first = c.triangles.size();
    for_each_grid_triangle(p, reach, i, [&](int f) {
      const Box& b = triangle_boxes_[static_cast<std::size_t>(f)];
      if ((p - p.cwiseMax(b.lo).cwiseMin(b.hi)).squaredNorm() > reach * reach) return;
      const Triangle& t = body.topology.faces[static_cast<std::size_t>(f)];
      if (distance_to_triangle(p, x_body[t[0]], x_body[t[1]], x_body[t[2]]) <= reach) c.triangles.push_back(f);
    });
    std::sort(c.triangles.begin() + static_cast<std::ptrdiff_t>(first), c.triangles.end());
    c.start.push_back(static_cast<int>(c.triangles.size()));
  }
}

int BodyCollider::resolve_vertices_against_triangles(const Body& moving, const Body& surface,
                                                     std::span<const double> inverse_mass, State& state,
                                                     const ContactMaterial& material, const PushLimit& push) {
  const double edge = surface.rest.mean_edge_m;
  const double search = kSearchFraction * edge, thickness = kThicknessFraction * edge;
  const std::span<const Vec3> x_surface = Model::of(surface, state.x);
  int contacts = 0;
  for_each_nearest(moving, surface, state.x, search, [&](int vertex, const Nearest& best) {
    const Vec3 p = state.x[vertex];
    const Triangle& t = surface.topology.faces[best.triangle];
    Vec3 normal = face_normal(x_surface, t);
    double height = (p - best.point).dot(normal);  // < 0: inside the surface body
    // Nearest to an edge or a corner: the signed distance to it, on the side its pseudonormal tells, and the push
    // along the offset (the face's plane says neither: next to a sharp edge a vertex outside is behind it).
    const bool on_face = best.weights[0] != 0.0 && best.weights[1] != 0.0 && best.weights[2] != 0.0;
    if (!on_face) {
      const SmoothFrame frame = contact_frame(surface, state.x, vertex, best, search);
      height = frame.signed_distance_m;
      normal = frame.direction;
    }
    if (moving_index_ == surface_index_) {
      // Self-contact: the vertex keeps the side of its own triangle that it was on when the step began.
      const double side = side_at_step_start(vertex, surface.first_vertex, t, best.weights, normal, state.x, push);
      height *= side;
      normal *= side;
    }
    if (height >= thickness) return;
    const Contact contact{vertex,
                          {surface.first_vertex + t[0], surface.first_vertex + t[1], surface.first_vertex + t[2]},
                          best.weights,
                          normal,
                          thickness - height};
    apply_contact(contact, inverse_mass, state, step_velocity_, material, push, 0.1 * search);
    ++contacts;
  });
  return contacts;
}

const BodyCollider::Adjacency& BodyCollider::adjacency(std::size_t body_index, const Body& body) {
  if (adjacency_.size() <= body_index) adjacency_.resize(body_index + 1);
  Adjacency& a = adjacency_[body_index];
  const std::vector<Triangle>& faces = body.topology.faces;
  if (a.across.size() == faces.size()) return a;
  // Each edge's two sides: (lower vertex, higher vertex, face, corner opposite), sorted so that a closed
  // manifold's two sides of an edge are neighbours.
  std::vector<std::array<int, 4>> sides;
  sides.reserve(3 * faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int u = faces[f][(k + 1) % 3], w = faces[f][(k + 2) % 3];
      sides.push_back({std::min(u, w), std::max(u, w), static_cast<int>(f), k});
    }
  }
  std::sort(sides.begin(), sides.end());
  a.across.assign(faces.size(), {-1, -1, -1});
  for (std::size_t s = 0; s + 1 < sides.size(); ++s) {
    if (sides[s][0] != sides[s + 1][0] || sides[s][1] != sides[s + 1][1]) continue;
    a.across[static_cast<std::size_t>(sides[s][2])][static_cast<std::size_t>(sides[s][3])] = sides[s + 1][2];
    a.across[static_cast<std::size_t>(sides[s + 1][2])][static_cast<std::size_t>(sides[s + 1][3])] = sides[s][2];
    ++s;
  }
  a.vertex_face_start.assign(static_cast<std::size_t>(body.vertex_count) + 1, 0);
  for (const Triangle& t : faces) {
    for (const int v : t) ++a.vertex_face_start[static_cast<std::size_t>(v) + 1];
  }
  for (std::size_t v = 1; v < a.vertex_face_start.size(); ++v) a.vertex_face_start[v] += a.vertex_face_start[v - 1];
  a.vertex_faces.resize(3 * faces.size());
  std::vector<int> next(a.vertex_face_start.begin(), a.vertex_face_start.end() - 1);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (const int v : faces[f]) {
      a.vertex_faces[static_cast<std::size_t>(next[static_cast<std::size_t>(v)]++)] = static_cast<int>(f);
    }
  }
  return a;
}

const SelfExclusion& BodyCollider::self_exclusion(std::size_t body_index, const Body& body) {
  if (self_exclusions_.size() <= body_index) self_exclusions_.resize(body_index + 1);
  SelfExclusion& exclusion = self_exclusions_[body_index];
  if (exclusion.start.size() == static_cast<std::size_t>(body.vertex_count) + 1) return exclusion;
  const Adjacency& a = adjacency(body_index, body);
  exclusion = build_self_exclusion(body.topology.faces, a.across, a.vertex_face_start, a.vertex_faces,
                                   body.rest.position_m, kSelfExclusionFraction * body.rest.mean_edge_m);
  return exclusion;
}

Vec3 BodyCollider::surface_pseudonormal(const Body& surface, std::span<const Vec3> x_surface, int face,
                                        const Vec3& weights) {
  const std::vector<Triangle>& faces = surface.topology.faces;
  const Triangle& t = faces[static_cast<std::size_t>(face)];
  const int zeros = (weights[0] == 0.0) + (weights[1] == 0.0) + (weights[2] == 0.0);
  if (zeros == 0) return face_normal(x_surface, t);
  const Adjacency& a = adjacency(surface_index_, surface);
  if (zeros == 1) {  // on the edge opposite the corner of weight 0
    const int k = weights[0] == 0.0 ? 0 : weights[1] == 0.0 ? 1 : 2;
    const int other = a.across[static_cast<std::size_t>(face)][static_cast<std::size_t>(k)];
    const Vec3 n = face_normal(x_surface, t);
    return other < 0 ? n : Vec3(n + face_normal(x_surface, faces[static_cast<std::size_t>(other)]));
  }
  const int corner = t[weights[0] != 0.0 ? 0 : weights[1] != 0.0 ? 1 : 2];  // at the corner of weight 1
  Vec3 sum = Vec3::Zero();
  const auto v = static_cast<std::size_t>(corner);
  for (int i = a.vertex_face_start[v]; i < a.vertex_face_start[v + 1]; ++i) {
    const Triangle& f = faces[static_cast<std::size_t>(a.vertex_faces[static_cast<std::size_t>(i)])];
    const int c = f[0] == corner ? 0 : f[1] == corner ? 1 : 2;
    const Vec3 e1 = x_surface[f[(c + 1) % 3]] - x_surface[corner], e2 = x_surface[f[(c + 2) % 3]] - x_surface[corner];
    const double angle = std::atan2(e1.cross(e2).norm(), e1.dot(e2));  // the face's angle at the corner [rad]
    sum += angle * face_normal(x_surface, f);
  }
  return sum;
}

BodyCollider::SmoothFrame BodyCollider::contact_frame(const Body& surface, std::span<const Vec3> x, int vertex,
                                                      const Nearest& best, double search) {
  const std::span<const Vec3> x_surface = Model::of(surface, x);
  const Triangle& t = surface.topology.faces[best.triangle];
  const Vec3 offset = x[vertex] - best.point;
  const double distance = offset.norm();
  // −1: inside the surface body. A body's own surface is two-sided to its vertices (a vertex may face its own
  // triangle from within the body, as the two walls of a flattened tube face each other): the side it is on.
  const bool self = moving_index_ == surface_index_;
  const double side =
      !self && offset.dot(surface_pseudonormal(surface, x_surface, best.triangle, best.weights)) < 0.0 ? -1.0 : 1.0;
  SmoothFrame frame;
  frame.vertex = vertex;
  frame.corners = {surface.first_vertex + t[0], surface.first_vertex + t[1], surface.first_vertex + t[2]};
  frame.weights = best.weights;
  frame.signed_distance_m = side * distance;
  // Along the offset from the closest point (continuous where the nearest triangle changes on a convex
  // surface); the face normal where the vertex sits on the surface.
  frame.direction = distance > 1e-9 * search ? Vec3(side / distance * offset) : face_normal(x_surface, t);
  return frame;
}

int BodyCollider::add_smooth_pair_forces(const Body& moving, const Body& surface, std::span<const double> mass_kg,
                                         std::span<const Vec3> x, std::span<const Vec3> v,
                                         const SmoothResponse& contact, std::span<Vec3> force) {
  const double search = kSearchFraction * surface.rest.mean_edge_m;
  const double skin = contact.smoothing_m;  // the contact starts δ outside the surface: at s = 0 the ramp is done
  const double eps2 = contact.slip_speed_m_per_s * contact.slip_speed_m_per_s;
  int contacts = 0;
  for_each_nearest(moving, surface, x, search, [&](int vertex, const Nearest& best) {
    const SmoothFrame frame = contact_frame(surface, x, vertex, best, search);
    const double depth = skin - frame.signed_distance_m;
    if (depth <= 0.0) return;
    const Vec3& direction = frame.direction;
    Vec3 surface_velocity = Vec3::Zero();
    for (int k = 0; k < 3; ++k) surface_velocity += frame.weights[k] * v[frame.corners[k]];
    const Vec3 relative = v[vertex] - surface_velocity;
    const double normal_speed = relative.dot(direction);
    const Vec3 tangential = relative - normal_speed * direction;
    const double m = mass_kg[vertex];
    const double elastic = m * smooth_elastic_per_mass(contact, depth);                                       // [N]
    const double dashpot = -m * contact.damping_rate * normal_speed * smooth_dashpot_weight(contact, depth);  // [N]
    const double per_slip =
        contact.friction * elastic / std::sqrt(tangential.squaredNorm() + eps2);  // μ N / √(v_t² + ε²)
    const Vec3 f = (elastic + dashpot) * direction - per_slip * tangential;
    force[vertex] += f;
    for (int k = 0; k < 3; ++k) force[frame.corners[k]] -= frame.weights[k] * f;
    ++contacts;
  });
  return contacts;
}

void BodyCollider::compute_boxes(const std::vector<Body>& bodies, std::span<const Vec3> x) {
  boxes_.resize(bodies.size());
  for (const Body& body : bodies) {
    Box& box = boxes_[&body - bodies.data()];
    box.lo = box.hi = x[body.first_vertex];
    for (int i = 0; i < body.vertex_count; ++i) {
      box.lo = box.lo.cwiseMin(x[body.first_vertex + i]);
      box.hi = box.hi.cwiseMax(x[body.first_vertex + i]);
    }
  }
}

template <class Visit>
int BodyCollider::for_each_touching_pair(const std::vector<Body>& bodies, Visit visit) {
  int contacts = 0;
  for (std::size_t a = 0; a < bodies.size(); ++a) {
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      if (a == b && !bodies[a].self_collision) continue;
      const double margin = kSearchFraction * bodies[b].rest.mean_edge_m;
      if (!boxes_overlap(boxes_[a].lo, boxes_[a].hi, boxes_[b].lo, boxes_[b].hi, margin)) continue;
      moving_index_ = a;
      surface_index_ = b;
      contacts += visit(bodies[a], bodies[b]);
    }
  }
  return contacts;
}

int BodyCollider::resolve(const std::vector<Body>& bodies, std::span<const double> inverse_mass, State& state,
                          const ContactMaterial& material, const PushLimit& push) {
  if (!searches_body_contact(bodies)) return 0;
  compute_boxes(bodies, state.x);
  step_velocity_ = state.v;
  return for_each_touching_pair(bodies, [&](const Body& moving, const Body& surface) {
    return resolve_vertices_against_triangles(moving, surface, inverse_mass, state, material, push);
  });
}

int BodyCollider::add_smooth_forces(const std::vector<Body>& bodies, std::span<const double> mass_kg,
                                    std::span<const Vec3> x, std::span<const Vec3> v, const SmoothResponse& contact,
                                    std::span<Vec3> force) {
  if (!searches_body_contact(bodies)) return 0;
  compute_boxes(bodies, x);
  return for_each_touching_pair(bodies, [&](const Body& moving, const Body& surface) {
    return add_smooth_pair_forces(moving, surface, mass_kg, x, v, contact, force);
  });
}

double BodyCollider::smooth_energy(const std::vector<Body>& bodies, std::span<const double> mass_kg,
                                   std::span<const Vec3> x, const SmoothResponse& contact, std::size_t moving) {
  if (!searches_body_contact(bodies)) return 0.0;
  compute_boxes(bodies, x);
  double energy = 0.0;
  for_each_touching_pair(bodies, [&](const Body& moving_body, const Body& surface) {
    if (moving_index_ != moving) return 0;
    const double search = kSearchFraction * surface.rest.mean_edge_m;
    for_each_nearest(moving_body, surface, x, search, [&](int vertex, const Nearest& best) {
      const double depth = contact.smoothing_m - contact_frame(surface, x, vertex, best, search).signed_distance_m;
      if (depth > 0.0) energy += mass_kg[vertex] * smooth_energy_per_mass(contact, depth);  // m ω² δ² R(d/δ)
    });
    return 0;
  });
  return energy;
}

void BodyCollider::find_smooth_frames(const std::vector<Body>& bodies, std::span<const Vec3> x,
                                      std::vector<SmoothFrame>& frames) {
  frames.clear();
  if (!searches_body_contact(bodies)) return;
  compute_boxes(bodies, x);
  for_each_touching_pair(bodies, [&](const Body& moving, const Body& surface) {
    const double search = kSearchFraction * surface.rest.mean_edge_m;
    for_each_nearest(moving, surface, x, search, [&](int vertex, const Nearest& best) {
      frames.push_back(contact_frame(surface, x, vertex, best, search));
    });
    return 0;
  });
}

double winding_number(std::span<const Vec3> x, std::span<const Triangle> faces, const Vec3& p) {
  double solid_angle = 0.0;
  for (const Triangle& f : faces) {
    const Vec3 a = x[f[0]] - p, b = x[f[1]] - p, c = x[f[2]] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    solid_angle += 2.0 * std::atan2(numerator, denominator);
  }
  return solid_angle / (4.0 * std::numbers::pi);
}

}  // namespace sim
