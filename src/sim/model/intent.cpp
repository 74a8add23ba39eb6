// Resolving physical intent: breathing-mode Rayleigh quotient, lattice stiffness, equilibrium tensions.
#include "sim/model/intent.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

#include "core/errors.hpp"
#include "sim/forces/energy.hpp"
#include "sim/forces/forces.hpp"

namespace sim {
namespace {

// The equilibrium equations at shape x, one column per edge and three rows per vertex:
//   Σ_{e∋i} −t_e d̂_e(i) + (1/V) ∂V/∂x_i = 0,  d̂_e(i) the unit vector from the other end to i,
// as A t = b with A's column e holding d̂_e at i and −d̂_e at j, and b_i = (1/V) ∂V/∂x_i.
struct TensionSystem {
  Eigen::SparseMatrix<double> A;
  Eigen::VectorXd b;  // per unit nRT [1/m]
};

TensionSystem tension_system(const Topology& t, std::span<const Vec3> x, double volume) {
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
  TensionSystem system;
  system.A.resize(n, m);
  system.A.setFromTriplets(entries.begin(), entries.end());
  system.b.resize(n);
  std::vector<Vec3> g;
  volume_gradient(t.faces, x, g);
  for (std::size_t i = 0; i < x.size(); ++i) system.b.segment<3>(3 * static_cast<Eigen::Index>(i)) = g[i] / volume;
  return system;
}

// The least-squares solution of A t = b, to |Aᵀ(A t − b)| ≤ tolerance |Aᵀ b|, from `guess` when given.
Eigen::VectorXd least_squares(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& b, double tolerance = 1e-12,
                              const Eigen::VectorXd* guess = nullptr) {
  Eigen::LeastSquaresConjugateGradient<Eigen::SparseMatrix<double>> solver;
  solver.setTolerance(tolerance);
  solver.setMaxIterations(20000);
  solver.compute(A);
  return guess ? Eigen::VectorXd(solver.solveWithGuess(b, *guess)) : Eigen::VectorXd(solver.solve(b));
}

// Edge tensions t_e [N] per unit nRT that balance the gas at shape x, vertex by vertex (tension_system):
// 3n equations for 3n − 6 tensions (a closed triangulated surface); rigid motions are balanced anyway, and
// a convex polyhedron is infinitesimally rigid (Dehn), so the least-squares solution is exact there.
std::vector<double> unit_gas_tensions(const Topology& t, std::span<const Vec3> x, double volume) {
  const TensionSystem system = tension_system(t, x, volume);
  const Eigen::VectorXd tension = least_squares(system.A, system.b);
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

// The closest equilibrium when the exact one needs a rest length at or below zero (a tension t_e ≥ k L_e). On a
// non-convex mesh the exact least-squares tensions balance the gas by large tensions and compressions that
// cancel (the surface is nearly a mechanism there), so no bound on single springs repairs them. Instead the
// tensions are pulled towards the membrane's T0_e = k L_e f/(1 + f) (every spring at the mean strain f, the
// intent's own measure) by Tikhonov regularisation,
//     min_t |A t − nRT b|² + α² |t − T0|²      (A, b: the tension_system; [N²])
// which gives the exact solution at α → 0 and T0 at α → ∞. The smallest α (bisected on log α) whose tensions
// leave every rest length L0 = L − t/k at least kShortestRestFraction · L is taken: the closest balance with
// springs no more than doubled in length.
constexpr double kShortestRestFraction = 0.5;  // L0 ≥ L/2: no spring starts stretched beyond twice its rest length
constexpr int kRegularisationBisections = 10;  // log α to 10/2^10 of a decade

struct ClosestEquilibrium {
  std::vector<double> rest_length_m;
  double residual_fraction = 0;  // |A t − nRT b| / |nRT b|: the residual force over the gas force (RMS)
  double inflation = 0;          // the mean strain it reaches (the intent's measure)
};

// The regularised tensions for weight α [N] (see above): least squares of [A; α I] t = [nRT b; α T0], from the
// guess t. A tolerance of 1e-9 puts t well within what the bisection resolves.
Eigen::VectorXd regularised_tensions(const TensionSystem& system, const Eigen::VectorXd& gas,
                                     const Eigen::VectorXd& membrane, double alpha, const Eigen::VectorXd& guess) {
  const Eigen::Index rows = system.A.rows(), m = system.A.cols();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(system.A.nonZeros() + m));
  for (Eigen::Index e = 0; e < system.A.outerSize(); ++e) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(system.A, e); it; ++it) {
      entries.emplace_back(it.row(), it.col(), it.value());
    }
    entries.emplace_back(rows + e, e, alpha);
  }
  Eigen::SparseMatrix<double> stacked(rows + m, m);
  stacked.setFromTriplets(entries.begin(), entries.end());
  Eigen::VectorXd rhs(rows + m);
  rhs << gas, alpha * membrane;
  return least_squares(stacked, rhs, 1e-9, &guess);
}

bool rest_lengths_allowed(const Eigen::VectorXd& tension, const std::vector<double>& L, double k) {
  for (std::size_t e = 0; e < L.size(); ++e) {
    if (L[e] - tension[static_cast<Eigen::Index>(e)] / k < kShortestRestFraction * L[e]) return false;
  }
  return true;
}

