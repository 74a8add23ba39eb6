// The largest stable time step of a world for each integrator, estimated from its stiffest modes.
//
// Design note. Linearised about the initial state, each body is M ẍ = −K x − C ẋ + gas, with K the
// spring stiffness matrix, C = (c/k) K_dd the damper matrix (dampers act along the springs, so C has the
// pattern of the springs' axial part K_dd) and a gas term. The bending links (sim/forces/bending.hpp) are springs
// with k_b and c_b = (c/k) k_b: K and C take them with the weight k_b / k, and C stays (c/k) K_dd. A mode of M⁻¹K_dd
// with eigenvalue λ [1/kg] therefore has
//     μ = k λ (1 + r_gas)   squared frequency [1/s²], r_gas = the gas's share relative to the springs
//     γ = c λ              damping rate [1/s]           (ζ ω = γ / 2: proportional damping)
// and obeys ẍ = −μ x − γ ẋ. A step of size h multiplies (x, v) of that mode by the integrator's
// amplification matrix G(h μ, h γ); the step is stable while every mode's spectral radius ρ(G) ≤ 1.
// The estimate takes λ_max (power iterations on M⁻¹K, bounded above by Gershgorin), samples λ down to
// λ_max·1e-6 (low modes matter for forward Euler: h < c/k whatever λ), and bisects h for each.
//
//   integrator   G for one mode                                undamped limit
//   euler        I + hA,  A = [[0, 1], [−μ, −γ]]                none (ρ > 1 at every h)
//   symplectic   v' = v + h a(x, v), x' = x + h v'               h < 2/ω
//   verlet       kick-drift-kick with cached a (3×3 map)         h < 2/ω
//   rk4          Σ_{j≤4} (hA)^j / j!                             h < 2.83/ω
//   rk45         Σ_{j≤5} (hA)^j / j! + (hA)^6 / 600 (DOPRI5)     h < 3.3/ω (step chosen adaptively)
//   xpbd         springs and dampers as compliant constraints: no limit; the gas explicit: h < 2/ω_gas
#pragma once

#include <array>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "sim/model/body.hpp"
#include "sim/model/model.hpp"
#include "sim/model/settings.hpp"
#include "sim/model/state.hpp"

