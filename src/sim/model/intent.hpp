// Physical intent to force constants: a body's stiffness, damping and gas from what the user means
// (Young's modulus, a frequency, a damping ratio, an inflation), resolved against its mesh so that the
// same intent behaves alike at every mesh resolution.
//
// The reference motion is the breathing (uniform scaling) mode u_i = x_i − c about the centre of mass c:
// every spring stretches by its own length, so with k = 1
//     λ_b = Σ_e L_e² / Σ_i m_i |x_i − c|²   [1/kg],   ω_b² = k λ_b   (Rayleigh quotient, exact for a sphere)
// Both sums approximate surface integrals, so λ_b, and with it every rule below, is nearly independent of
// the mesh resolution.
#pragma once

#include <span>

#include <optional>
#include <string>
#include <vector>

#include "sim/model/body.hpp"

namespace sim {

// What the user means by a body's stiffness, damping and gas, instead of the constants themselves.
struct StiffnessIntent {
  double youngs_Pa = 0.0;     // "youngs": Young's modulus of the shell material (> 0 picks this)
  double thickness_m = 1e-3;  // "thickness": shell thickness; membrane stiffness E·t [N/m]
  double frequency_Hz = 0.0;  // "frequency": the springs' breathing-mode frequency (> 0 picks this)
};
struct PressureIntent {
  double inflation = 0.1;            // "inflation": springs stretched by this fraction at equilibrium (0: no gas)
  bool start_at_equilibrium = true;  // "start": "equilibrium" (mesh = equilibrium shape, no pop) or
                                     // "rest" (mesh = the springs' rest shape: the gas inflates it, the pop)
};
struct BodyIntent {
  std::optional<StiffnessIntent> stiffness;  // instead of Params::stiffness_N_per_m
  std::optional<double> damping_ratio;       // ζ, of the breathing mode's critical damping
  std::optional<PressureIntent> pressure;    // instead of Params::pressure_J
  std::optional<double> bending_ratio;       // r: Params::bending_N_per_m = r k (the edges' k after intent)
};

// λ_b of the breathing mode of the springs with k = 1 [1/kg].
double breathing_lambda(const Body& body, std::span<const Vec3> x);

// The body's force constants: the raw numbers, with the intent resolved where it is given:
//   "youngs" E, "thickness" t:  k = (√3/2) E t   (a triangular spring lattice has the 2D Young's modulus
//                                                 2k/√3 at any edge length; Ostoja-Starzewski 2002)
//   "frequency" f:              k = (2π f)² / λ, the breathing mode at f: λ = λ_b for springs alone;
//                               with "pressure" {"inflation": f_i, "start": "equilibrium"} the gas stiffens
//                               the mode, λ = λ_b (1 + f_i/(1 + f_i)) (d²(−nRT ln V)/ds² = 3 nRT for V ∝ (1+s)³)
//   "damping" {"ratio": ζ}:     c = 2 ζ ω_b / λ_b with ω_b² = k λ   (dampers act along the springs:
//                               the breathing mode's damping rate is c λ_b = 2 ζ ω_b)
//   "pressure" {"inflation": f}: nRT and the springs' rest lengths such that the gas balances the springs
//                                stretched by f (mean strain) at the initial shape, vertex by vertex
//                                (start "equilibrium": no pop), or the rest lengths kept and nRT chosen
//                                for that equilibrium (start "rest": the body inflates, the paper's pop).
//                                Where the exact balance needs a rest length at or below zero (a non-convex
//                                mesh), the closest balance with every rest length at least half its edge,
//                                and a note with its residual force and the inflation it reaches.
//   "bending" {"ratio": r}:     k_b = r k (after the stiffness intent), the bending links' stiffness; with
//                               any k_b > 0, c_b = c k_b / k (sim/forces/bending.hpp)
// `raw` holds the constants given as numbers. May change body.rest.edge_length_m (and its mean); adds to
// `notes` (each naming `key_path`). Throws softbody::InputError (naming `key_path`, e.g. "scene.json: bodies.0")
// for an intent the body cannot have (inflation or bending without springs).
Params resolve_params(const Params& raw, const BodyIntent& intent, Body& body, std::span<const Vec3> x,
                      const std::string& key_path, std::vector<std::string>& notes);

}  // namespace sim
