// The mesh collider's tree, pseudo-normals and nearest-point query.
#include "sim/contact/collider_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

namespace sim {
namespace {

// A point within this fraction of the mesh's diagonal of its nearest point lies on the mesh, to round-off.
constexpr double kOnMeshRelative = 1e-12;

constexpr int kLeafTriangles = 4;

// One directed edge of a triangle, for pairing the two triangles of each undirected edge.
struct EdgeUse {
  int lo = 0, hi = 0;  // its vertices, smaller first
  int triangle = 0, corner = 0;
  bool forward = true;  // runs lo → hi in its triangle
};

// The nearest point of triangle abc to p and the feature it lies on: corner 0, 1, 2; edge 3, 4, 5 (edge k from
// corner k to corner k + 1); or 6, the face. Voronoi regions of the corners, then of the edges, then the face by
// barycentric coordinates (Ericson 2005, Real-Time Collision Detection, Sect. 5.1.5).
struct TriangleHit {
  Vec3 point;
  int feature = 6;
};

TriangleHit closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {a, 0};
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return {b, 1};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return {Vec3(a + (d1 / (d1 - d3)) * ab), 3};
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return {c, 2};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return {Vec3(a + (d2 / (d2 - d6)) * ac), 5};
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    return {Vec3(b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b)), 4};
  }
  const double scale = 1.0 / (va + vb + vc);
  return {Vec3(a + ab * (vb * scale) + ac * (vc * scale)), 6};
}

// Squared distance from q to the box [lo, hi] (0 inside).
double box_distance2(const Vec3& lo, const Vec3& hi, const Vec3& q) {
  return (lo - q).cwiseMax(q - hi).cwiseMax(0.0).squaredNorm();
}

// The interior angle of triangle abc at a [rad].
double corner_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 u = b - a, v = c - a;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

// Pairs the triangles at each edge: counts boundary edges and, where every edge has two triangles wound opposite ways,
// sums their normals into the edge pseudo-normals. Returns whether the mesh is closed.
bool pair_edges(ColliderMesh& m) {
  std::vector<EdgeUse> uses;
  uses.reserve(3 * m.triangles.size());
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int a = m.triangles[t][static_cast<std::size_t>(k)],
                b = m.triangles[t][static_cast<std::size_t>((k + 1) % 3)];
      uses.push_back({std::min(a, b), std::max(a, b), static_cast<int>(t), k, a < b});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return std::tie(x.lo, x.hi, x.triangle, x.corner) < std::tie(y.lo, y.hi, y.triangle, y.corner);
  });
  bool closed = true;
  m.edge_normals.assign(m.triangles.size(), {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()});
  m.edge_partners.assign(m.triangles.size(), {-1, -1, -1});
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi) ++j;
    if (j - i == 1) ++m.boundary_edges;
    if (j - i != 2 || uses[i].forward == uses[i + 1].forward) {
      closed = false;
    } else {
      const Vec3 sum = m.face_normals[static_cast<std::size_t>(uses[i].triangle)] +
                       m.face_normals[static_cast<std::size_t>(uses[i + 1].triangle)];
      for (std::size_t u = i; u < j; ++u) {
        m.edge_normals[static_cast<std::size_t>(uses[u].triangle)][static_cast<std::size_t>(uses[u].corner)] = sum;
        m.edge_partners[static_cast<std::size_t>(uses[u].triangle)][static_cast<std::size_t>(uses[u].corner)] =
            uses[u == i ? i + 1 : i].triangle;
      }
    }
    i = j;
  }
  return closed;
}

// The signed volume Σ a·(b × c) / 6 [m³]: negative for a closed mesh wound inside out.
double signed_volume(const ColliderMesh& m) {
  double six_volume = 0.0;
  for (const softbody::Triangle& t : m.triangles) {
    const Vec3 &a = m.vertices_m[static_cast<std::size_t>(t[0])], &b = m.vertices_m[static_cast<std::size_t>(t[1])],
               &c = m.vertices_m[static_cast<std::size_t>(t[2])];
    six_volume += a.dot(b.cross(c));
  }
  return six_volume / 6.0;
}