namespace sim {

// Power iterations per body: a fixed count, so the estimate costs 100 passes over the edges whatever the
// mesh; Gershgorin's bound caps λ where they have not converged.
inline constexpr int kPowerIterations = 100;

// What the estimate knows about one body's fastest modes.
struct ModeBounds {
  double lambda_max_per_kg = 0.0;         // λ_max of M⁻¹K_dd with k = 1 (links k_b/k), from power iterations [1/kg]
  double lambda_gershgorin_per_kg = 0.0;  // Gershgorin's upper bound on the same: max_i (‖K_ii‖ + Σ_j ‖K_ij‖) / m_i
  double omega2_springs = 0.0;            // k λ [1/s²], with the stretched springs' geometric stiffness
  double omega2_gas = 0.0;                // the gas's local and breathing stiffness over the mass [1/s²]
  double damping_rate = 0.0;              // γ = c λ of the fastest mode [1/s] (+ the smooth contact's 2ζω)
  double omega2_contact = 0.0;            // the smooth floor contact's spring per unit mass, 1/τ² [1/s²]
  double omega_max() const;               // √(ω²_springs + ω²_gas + ω²_contact) [rad/s]
};

// Mesh statistics the `info` command prints with the estimate.
struct BodyStats {
  int vertices = 0, edges = 0, faces = 0;
  int valence_min = 0, valence_max = 0;
  double edge_min_m = 0.0, edge_max_m = 0.0;
  double mass_min_kg = 0.0, mass_max_kg = 0.0;
  double rest_volume_m3 = 0.0;
};

// The stable dt of every integrator, smallest over the model's bodies.
struct StabilityEstimate {
  static constexpr double kUnlimited = std::numeric_limits<double>::infinity();
  std::vector<ModeBounds> bodies;                         // per body
  std::array<double, kIntegrators.size()> stable_dt_s{};  // indexed by IntegratorKind; 0: unstable at every dt
  double travel_dt_s = kUnlimited;                        // contact limit (with a floor), already in stable_dt_s
  int limiting_body = 0;                                  // the body with the highest ω_max
  double impact_speed_m_per_s = 0.0;                      // the fastest vertex, plus a fall to the floor if any
  double stable_dt(IntegratorKind integrator) const { return stable_dt_s[static_cast<int>(integrator)]; }
};

// The safety factor `solver.dt: "auto"` applies to the estimate (contacts and large deformations move
// the limit a little; measured margins in docs/physics/stability.md).
constexpr double kAutoDtSafety = 0.7;

BodyStats body_stats(const Body& body, std::span<const Vec3> x);
ModeBounds mode_bounds(const Body& body, std::span<const Vec3> x);

// Largest h with ρ(G(h)) ≤ 1 for every mode of these bounds (0: none; kUnlimited: no limit).
double stable_dt(IntegratorKind integrator, const ModeBounds& bounds);

// A contact limit for every integrator when there is a floor: no vertex may travel more than a tenth of
// the body's shortest edge in one step, at its speed now plus what a fall to the floor adds, √(2 |g| h), plus a
// keyframed collider's fastest point's speed (sim::fastest_point_speed); so the floor projection sees a fast
// body (50 m/s) at once and never crushes it in a single step.
constexpr double kTravelFraction = 0.1;

// Forward Euler's damper limit h < c/k is sharp: at h = c/k every underdamped mode has |g|² = 1 + hλ(hk − c) = 1
// at once, so nothing is left for the nonlinear terms (stretch-dependent geometric stiffness, the gas). Its
// estimate is this fraction of the linear limit.
constexpr double kSharpLimitMargin = 0.9;
// Every explicit method with floor contact: the projection moves vertices between steps, which costs up to a
// tenth of the free-flight limit (measured: docs/physics/stability.md).
constexpr double kContactMargin = 0.9;
// Symplectic Euler on the floor, further: its reversal (sim/integrators/symplectic_euler.hpp) keeps a damped
// body's free-flight limit, but the projection y ← floor moves a vertex without changing its velocity, and
// without dampers nothing takes that energy out again. A measured factor, not derived
// (docs/physics/stability.md, "Floor contact and the step"); with kContactMargin the estimate is 0.72 × the
// free-flight one.
constexpr double kSymplecticProjectionFactor = 0.8;
// Forward Euler with the paper's floor response (v ← −v, the tangential velocity included): for one mode
// reversed every step, R·(I + hA) has an eigenvalue above 1 at every h, so each reversal pumps energy that only
// the dampers remove. The stable step is a fraction of c/k that falls with the fastest mode's damping ratio
// ζ_max = γ/(2ω) = c√λ_max/(2√k), measured on icospheres 0-5 and not derived (docs/physics/stability.md,
// "Floor contact and the step"); the estimate takes 10 % below the largest dt found stable. The friction
// contact changes only the normal velocity and costs nothing.
constexpr double kPaperEulerFractionLightDamping = 0.75;  // of c/k, ζ_max < kPaperEulerZeta
constexpr double kPaperEulerFractionHeavyDamping = 0.27;  // of c/k, ζ_max ≥ kPaperEulerZeta
constexpr double kPaperEulerZeta = 0.5;

// The estimate for a model in `state` (with the contact limit), or for bodies at positions `x`
// (all bodies' vertices; spring, damper and gas limits only). Without `modes` the model's estimate leaves out the
// bodies' modes (their power iterations: a tenth of a second at 40,000 vertices), so that it holds the contact's
// travel limit and impact speed only: what auto_substeps asks for vbd.
StabilityEstimate estimate_stability(const Model& model, const State& state, bool modes = true);
StabilityEstimate estimate_stability(std::span<const Body> bodies, std::span<const Vec3> x);

// The dt `solver.dt: "auto"` uses: kAutoDtSafety × the estimate; where nothing limits it (free particles), a quarter
// of `frame_interval_s` for accuracy. Throws softbody::InputError for forward Euler without dampers (unstable at every
// dt), naming the key.
double auto_dt(const StabilityEstimate& estimate, IntegratorKind integrator, double frame_interval_s,
               const std::string& scene_file);

// `solver.substeps: "auto"` (and `dt: "auto"`) of `integrator`, xpbd: the fewest substeps per frame interval whose
// substep h keeps (1) every body in the carried form, h ≤ xpbd_carried_dt (ω_max: the fastest mode of springs, gas and
// contact, ModeBounds::omega_max), and (2) the contact travel of every integrator, a tenth of the shortest edge
// per step (travel_dt_s).
//
// The classical form (h ω_max above the limit) takes no stability limit from the springs (xpbd.hpp), but one
// constraint pass per substep leaves a pressurised body inflated by a free-flight volume bias, fitted as
//   bias ≈ kXpbdBiasScale (h ω_max)^kXpbdBiasPower (N / 642)^kXpbdBiasMeshPower      (N: the body's vertices)
// on the bounce ball at icosphere:3 and :5, one material (docs/notes/2026-12-05-header-derivations.md);
// xpbd_bias_dt solves it for h.
constexpr double kXpbdVolumeBias = 0.005;  // the bias xpbd_bias_dt aims for (0.5 % of the volume)
constexpr double kXpbdBiasScale = 0.0048;  // bias at h ω_max = 1 on icosphere:3
constexpr double kXpbdBiasPower = 1.25;
constexpr double kXpbdBiasMeshPower = 0.43;
constexpr int kXpbdMostAutoSubsteps = 10000;  // at least 1, at most this many
// xpbd takes its carried form (sim/integrators/xpbd.hpp) while h ≤ xpbd_carried_dt: h ω_max ≤
// kXpbdCarriedPhaseLimit. That form has no volume bias, but its explicit part has a stability limit: 1.9 is
// 0.6 × the fastest substep that stayed stable on the bounce ball (icosphere:3 and :5), with about 1 % volume
// error on both (docs/notes/2026-12-05-header-derivations.md). The guard stops a run that diverges anyway, and
// solver.retry halves the substep, which keeps the form.
constexpr double kXpbdCarriedPhaseLimit = 1.9;
// The largest substep of the carried form for a body with fastest mode ω_max (kUnlimited: no modes).
double xpbd_carried_dt(double omega_max);
// The substep bound of (1) for one body of `vertices` vertices with fastest mode ω_max [s] (kUnlimited: no modes).
double xpbd_bias_dt(double omega_max, int vertices);
// vbd's `solver.substeps: "auto"`: every force is implicit, nothing limits its step but accuracy. With a smooth floor
// (or none) one step per frame interval but at most kVbdLongestAutoStep, since vbd shrinks its own steps around
// an impact (sim/integrators/vertex_block_descent.hpp); with a floor whose contact is a projection after the step,
// (2), whose travel limit that projection needs.
constexpr double kVbdLongestAutoStep = 1.0 / 30.0;  // s: measured on scenes/bounce_smooth.json (docs/notes)
int auto_substeps(IntegratorKind integrator, const Model& model, const StabilityEstimate& estimate,
                  double frame_interval_s);
// Whether a contact acts after the step as a projection (a paper or friction floor, a keyframed collider's projection,
// the impulse contact between bodies or of a body with itself): then every integrator's step keeps the travel limit.
bool contact_after_step(const Model& model);
// The fewest substeps per frame interval that keep (2), the contact travel limit, where it binds `integrator` (vbd:
// only with a contact after the step; 1 where nothing binds).
int travel_substeps(IntegratorKind integrator, const Model& model, const StabilityEstimate& estimate,
                    double frame_interval_s);

// What a floor costs (kContactMargin; with the paper's response also kSymplecticProjectionFactor and
// kPaperEuler*; the smooth contact adds its spring and dashpot to every body's fastest mode, a bound: the
// contact acts on the same vertices as the springs, so the stiffest mode is at most the sum); the travel
// limit needs velocities and is applied by estimate_stability(model, state).
void scale_for_floor_contact(StabilityEstimate& estimate, const Floor& floor);
// The colliders' contacts as the floor's: each smooth one's spring, dashpot and friction, and a projection's margins
// once (not again where the floor's contact already took them).
void scale_for_collider_contacts(StabilityEstimate& estimate, const Model& model);
// The floor's (if any), the colliders' and the smooth body contact's (with several bodies) costs.
void scale_for_contacts(StabilityEstimate& estimate, const Model& model);

}  // namespace sim
