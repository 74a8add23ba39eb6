// The joint affine correction: the bodies' affine systems coupled by their contacts, one Newton step and its search.
#include "sim/integrators/joint_affine_correction.hpp"

#include <Eigen/Dense>

#include "sim/integrators/motion_search.hpp"

namespace sim {
namespace {

using Vector12 = Eigen::Matrix<double, 12, 1>;

// The body of a world vertex (the bodies' vertices are contiguous, in order).
std::size_t body_of(const Model& model, int vertex) {
  std::size_t b = 0;
  while (b + 1 < model.bodies.size() && model.bodies[b + 1].first_vertex <= vertex) ++b;
  return b;
}

// One contact's map P_b per body it touches: r moves by A_b u_b + s_b t_b.
struct ContactMap {
  std::size_t body[4];
  Vec3 u[4];
  double s[4];
  int bodies = 0;

  void add(std::size_t b, double coefficient, const Vec3& offset) {
    int k = 0;
    while (k < bodies && body[k] != b) ++k;
    if (k == bodies) {
      body[k] = b;
      u[k] = Vec3::Zero();
      s[k] = 0.0;
      ++bodies;
    }
    u[k] += coefficient * offset;
    s[k] += coefficient;
  }
};

// Unknown (row of A, column of A) → index: A row-major, then t at 9.
Eigen::Index a_index(std::size_t body, int row, int column) {
  return static_cast<Eigen::Index>(12 * body) + 3 * row + column;
}
Eigen::Index t_index(std::size_t body, int row) { return static_cast<Eigen::Index>(12 * body) + 9 + row; }

}  // namespace

bool joint_affine_correction(const Model& model, std::span<const BodySolve> solves, const VertexContacts& contacts,
                             std::span<Vec3> x, JointAffineScratch& scratch) {
  const std::size_t count = model.bodies.size();
  if (count > kMostJointBodies) return false;
  const auto unknowns = static_cast<Eigen::Index>(12 * count);
  scratch.bodies.resize(count);
  scratch.systems.resize(count);
  Eigen::MatrixXd& K = scratch.matrix;
  Eigen::VectorXd& G = scratch.gradient;
  K.setZero(unknowns, unknowns);
  G.setZero(unknowns);
  for (std::size_t b = 0; b < count; ++b) {
    const Body& body = model.bodies[b];
    scratch.systems[b] = affine_system(body, solves[b], Model::of(body, x), scratch.bodies[b]);
    K.block<12, 12>(static_cast<Eigen::Index>(12 * b), static_cast<Eigen::Index>(12 * b)) = scratch.systems[b].matrix;
    G.segment<12>(static_cast<Eigen::Index>(12 * b)) = scratch.systems[b].gradient;
  }
  for (std::size_t c = 0; c < contacts.contacts(); ++c) {
    const BodyCollider::SmoothFrame& f = contacts.frame(c);
    Vec3 g;
    Block3 block;
    contacts.relative_derivatives(c, g, block);
    const Eigen::Matrix3d H =
        (Eigen::Matrix3d() << block.xx, block.xy, block.xz, block.xy, block.yy, block.yz, block.xz, block.yz, block.zz)
            .finished();
    ContactMap map;
    const auto offset = [&](int vertex) {
      return Vec3(x[static_cast<std::size_t>(vertex)] - scratch.systems[body_of(model, vertex)].centre);
    };
    map.add(body_of(model, f.vertex), 1.0, offset(f.vertex));
    for (int k = 0; k < 3; ++k) map.add(body_of(model, f.corners[k]), -f.weights[k], offset(f.corners[k]));
    for (int p = 0; p < map.bodies; ++p) {  // P_pᵀ ∇_r E_c
      for (int row = 0; row < 3; ++row) {
        for (int a = 0; a < 3; ++a) G(a_index(map.body[p], row, a)) += g[row] * map.u[p][a];
        G(t_index(map.body[p], row)) += map.s[p] * g[row];
      }
    }
    for (int p = 0; p < map.bodies; ++p) {  // P_pᵀ K P_q
      for (int q = 0; q < map.bodies; ++q) {
        for (int row = 0; row < 3; ++row) {
          for (int col = 0; col < 3; ++col) {
            const double h = H(row, col);
            for (int a = 0; a < 3; ++a) {
              for (int b = 0; b < 3; ++b) {
                K(a_index(map.body[p], row, a), a_index(map.body[q], col, b)) += h * map.u[p][a] * map.u[q][b];
              }
              K(a_index(map.body[p], row, a), t_index(map.body[q], col)) += h * map.u[p][a] * map.s[q];
              K(t_index(map.body[p], row), a_index(map.body[q], col, a)) += h * map.s[p] * map.u[q][a];
            }
            K(t_index(map.body[p], row), t_index(map.body[q], col)) += h * map.s[p] * map.s[q];
          }
        }
      }
    }
  }
  Eigen::VectorXd& step = scratch.step;
  scratch.factor.compute(K);
  scratch.rhs = -G;
  step = scratch.factor.solve(scratch.rhs);
  const double slope = G.dot(step);
  if (!(slope < 0.0)) return false;
  // The motion of every vertex (each body's lags for the search are its affine_system's, taken at x).
  scratch.motion.resize(x.size());
  for (std::size_t b = 0; b < count; ++b) {
    const Body& body = model.bodies[b];
    const Vector12 q = step.segment<12>(static_cast<Eigen::Index>(12 * b));
    MotionScratch& search = scratch.bodies[b].search;
    affine_motion(q, Model::of(body, x), scratch.systems[b].centre, search);
    std::copy(search.motion.begin(), search.motion.end(), scratch.motion.begin() + body.first_vertex);
  }
  for (double alpha = 1.0; alpha > 1e-3; alpha *= 0.5) {
    double change = contacts.motion_energy_change(0, scratch.motion, alpha);
    for (std::size_t b = 0; b < count; ++b) {
      const Body& body = model.bodies[b];
      change += motion_energy_change(body, solves[b], Model::of(body, x), scratch.systems[b].volume, alpha,
                                     scratch.bodies[b].search);
    }
    if (change <= kArmijo * alpha * slope) {
      for (std::size_t i = 0; i < x.size(); ++i) x[i] += alpha * scratch.motion[i];
      return true;
    }
  }
  return false;
}

}  // namespace sim
