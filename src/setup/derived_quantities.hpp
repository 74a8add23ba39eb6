// Checks that what setup derives from a scene's numbers fits a double with room to spare: each number is
// within its key's range, but their quotients and products (k/m, (2πf)², 1/τ², nRT/V) can still overflow or
// underflow, and a run would diverge later with a misleading hint. Refused before any step, naming the key.
#pragma once

#include <string>

#include "scene/scene.hpp"
#include "sim/model/body.hpp"

namespace setup {

// The most a squared rate (ω² = k/m, c/m, nRT/(m V^(2/3)), 1/τ²) may be [1/s²]: beyond, the step's products
// (ω² dt², sums over a vertex's springs, m ω² d) come near the largest double (1.8e308).
inline constexpr double kMaxSquaredRate = 1e200;

// A built body (its vertex masses and resolved constants): every vertex mass normal (at least 2.2e-308 kg),
// and k/m, c/m, k_b/m and the gas's nRT/(m V^(2/3)) finite and at most kMaxSquaredRate, each of the
// smallest vertex mass. Throws softbody::InputError naming the scene file, the key (under `body_key`,
// "bodies.0") and what to change.
void check_body_quantities(const sim::Body& body, const scene::Body& spec, const std::string& file,
                           const std::string& body_key);

// The smooth contacts' constants, when the floor or the collisions use them: ω² = 1/τ² and the dashpot's
// (2ζω)² at most kMaxSquaredRate, and the spring m ω² of the heaviest vertex far from overflow.
void check_contact_quantities(const scene::Scene& scene, double heaviest_vertex_kg);

}  // namespace setup