// The volume of the vertices' bounding box [m³], the scale a signed volume is compared with.
double box_volume(const ColliderMesh& m) {
  Vec3 lo = m.vertices_m.front(), hi = lo;
  for (const Vec3& p : m.vertices_m) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double diagonal = (hi - lo).norm();
  return diagonal * diagonal * diagonal;
}

void add_vertex_normals(ColliderMesh& m) {
  m.vertex_normals.assign(m.vertices_m.size(), Vec3::Zero());
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    for (std::size_t k = 0; k < 3; ++k) {
      const auto a = static_cast<std::size_t>(m.triangles[t][k]),
                 b = static_cast<std::size_t>(m.triangles[t][(k + 1) % 3]),
                 c = static_cast<std::size_t>(m.triangles[t][(k + 2) % 3]);
      m.vertex_normals[a] += corner_angle(m.vertices_m[a], m.vertices_m[b], m.vertices_m[c]) * m.face_normals[t];
    }
  }
}

// The box around the corners of the triangles order[first, first + count).
void triangles_box(const ColliderMesh& m, int first, int count, Vec3& lo, Vec3& hi) {
  lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  hi = -lo;
  for (int i = first; i < first + count; ++i) {
    for (int v : m.triangles[static_cast<std::size_t>(m.order[static_cast<std::size_t>(i)])]) {
      lo = lo.cwiseMin(m.vertices_m[static_cast<std::size_t>(v)]);
      hi = hi.cwiseMax(m.vertices_m[static_cast<std::size_t>(v)]);
    }
  }
}

// Splits order[first, first + count) at the median of the triangles' centroids along the box's longest axis (ties
// by triangle index, so the tree is the same on every run), until a leaf holds at most kLeafTriangles. An inner node
// keeps its left child's index in `first` and its right child's, negated, in `count`.
int build_tree(ColliderMesh& m, const std::vector<Vec3>& centroid, int first, int count) {
  const int index = static_cast<int>(m.nodes.size());
  m.nodes.push_back({});
  Vec3 lo, hi;
  triangles_box(m, first, count, lo, hi);
  ColliderMesh::Node node{lo, hi, first, count};
  if (count > kLeafTriangles) {
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    const auto begin = m.order.begin() + first;
    const int half = count / 2;
    std::nth_element(begin, begin + half, begin + count, [&](int x, int y) {
      const double cx = centroid[static_cast<std::size_t>(x)][axis], cy = centroid[static_cast<std::size_t>(y)][axis];
      return cx < cy || (cx == cy && x < y);
    });
    node.first = build_tree(m, centroid, first, half);
    node.count = -build_tree(m, centroid, first + half, count - half);
  }
  m.nodes[static_cast<std::size_t>(index)] = node;
  return index;
}

// The nearest point of the mesh to q: its triangle, the point and the feature, by a depth-first walk of the tree that
// visits the nearer child first and skips every box farther than the best point so far (the first of equals wins).
struct MeshHit {
  int triangle = -1;
  TriangleHit hit;
  double distance2 = std::numeric_limits<double>::infinity();
};

MeshHit nearest_triangle(const ColliderMesh& m, const Vec3& q) {
  MeshHit best;
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const ColliderMesh::Node& node = m.nodes[static_cast<std::size_t>(stack[--top])];
    if (box_distance2(node.lo, node.hi, q) >= best.distance2) continue;
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i) {
        const int t = m.order[static_cast<std::size_t>(i)];
        const softbody::Triangle& tri = m.triangles[static_cast<std::size_t>(t)];
        const TriangleHit hit = closest_on_triangle(q, m.vertices_m[static_cast<std::size_t>(tri[0])],
                                                    m.vertices_m[static_cast<std::size_t>(tri[1])],
                                                    m.vertices_m[static_cast<std::size_t>(tri[2])]);
        const double d2 = (q - hit.point).squaredNorm();
        if (d2 < best.distance2) best = {t, hit, d2};
      }
      continue;
    }
    const int left = node.first, right = -node.count;
    const double dl =
        box_distance2(m.nodes[static_cast<std::size_t>(left)].lo, m.nodes[static_cast<std::size_t>(left)].hi, q);
    const double dr =
        box_distance2(m.nodes[static_cast<std::size_t>(right)].lo, m.nodes[static_cast<std::size_t>(right)].hi, q);
    // The nearer child on top of the stack, so that it is searched first.
    stack[top++] = dl <= dr ? right : left;
    stack[top++] = dl <= dr ? left : right;
  }
  return best;
}

