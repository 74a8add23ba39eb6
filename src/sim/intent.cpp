// Resolving physical intent: breathing-mode Rayleigh quotient, lattice stiffness, equilibrium tensions.
#include "sim/intent.hpp"

#include <cmath>
#include <numbers>
#include <optional>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

#include "core/errors.hpp"
#include "sim/energy.hpp"
#include "sim/forces.hpp"

namespace sim {
namespace {

// Edge tensions t_e [N] per unit nRT that balance the gas at shape x, vertex by vertex:
//   Σ_{e∋i} −t_e d̂_e(i) + (1/V) ∂V/∂x_i = 0,  d̂_e(i) the unit vector from the other end to i.
// 3n equations for 3n − 6 tensions (a closed triangulated surface); rigid motions are balanced anyway, and
// a convex polyhedron is infinitesimally rigid (Dehn), so the least-squares solution is exact there.
std::vector<double> unit_gas_tensions(const Topology& t, std::span<const Vec3> x, double volume) {
  const auto n = static_cast<Eigen::Index>(3 * x.size());
  const auto m = static_cast<Eigen::Index>(t.edges.size());
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(6 * t.edges.size());
  for (std::size_t e = 0; e < t.edges.size(); ++e) {
    const auto [i, j] = t.edges[e];
    const Vec3 d = (x[i] - x[j]).normalized();
    for (int k = 0; k < 3; ++k) {
      entries.emplace_back(3 * i + k, static_cast<Eigen::Index>(e), d[k]);
      entries.emplace_back(3 * j + k, static_cast<Eigen::Index>(e), -d[k]);
    }
  }
  Eigen::SparseMatrix<double> A(n, m);
  A.setFromTriplets(entries.begin(), entries.end());
  Eigen::VectorXd rhs(n);
  std::vector<Vec3> g;
  volume_gradient(t.faces, x, g);
  for (std::size_t i = 0; i < x.size(); ++i) rhs.segment<3>(3 * static_cast<Eigen::Index>(i)) = g[i] / volume;
  Eigen::LeastSquaresConjugateGradient<Eigen::SparseMatrix<double>> solver;
  solver.setTolerance(1e-12);
  solver.setMaxIterations(20000);
  solver.compute(A);
  const Eigen::VectorXd tension = solver.solve(rhs);
  return {tension.data(), tension.data() + tension.size()};
}

double stiffness_from_intent(const StiffnessIntent& intent, double lambda) {
  if (intent.youngs_Pa > 0.0) return std::sqrt(3.0) / 2.0 * intent.youngs_Pa * intent.thickness_m;  // N/m
  const double omega = 2.0 * std::numbers::pi * intent.frequency_Hz;
  return omega * omega / lambda;  // k = ω² / λ [N/m]
}

// The gas a pressure intent asks for, per unit spring stiffness: nRT / k [m²] and the unit tensions t¹.
struct GasPerStiffness {
  double nRT_per_k = 0.0;
  std::vector<double> unit_tension;  // per edge [N per J of nRT]
};

GasPerStiffness gas_per_stiffness(const PressureIntent& intent, const Body& body, std::span<const Vec3> x) {
  const Topology& t = body.topology;
  GasPerStiffness gas;
  gas.unit_tension = unit_gas_tensions(t, x, enclosed_volume(t.faces, x));
  // Global balance (virtual work of the breathing mode): nRT Σ t¹_e L_e = k Σ (L − L0) L with the mean
  // strain (L − L0)/L0 = f, i.e. L − L0 = L f / (1 + f).
  double sum_tL = 0.0, sum_L2 = 0.0;
  for (std::size_t e = 0; e < t.edges.size(); ++e) {
    sum_tL += gas.unit_tension[e] * body.rest.edge_length_m[e];
    sum_L2 += body.rest.edge_length_m[e] * body.rest.edge_length_m[e];
  }
  gas.nRT_per_k = intent.inflation / (1.0 + intent.inflation) * sum_L2 / sum_tL;
  return gas;
}

// For start "equilibrium": the rest lengths L0 = L − t/k with the gas's tensions t = nRT t¹.
void set_equilibrium_rest_lengths(const PressureIntent& intent, const GasPerStiffness& gas, RestShape& shape,
                                  const std::string& key_path) {
  for (std::size_t e = 0; e < shape.edge_length_m.size(); ++e) {
    const double rest = shape.edge_length_m[e] - gas.nRT_per_k * gas.unit_tension[e];
    if (!(rest > 0.0)) {
      throw softbody::InputError(key_path + ".pressure: inflation " + std::to_string(intent.inflation) +
                                 " needs a spring compressed below zero length on this mesh (expected a smaller "
                                 "inflation or a convex mesh)");
    }
    shape.edge_length_m[e] = rest;
  }
  shape.mean_edge_m = mean_edge_length(shape);
}

// Σ_i m_i |x_i − c|² about the centre of mass c [kg m²]: the breathing mode's inertia.
double breathing_inertia(const Body& body, std::span<const Vec3> x) {
  const Vec3 centre = centre_of_mass(body, x);
  double inertia = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) inertia += body.masses.kg[i] * (x[i] - centre).squaredNorm();
  return inertia;
}

}  // namespace

double breathing_lambda(const Body& body, std::span<const Vec3> x) {
  double sum_L2 = 0.0;
  for (const auto& [i, j] : body.topology.edges) sum_L2 += (x[i] - x[j]).squaredNorm();
  return sum_L2 / breathing_inertia(body, x);
}

Params resolve_params(const Params& raw, const BodyIntent& intent, Body& body, std::span<const Vec3> x,
                      const std::string& key_path) {
  Params params = raw;
  const double lambda_b = breathing_lambda(body, x);
  const PressureIntent* pressure = intent.pressure && intent.pressure->inflation > 0.0 ? &*intent.pressure : nullptr;
  std::optional<GasPerStiffness> gas;
  if (pressure) gas = gas_per_stiffness(*pressure, body, x);
  // The breathing mode's stiffness per unit k [1/kg]: the springs' λ_b, plus, when the body starts at the
  // gas's equilibrium, the gas: E_gas = −nRT ln V with V ∝ (1 + s)³ gives d²E_gas/ds² = 3 nRT, i.e.
  // ω_b² = k (λ_b + 3 (nRT/k) / I) = k λ_b (1 + f/(1 + f)) for inflation f (3 nRT = k f/(1+f) Σ L²).
  const double lambda = lambda_b + (gas && pressure->start_at_equilibrium
                                        ? 3.0 * gas->nRT_per_k / breathing_inertia(body, x)
                                        : 0.0);
  if (intent.stiffness) params.stiffness_N_per_m = stiffness_from_intent(*intent.stiffness, lambda);
  if (intent.damping_ratio) {
    // Dampers act along the springs: the breathing mode's damping rate is γ = c λ_b, and ζ = γ / (2 ω_b).
    const double omega_b = std::sqrt(params.stiffness_N_per_m * lambda);
    params.damping_N_s_per_m = omega_b > 0.0 ? 2.0 * *intent.damping_ratio * omega_b / lambda_b : 0.0;
  }
  if (pressure) {
    const double k = params.stiffness_N_per_m;
    if (k <= 0.0) throw softbody::InputError(key_path + ".pressure.inflation: needs springs (stiffness > 0)");
    params.pressure_J = k * gas->nRT_per_k;
    // start "rest": the mesh stays the springs' rest shape; the gas inflates the body to about (1 + f).
    if (pressure->start_at_equilibrium) set_equilibrium_rest_lengths(*pressure, *gas, body.rest, key_path);
  }
  return params;
}

}  // namespace sim
