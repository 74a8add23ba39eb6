// The solver's settings types: integrators (the one list every part of the program reads), floor and
// body contact, and the solver options. Plain data with defaults; the scene file fills them (src/scene/).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "sim/contact/collider_motion.hpp"
#include "sim/contact/collider_shape.hpp"

namespace sim {

// Time integrators (src/sim/integrators/): the paper's forward Euler and the methods compared in
// docs/physics/integrators.md. kIntegrators below lists them with their names and properties.
enum class IntegratorKind {
  Euler,       // forward Euler (Matyka & Ollila 2003, Eq. 11): first order
  Symplectic,  // semi-implicit Euler: v from the force, then x from the new v; first order, symplectic
  Verlet,      // velocity Verlet: second order, one force evaluation per step
  Rk4,         // classical Runge–Kutta: fourth order, four force evaluations per step
  Rk45,        // Dormand–Prince 5(4): adaptive step from an error estimate (solver.tolerance)
  Xpbd,        // substepped extended position-based dynamics (Macklin et al. 2016, 2019): first order, one
               // constraint pass per substep, springs as compliant constraints: stable at large steps
  Vbd,         // vertex block descent (Chen et al. 2024) on BDF2's implicit step, every force implicit: second order
               // when its sweeps converge, stable at large steps
};

// What the program needs to know of an integrator besides its code.
struct IntegratorInfo {
  IntegratorKind kind;
  std::string_view name;  // in scene files, on the command line, in CSVs and messages
  int order;              // convergence order on smooth motion (rk45: 5, its propagated solution)
  bool adaptive;          // chooses its own step sizes (driven by sim::advance_to)
  bool explicit_springs;  // the springs limit its stable step (every method but xpbd and vbd)
  bool position_based;    // velocities follow from positions, v = (x − x_prev)/h, and the friction floor is a
                          // positional constraint with static friction (xpbd only; sim/contact/contact.hpp)
  bool frame_substeps;    // its step is solver.substeps per frame interval (or "auto"), not solver.dt (xpbd, vbd)
};

// Every integrator, in the order of the enum: the parser, `info`, the stability estimate and the
// benchmarks all iterate this list.
inline constexpr std::array<IntegratorInfo, 7> kIntegrators = {{
    {IntegratorKind::Euler, "euler", 1, false, true, false, false},
    {IntegratorKind::Symplectic, "symplectic", 1, false, true, false, false},
    {IntegratorKind::Verlet, "verlet", 2, false, true, false, false},
    {IntegratorKind::Rk4, "rk4", 4, false, true, false, false},
    {IntegratorKind::Rk45, "rk45", 5, true, true, false, false},
    {IntegratorKind::Xpbd, "xpbd", 1, false, false, true, true},
    {IntegratorKind::Vbd, "vbd", 2, false, false, false, true},
}};
static_assert(
    [] {
      for (int i = 0; i < static_cast<int>(kIntegrators.size()); ++i) {
        if (static_cast<int>(kIntegrators[i].kind) != i) return false;
      }
      return true;
    }(),
    "kIntegrators lists the integrators in the order of the enum");

constexpr const IntegratorInfo& integrator_info(IntegratorKind integrator) {
  return kIntegrators[static_cast<int>(integrator)];
}
std::string to_string(IntegratorKind integrator);
// The integrator called `name`, or nothing.
std::optional<IntegratorKind> integrator_named(std::string_view name);

// How vertices below the floor are handled.
enum class FloorContact {
  Paper,     // Matyka & Ollila: a vertex below the floor has its velocity reflected and is put back on it
  Friction,  // restitution on the normal velocity, Coulomb friction (static and sliding) on the tangential
  Smooth,    // a penalty spring-damper with regularised Coulomb friction, a force inside a(x, v)
             // (sim/contact/smooth_contact.hpp)
};
std::string to_string(FloorContact contact);

// The rule of an impulse contact (the friction floor, contact between bodies): restitution on the normal
// approach speed and Coulomb friction on the tangential one (sim/contact/contact_response.hpp).
struct ContactMaterial {
  double restitution = 0.5;  // normal speed kept after an impact (0 inelastic .. 1 elastic)
  double friction = 0.5;     // Coulomb coefficient μ (static = sliding)
  // Below this approach speed a contact is resting, not an impact: no bounce, so that a body lying on
  // something does not jitter. 0.05 m/s is the speed gravity gives in 5 ms, well above one step's g·dt.
  double resting_speed_m_per_s = 0.05;
};

// The smooth contact's constants, from an intent: how fast a contact pushes back and how much of an impact's
// speed it returns. Per vertex of mass m the contact is a spring m/τ² and a dashpot 2ζm/τ on the
// penetration (an oscillator of ω = 1/τ and damping ratio ζ, like MuJoCo's solref), so every vertex, light
// or heavy, meets the floor on the same time scale, and the stable step it asks for does not depend on the
// mesh (sim/contact/smooth_contact.hpp derives the force).
struct SmoothContact {
  double time_constant_s = 0.002;   // τ = 1/ω: an impact of one vertex lasts about π τ
  double damping_ratio = -1.0;      // ζ; < 0: from the material's restitution, e = exp(−πζ/√(1−ζ²))
  double slip_speed_m_per_s = 0.1;  // ε: Coulomb friction is regularised as μ N v_t / √(|v_t|² + ε²); its
                                    // stiffness μN/ε limits explicit steps (0.01 m/s needed 4× smaller ones)
  double smoothing_m = 0.002;       // δ: the spring stiffens from 0 to m/τ² over the first δ of penetration
                                    // (a C² ramp, so that the equations of motion stay smooth: rk4 keeps
                                    // its order through an impact)
};

struct Floor {
  double height_m = 0.0;  // the plane y = height_m
  FloorContact contact = FloorContact::Paper;
  ContactMaterial material;  // the friction and smooth contacts' restitution and friction
  SmoothContact smooth;      // the smooth contact's constants
};

// A shape that moves bodies and is not moved by them (static or keyframed), with a floor's contact model and
// constants (sim/contact/collider_contact.hpp, smooth_collider.hpp): a plane collider acts as a floor does.
struct Collider {
  ColliderGeometry geometry;  // static: its pose; keyframed: its sizes at scale 1 (the pose comes from `motion`)
  FloorContact contact = FloorContact::Paper;
  ContactMaterial material;
  SmoothContact smooth;
  ColliderMotion motion;  // no keys: static
  // The continuous check of every step (sim/contact/collider_sweep.hpp); tests switch it off to show what the
  // discrete test alone lets through.
  bool continuous = true;
};

// The collider's shape at time t, with the velocity of its points.
inline ColliderGeometry collider_at(const Collider& collider, double time_s) {
  return geometry_at(collider.geometry, collider.motion, time_s);
}

// How bodies touch each other.
enum class BodyContactModel {
  Impulse,  // after each step: a vertex inside is moved out, with restitution and Coulomb friction impulses
  Smooth,   // a penalty spring-damper with regularised friction inside a(x, v) (sim/contact/body_collision.hpp)
};
std::string to_string(BodyContactModel contact);

// Contact between bodies (vertices of one against the triangles of another), when there are several.
struct BodyContact {
  BodyContactModel contact = BodyContactModel::Impulse;
  ContactMaterial material{0.3, 0.5};
  // The smooth model's constants (its spring acts on the vertex's mass). Stiffer than the floor's by default:
  // a body often rests on another on few vertices (a coarse mesh's), each of which then carries much more
  // than its own weight; at τ = 0.5 ms a vertex carrying 200× its weight stays within the 2 mm skin.
  SmoothContact smooth{0.0005};
  // The impulse model's push out of a penetration that a step did not itself cause [m/s] (sim::PushLimit): a
  // vertex found inside another body (or within the contact's thickness of it) is moved out by this step's
  // approach plus at most this speed times the step. A push moves a vertex without a force, against its springs
  // and gas, so it adds energy about in proportion to its speed. 0.1 m/s takes a 1 cm overlap out in 0.1 s and,
  // on two balls started 10 cm into each other, adds less than the impulses take.
  double push_speed_m_per_s = 0.1;
};

// vbd's default solver.impact_phase: around an impact on a smooth contact its steps shrink to ω h ≤ this (ω = 1/τ of
// the contact's spring).
inline constexpr double kVbdImpactPhase = 0.5;
// With "iterations": "auto", where solver.impact_phase is not given: on scenes/bounce_smooth.json at icosphere:4 the
// centre of mass through the first impact is 2.55 cm off at 0.5 and 0.71 cm at this, for 1.12x the run's cost
// (docs/notes/2026-12-07-vbd-auto-impacts.md).
inline constexpr double kVbdAutoImpactPhase = 0.25;

// How vbd ends a step's sweeps (solver.iterations).
enum class SweepControl {
  Count,     // a whole number: solver.iterations sweeps per step
  Converge,  // "converge": until a sweep barely moves a vertex
  Auto,      // "auto": vbd holds its error to a tolerance itself, its sweeps converged to its step and its steps
             // shortened where the gas's volume needs it (sim/integrators/vertex_block_descent.hpp)
};
// "count", "converge" or "auto": the last two as solver.iterations spells them.
std::string to_string(SweepControl control);

struct Solver {
  IntegratorKind integrator = IntegratorKind::Euler;
  double dt_s = 1e-4;    // requested time step; the run uses the largest dt <= this that divides 1/fps
                         // (rk45: only the first trial step; it then chooses its own)
  bool dt_auto = false;  // "dt": "auto": sim::resolve_step sets dt_s from the stable-dt estimate (stability.hpp)
  // xpbd and vbd: substeps per frame interval (xpbd: one constraint pass each), so dt = (1/fps) / substeps, set by
  // sim::resolve_step; 0: dt_s decides. substeps_auto ("substeps": "auto"): the fewest that keep the accuracy
  // sim::auto_substeps states. Not the guard's retry substeps (State::retry_substeps).
  int substeps = 0;
  bool substeps_auto = false;
  // Set by sim::resolve_step where substeps given as a number are longer than the contact travel limit that a contact
  // after the step needs (sim::travel_substeps): that limit [s], for the divergence message; 0 otherwise.
  double travel_dt_exceeded_s = 0.0;
  int iterations = 4;  // vbd: Gauss–Seidel sweeps over the vertices per step (sim/integrators/vertex_block_descent.hpp)
  SweepControl sweep_control = SweepControl::Count;  // "iterations": a number, "converge" or "auto"
  // vbd: its steps around an impact on a smooth contact keep ω h ≤ this; unset: kVbdImpactPhase, or with
  // "iterations": "auto" kVbdAutoImpactPhase (vbd_impact_phase)
  std::optional<double> impact_phase = std::nullopt;
  int coarse_space = 0;           // vbd: cells per body of its coarse level (sim/integrators/coarse_space.hpp); 0: none
  bool coarse_space_auto = true;  // "coarse_space": "auto" (the default): each body's cells by its size
                                  // (sim::auto_coarse_cells); false: coarse_space for every body
  bool retry = false;             // a step the divergence guard rejects is retried as 2, 4, ... substeps (up to 1024;
                                  // State::retry_substeps)
  double tolerance = 1e-6;        // rk45 only: per-step error bound, absolute and relative, on positions [m]
                                  // and velocities [m/s]
  int threads = 0;                // threads for the force passes of large bodies (sim::kParallelMinVertices) and vbd's
                                  // sweeps and coarse corrections; 0: one per core. Results do not depend on it
};

// vbd's solver.impact_phase: the given value, else kVbdAutoImpactPhase with "iterations": "auto" and kVbdImpactPhase
// otherwise.
double vbd_impact_phase(const Solver& solver);

}  // namespace sim