// The pseudo-normal of the feature a closed mesh's nearest point lies on (not normalised: only its sign is used).
Vec3 pseudo_normal(const ColliderMesh& m, const MeshHit& h) {
  const auto t = static_cast<std::size_t>(h.triangle);
  if (h.hit.feature < 3) {
    return m.vertex_normals[static_cast<std::size_t>(m.triangles[t][static_cast<std::size_t>(h.hit.feature)])];
  }
  if (h.hit.feature < 6) return m.edge_normals[t][static_cast<std::size_t>(h.hit.feature - 3)];
  return m.face_normals[t];
}

// The parameter in [0, 1] where the segment a + t d enters the box [lo, hi] (the slabs' latest entry before every
// exit; 0 when a is inside), or none.
std::optional<double> segment_box_entry(const Vec3& lo, const Vec3& hi, const Vec3& a, const Vec3& d) {
  double enter = 0.0, leave = 1.0;
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0.0) {
      if (a[k] < lo[k] || a[k] > hi[k]) return std::nullopt;
      continue;
    }
    const double t1 = (lo[k] - a[k]) / d[k], t2 = (hi[k] - a[k]) / d[k];
    enter = std::max(enter, std::min(t1, t2));
    leave = std::min(leave, std::max(t1, t2));
  }
  if (enter > leave) return std::nullopt;
  return enter;
}

// The parameter in [0, 1] where the segment a + t d crosses triangle (p, q, r), edges included (Möller & Trumbore
// 1997, "Fast, minimum storage ray-triangle intersection"), or none; a segment in the triangle's plane crosses none.
std::optional<double> segment_triangle_crossing(const Vec3& a, const Vec3& d, const Vec3& p, const Vec3& q,
                                                const Vec3& r) {
  const Vec3 e1 = q - p, e2 = r - p;
  const Vec3 s = d.cross(e2);
  const double det = e1.dot(s);
  if (det == 0.0) return std::nullopt;
  const Vec3 offset = a - p;
  const double u = offset.dot(s) / det;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const Vec3 w = offset.cross(e1);
  const double v = d.dot(w) / det;
  if (v < 0.0 || u + v > 1.0) return std::nullopt;
  const double t = e2.dot(w) / det;
  // A start on the face to round-off (where a contact put the vertex) crosses it at t = 0, as the box's slabs say.
  if (t < -kOnMeshRelative || t > 1.0) return std::nullopt;
  return std::max(t, 0.0);
}

// The barycentric weights of point p of triangle abc (p in its plane): a degenerate triangle's first corner.
std::array<double, 3> barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e0 = b - a, e1 = c - a, e2 = p - a;
  const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1), d20 = e2.dot(e0), d21 = e2.dot(e1);
  const double denominator = d00 * d11 - d01 * d01;
  if (denominator == 0.0) return {1.0, 0.0, 0.0};
  const double wb = (d11 * d20 - d01 * d21) / denominator, wc = (d00 * d21 - d01 * d20) / denominator;
  return {1.0 - wb - wc, wb, wc};
}

// The tree's boxes around the triangles' current vertices, children before parents (a parent's index is below its
// children's: build_tree pushes a node before its subtrees).
void refit_tree(ColliderMesh& m) {
  for (std::size_t i = m.nodes.size(); i-- > 0;) {
    ColliderMesh::Node& node = m.nodes[i];
    if (node.count < 0) {
      const ColliderMesh::Node &left = m.nodes[static_cast<std::size_t>(node.first)],
                               &right = m.nodes[static_cast<std::size_t>(-node.count)];
      node.lo = left.lo.cwiseMin(right.lo);
      node.hi = left.hi.cwiseMax(right.hi);
      continue;
    }
    triangles_box(m, node.first, node.count, node.lo, node.hi);
  }
}

}  // namespace