ClosestEquilibrium closest_equilibrium(const Body& body, std::span<const Vec3> x, double k, double nRT,
                                       double inflation) {
  const Topology& t = body.topology;
  const TensionSystem system = tension_system(t, x, enclosed_volume(t.faces, x));
  const Eigen::VectorXd gas = nRT * system.b;  // the gas force per vertex [N]
  const std::vector<double>& L = body.rest.edge_length_m;
  Eigen::VectorXd membrane(static_cast<Eigen::Index>(L.size()));
  for (std::size_t e = 0; e < L.size(); ++e)
    membrane[static_cast<Eigen::Index>(e)] = k * L[e] * inflation / (1.0 + inflation);
  // Bisect log α between a weight that is nearly exact and one that is nearly the membrane (feasible for f < 1).
  double low = -6.0, high = 4.0;  // log10 α
  Eigen::VectorXd best = membrane;
  for (int it = 0; it < kRegularisationBisections; ++it) {
    const double mid = 0.5 * (low + high);
    const Eigen::VectorXd tension = regularised_tensions(system, gas, membrane, std::pow(10.0, mid), best);
    if (rest_lengths_allowed(tension, L, k)) {
      best = tension;
      high = mid;
    } else {
      low = mid;
    }
  }
  ClosestEquilibrium closest;
  closest.rest_length_m.resize(L.size());
  double sum_stretch_L = 0.0, sum_L2 = 0.0;
  for (std::size_t e = 0; e < L.size(); ++e) {
    closest.rest_length_m[e] = L[e] - best[static_cast<Eigen::Index>(e)] / k;  // L0 = L − t/k
    sum_stretch_L += (L[e] - closest.rest_length_m[e]) * L[e];
    sum_L2 += L[e] * L[e];
  }
  closest.residual_fraction = (system.A * best - gas).norm() / gas.norm();
  const double q = sum_stretch_L / sum_L2;  // Σ (L − L0) L / Σ L² = f / (1 + f), as in gas_per_stiffness
  closest.inflation = q / (1.0 - q);
  return closest;
}

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2g %%", 100.0 * fraction);
  return text;
}

// For start "equilibrium": the rest lengths L0 = L − t/k with the gas's tensions t = nRT t¹; where one would
// be at or below zero, the closest equilibrium instead, with a note saying how close.
void set_equilibrium_rest_lengths(const PressureIntent& intent, const GasPerStiffness& gas, Body& body,
                                  std::span<const Vec3> x, double k, const std::string& key_path,
                                  std::vector<std::string>& notes) {
  RestShape& shape = body.rest;
  std::vector<double> rest(shape.edge_length_m.size());
  int negative = 0;
  for (std::size_t e = 0; e < rest.size(); ++e) {
    rest[e] = shape.edge_length_m[e] - gas.nRT_per_k * gas.unit_tension[e];
    if (!(rest[e] > 0.0)) ++negative;
  }
  if (negative > 0) {
    const ClosestEquilibrium closest = closest_equilibrium(body, x, k, k * gas.nRT_per_k, intent.inflation);
    rest = closest.rest_length_m;
    char inflation[32];
    std::snprintf(inflation, sizeof inflation, "%.3g", intent.inflation);
    char reached[32];
    std::snprintf(reached, sizeof reached, "%.3g", closest.inflation);
    notes.push_back(key_path + ".pressure: no exact equilibrium at inflation " + inflation + " on this mesh (" +
                    std::to_string(negative) + " of " + std::to_string(rest.size()) +
                    " springs would need a rest length at or below zero); starting from the closest one with every "
                    "rest length at least " +
                    percent(kShortestRestFraction) + " of its spring's length: inflation " + reached +
                    ", residual force " + percent(closest.residual_fraction) +
                    " of the gas force (RMS), from which the body moves to its own balance at the start");
  }
  shape.edge_length_m = rest;
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
                      const std::string& key_path, std::vector<std::string>& notes) {
  Params params = raw;
  const double lambda_b = breathing_lambda(body, x);
  const PressureIntent* pressure = intent.pressure && intent.pressure->inflation > 0.0 ? &*intent.pressure : nullptr;
  std::optional<GasPerStiffness> gas;
  if (pressure) gas = gas_per_stiffness(*pressure, body, x);
  // The breathing mode's stiffness per unit k [1/kg]: the springs' λ_b, plus, when the body starts at the
  // gas's equilibrium, the gas: E_gas = −nRT ln V with V ∝ (1 + s)³ gives d²E_gas/ds² = 3 nRT, i.e.
  // ω_b² = k (λ_b + 3 (nRT/k) / I) = k λ_b (1 + f/(1 + f)) for inflation f (3 nRT = k f/(1+f) Σ L²).
  const double lambda =
      lambda_b + (gas && pressure->start_at_equilibrium ? 3.0 * gas->nRT_per_k / breathing_inertia(body, x) : 0.0);
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
    if (pressure->start_at_equilibrium) set_equilibrium_rest_lengths(*pressure, *gas, body, x, k, key_path, notes);
  }
  if (intent.bending_ratio) params.bending_N_per_m = *intent.bending_ratio * params.stiffness_N_per_m;
  if (params.bending_N_per_m > 0.0) {
    if (params.stiffness_N_per_m <= 0.0)
      throw softbody::InputError(key_path + ".bending: needs springs (stiffness > 0)");
    // c_b = c k_b / k: the links damp on the edges' time scale c/k, so the damping stays proportional.
    params.bending_damping_N_s_per_m = params.damping_N_s_per_m * params.bending_N_per_m / params.stiffness_N_per_m;
  }
  return params;
}

}  // namespace sim
