// How far a body's shape is from its rest shape once its rigid motion is taken out: the best-fit rotation and
// translation (Kabsch), then the largest distance of a vertex from its rest position, relative to the body's size.
#pragma once

#include <span>

#include "core/vec.hpp"

namespace analysis {

using softbody::Vec3;

struct ShapeDeviation {
  double largest_m = 0.0;    // max_i |R r_i + t − x_i| with the best-fit R, t [m]
  double rms_m = 0.0;        // the mass-weighted RMS of the same distances [m]
  double body_size_m = 0.0;  // the rest shape's bounding-box diagonal [m]
  double relative() const { return body_size_m > 0.0 ? largest_m / body_size_m : 0.0; }
};

// The rigid motion (R, t) minimising Σ m_i |R r_i + t − x_i|² (Kabsch 1976: t from the centres of mass, R from the
// SVD of the mass-weighted covariance, a reflection excluded), and the deviations that remain.
// rest, x: the same vertices at rest and now; mass_kg: their weights.
ShapeDeviation shape_deviation(std::span<const Vec3> rest, std::span<const Vec3> x, std::span<const double> mass_kg);

}  // namespace analysis