std::shared_ptr<const ColliderMesh> refit_collider_mesh(const ColliderMesh& mesh, std::vector<Vec3> vertices_m,
                                                        std::vector<Vec3> velocities) {
  auto m = std::make_shared<ColliderMesh>(mesh);
  m->vertices_m = std::move(vertices_m);
  m->vertex_velocities = std::move(velocities);
  for (std::size_t t = 0; t < m->triangles.size(); ++t) {
    const softbody::Triangle& tri = m->triangles[t];
    const Vec3 n =
        (m->vertices_m[static_cast<std::size_t>(tri[1])] - m->vertices_m[static_cast<std::size_t>(tri[0])])
            .cross(m->vertices_m[static_cast<std::size_t>(tri[2])] - m->vertices_m[static_cast<std::size_t>(tri[0])]);
    m->face_normals[t] = n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3::Zero();
  }
  if (m->closed) {  // the same pairs as the rest pose's: only the normals summed change
    for (std::size_t t = 0; t < m->triangles.size(); ++t) {
      for (std::size_t k = 0; k < 3; ++k)
        m->edge_normals[t][k] = m->face_normals[t] + m->face_normals[static_cast<std::size_t>(m->edge_partners[t][k])];
    }
    add_vertex_normals(*m);
  }
  refit_tree(*m);
  m->lo_m = m->nodes.front().lo - Vec3::Constant(m->half_thickness_m);
  m->hi_m = m->nodes.front().hi + Vec3::Constant(m->half_thickness_m);
  return m;
}

MeshPoint mesh_nearest_point_local(const ColliderMesh& m, const Vec3& q) {
  const MeshHit h = nearest_triangle(m, q);
  const softbody::Triangle& tri = m.triangles[static_cast<std::size_t>(h.triangle)];
  return {h.triangle,
          barycentric(h.hit.point, m.vertices_m[static_cast<std::size_t>(tri[0])],
                      m.vertices_m[static_cast<std::size_t>(tri[1])], m.vertices_m[static_cast<std::size_t>(tri[2])])};
}

Vec3 at_mesh_point(const ColliderMesh& m, const MeshPoint& point, std::span<const Vec3> per_vertex) {
  const softbody::Triangle& tri = m.triangles[static_cast<std::size_t>(point.triangle)];
  Vec3 value = Vec3::Zero();
  for (std::size_t k = 0; k < 3; ++k) value += point.weights[k] * per_vertex[static_cast<std::size_t>(tri[k])];
  return value;
}

Vec3 mesh_point_position(const ColliderMesh& m, const MeshPoint& point) {
  return at_mesh_point(m, point, m.vertices_m);
}

bool mesh_segment_entry_local(const ColliderMesh& m, const Vec3& a, const Vec3& b, Vec3& point, Vec3& normal) {
  const Vec3 d = b - a;
  const Vec3 pad = Vec3::Constant(m.half_thickness_m);
  double best_t = std::numeric_limits<double>::infinity();
  int best = -1;
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const ColliderMesh::Node& node = m.nodes[static_cast<std::size_t>(stack[--top])];
    const std::optional<double> reach = segment_box_entry(node.lo - pad, node.hi + pad, a, d);
    if (!reach || *reach > best_t) continue;
    if (node.count < 0) {
      stack[top++] = node.first;
      stack[top++] = -node.count;
      continue;
    }
    for (int i = node.first; i < node.first + node.count; ++i) {
      const int t = m.order[static_cast<std::size_t>(i)];
      const auto ti = static_cast<std::size_t>(t);
      if (m.closed && m.face_normals[ti].dot(d) >= 0.0) continue;  // leaving a solid or along its face
      const softbody::Triangle& tri = m.triangles[ti];
      const std::optional<double> crossing = segment_triangle_crossing(
          a, d, m.vertices_m[static_cast<std::size_t>(tri[0])], m.vertices_m[static_cast<std::size_t>(tri[1])],
          m.vertices_m[static_cast<std::size_t>(tri[2])]);
      // The earliest crossing; of equal ones (an edge or a vertex shared) the lowest triangle, on every run.
      if (crossing && (*crossing < best_t || (*crossing == best_t && t < best))) {
        best_t = *crossing;
        best = t;
      }
    }
  }
  if (best < 0) return false;
  const Vec3& face = m.face_normals[static_cast<std::size_t>(best)];
  normal = face.dot(d) < 0.0 ? face : Vec3(-face);
  point = a + best_t * d + m.half_thickness_m * normal;
  return true;
}

