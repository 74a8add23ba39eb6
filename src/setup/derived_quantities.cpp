// Derived quantities of a scene checked against the range of a double, with the key to change.
#include "setup/derived_quantities.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

#include "core/errors.hpp"

namespace setup {
namespace {

// The most a force constant per vertex, m ω² [N/m], may be: m ω² d and its sums stay far from overflow.
constexpr double kMaxSpringPerVertex = 1e250;

// "KEY: QUANTITY = VALUE UNIT (DETAIL), WHY: expected EXPECTED".
struct Refusal {
  std::string file;
  std::string key;  // "bodies.0.mass"
  const char* quantity;
  const char* unit;
  std::string detail;    // the values it was derived from; empty: none
  std::string expected;  // what to change
};

[[noreturn]] void refuse(const Refusal& r, double value, const char* why) {
  char number[32];
  std::snprintf(number, sizeof number, "%.3g", value);
  throw softbody::InputError(r.file + ": " + r.key + ": " + r.quantity + " = " + number + " " + r.unit +
                             (r.detail.empty() ? "" : " (" + r.detail + ")") + ", " + why + ": expected " + r.expected);
}

// ω² and its kin: finite, and 0 or between the smallest normal double and kMaxSquaredRate.
void check_squared_rate(double value, const Refusal& r) {
  if (!(value <= kMaxSquaredRate)) refuse(r, value, "beyond the limit of 1e200 1/s²");
  if (value != 0.0 && value < DBL_MIN) refuse(r, value, "below the smallest normal double (2.2e-308)");
}

std::string words(const char* format, double a, double b = 0.0) {
  char text[160];
  std::snprintf(text, sizeof text, format, a, b);
  return text;
}

// The key of a constant given as a number or derived from an intent ("bodies.0.stiffness.frequency").
std::string stiffness_key(const scene::Body& spec, const std::string& key_path) {
  if (!spec.intent.stiffness) return key_path + ".stiffness";
  return key_path + (spec.intent.stiffness->frequency_Hz > 0.0 ? ".stiffness.frequency" : ".stiffness.youngs");
}

}  // namespace

void check_body_quantities(const sim::Body& body, const scene::Body& spec, const std::string& file,
                           const std::string& key_path) {
  const auto [lightest, heaviest] = std::minmax_element(body.masses.kg.begin(), body.masses.kg.end());
  if (lightest == body.masses.kg.end()) return;
  const double m = *lightest;
  const std::string mass_key = key_path + ".mass";
  if (!(m >= DBL_MIN && std::isfinite(*heaviest))) {
    refuse({file, mass_key, "the lightest vertex's mass", "kg",
            words("the body's %.3g kg over %.0f vertices", spec.mass_kg, static_cast<double>(body.masses.kg.size())),
            "a larger mass"},
           m, "not a normal double (at least 2.2e-308)");
  }
  const sim::Params& p = body.params;
  const std::string lighter = " or a larger " + mass_key;
  const std::string k_key = stiffness_key(spec, key_path);
  if (!std::isfinite(p.stiffness_N_per_m))
    refuse({file, k_key, "the springs' k", "N/m", "", "a smaller " + k_key}, p.stiffness_N_per_m, "not finite");
  check_squared_rate(
      p.stiffness_N_per_m / m,
      {file, k_key, "k/m", "1/s²", words("k = %.3g N/m, the lightest vertex %.3g kg", p.stiffness_N_per_m, m),
       "a smaller " + k_key + lighter});
  const std::string c_key = key_path + (spec.intent.damping_ratio ? ".damping.ratio" : ".damping");
  const double rate = p.damping_N_s_per_m / m;  // the damper's rate c/m [1/s]
  check_squared_rate(rate * rate, {file, c_key, "(c/m)²", "1/s²",
                                   words("c = %.3g N·s/m, the lightest vertex %.3g kg", p.damping_N_s_per_m, m),
                                   "a smaller " + c_key + lighter});
  const std::string b_key = key_path + (spec.intent.bending_ratio ? ".bending.ratio" : ".bending");
  check_squared_rate(p.bending_N_per_m / m, {file, b_key, "k_b/m", "1/s²",
                                             words("k_b = %.3g N/m, the lightest vertex %.3g kg", p.bending_N_per_m, m),
                                             "a smaller " + b_key + lighter});
  const std::string gas_key = key_path + (spec.intent.pressure ? ".pressure.inflation" : ".pressure");
  const double volume = std::abs(body.rest.volume_m3);
  if (p.pressure_J > 0.0 && volume > 0.0) {
    // The gas's stiffness per vertex scales as the pressure nRT/V over the body's size V^(1/3) and the mass.
    check_squared_rate(
        p.pressure_J / (m * std::pow(volume, 2.0 / 3.0)),
        {file, gas_key, "nRT/(m V^(2/3))", "1/s²",
         words("nRT = %.3g J, the lightest vertex %.3g kg", p.pressure_J, m) + words(", V = %.3g m³", volume),
         "a smaller " + gas_key + lighter});
  }
}

void check_contact_quantities(const scene::Scene& scene, double heaviest_vertex_kg) {
  const auto check = [&](const sim::SmoothContact& contact, const std::string& prefix) {
    const std::string file = scene.source.string(), key = prefix + ".time_constant";
    const std::string expected = "a larger " + prefix + ".time_constant";
    const double omega2 = 1.0 / (contact.time_constant_s * contact.time_constant_s);  // ω = 1/τ [1/s]
    check_squared_rate(omega2, {file, key, "the smooth contact's ω² = 1/τ²", "1/s²", "", expected});
    const double spring = heaviest_vertex_kg * omega2;
    if (!(spring <= kMaxSpringPerVertex)) {
      refuse({file, key, "the smooth contact's spring m ω²", "N/m",
              words("the heaviest vertex %.3g kg", heaviest_vertex_kg), expected + " or smaller masses"},
             spring, "beyond the limit of 1e250 N/m");
    }
    if (contact.damping_ratio > 0.0) {  // its dashpot's rate 2ζω [1/s]
      const double dashpot = 2.0 * contact.damping_ratio * std::sqrt(omega2);
      check_squared_rate(dashpot * dashpot, {file, prefix + ".damping_ratio", "the smooth contact's (2ζ/τ)²", "1/s²",
                                             "", "a smaller " + prefix + ".damping_ratio or a larger time_constant"});
    }
  };
  if (scene.floor && scene.floor->contact == sim::FloorContact::Smooth) check(scene.floor->smooth, "floor");
  if (scene.collisions.contact == sim::BodyContactModel::Smooth) check(scene.collisions.smooth, "collisions");
}

}  // namespace setup