std::shared_ptr<const ColliderMesh> make_collider_mesh(std::vector<Vec3> vertices_m,
                                                       std::vector<softbody::Triangle> triangles, double thickness_m) {
  auto m = std::make_shared<ColliderMesh>();
  m->vertices_m = std::move(vertices_m);
  for (const softbody::Triangle& t : triangles) {
    const Vec3 &a = m->vertices_m[static_cast<std::size_t>(t[0])], &b = m->vertices_m[static_cast<std::size_t>(t[1])],
               &c = m->vertices_m[static_cast<std::size_t>(t[2])];
    const Vec3 n = (b - a).cross(c - a);
    if (n.norm() == 0.0) continue;  // degenerate: no side, and nothing a point could be nearest to that an edge is not
    m->triangles.push_back(t);
    m->face_normals.push_back(n.normalized());
  }
  if (m->triangles.empty()) throw std::invalid_argument("the mesh has no triangle with an area");
  m->closed = pair_edges(*m);
  const double volume = m->closed ? signed_volume(*m) : 0.0;
  if (m->closed && std::abs(volume) <= 1e-12 * box_volume(*m)) {
    m->closed = false;  // no volume (a sheet's two sides as two layers of triangles): a sheet, not a solid
    m->edge_normals.clear();
  }
  if (m->closed && volume < 0.0) {  // wound inside out: turn every triangle and its normal
    for (softbody::Triangle& t : m->triangles) std::swap(t[1], t[2]);
    for (Vec3& n : m->face_normals) n = -n;
    m->boundary_edges = 0;
    pair_edges(*m);  // the edges' corners moved with the turn
  }
  if (m->closed) {
    add_vertex_normals(*m);
  } else {
    m->edge_normals.clear();
    m->half_thickness_m = 0.5 * thickness_m;
  }
  std::vector<Vec3> centroid;
  centroid.reserve(m->triangles.size());
  for (const softbody::Triangle& t : m->triangles) {
    centroid.push_back((m->vertices_m[static_cast<std::size_t>(t[0])] + m->vertices_m[static_cast<std::size_t>(t[1])] +
                        m->vertices_m[static_cast<std::size_t>(t[2])]) /
                       3.0);
  }
  m->order.resize(m->triangles.size());
  for (std::size_t i = 0; i < m->order.size(); ++i) m->order[i] = static_cast<int>(i);
  m->nodes.reserve(2 * m->triangles.size());
  build_tree(*m, centroid, 0, static_cast<int>(m->triangles.size()));
  m->lo_m = m->nodes.front().lo - Vec3::Constant(m->half_thickness_m);
  m->hi_m = m->nodes.front().hi + Vec3::Constant(m->half_thickness_m);
  return m;
}

SurfacePoint mesh_nearest_local(const ColliderMesh& m, const Vec3& q) {
  const MeshHit h = nearest_triangle(m, q);
  const Vec3 out = q - h.hit.point;
  const double length = std::sqrt(h.distance2);
  const Vec3& face = m.face_normals[static_cast<std::size_t>(h.triangle)];
  if (!m.closed) {  // a sheet: |q − c| − t/2, the normal away from the triangles (on them: the face's)
    const Vec3 normal = length > 0.0 ? Vec3(out / length) : face;
    return {length - m.half_thickness_m, normal, Vec3(h.hit.point + m.half_thickness_m * normal)};
  }
  const Vec3 pseudo = pseudo_normal(m, h);
  const double side = out.dot(pseudo) < 0.0 ? -1.0 : 1.0;
  // Nearest to a face's inside, the normal is the face's; nearest to an edge or a corner, the direction to the point,
  // unless the point is on the mesh to round-off (a vertex a contact just put there), where that direction is noise
  // and the feature's pseudo-normal is taken instead.
  const bool on_mesh = length <= kOnMeshRelative * (m.hi_m - m.lo_m).norm();
  const Vec3 normal = h.hit.feature >= 6 ? face : on_mesh ? Vec3(pseudo.normalized()) : Vec3(side * out / length);
  return {side * length, normal, h.hit.point};
}

bool mesh_inside_local(const ColliderMesh& m, const Vec3& q) {
  if ((q - m.lo_m).minCoeff() <= 0.0 || (m.hi_m - q).minCoeff() <= 0.0) return false;
  return mesh_nearest_local(m, q).distance_m < 0.0;
}

}  // namespace sim
