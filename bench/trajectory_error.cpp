// Error measures of a recorded bounce against a reference run (bench_large_steps).
#include "trajectory_error.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace bench {

namespace {

// Σ_i |x_i − x_ref,i|² over one sample's vertices [m²].
double squared_distance_sum(const std::vector<softbody::Vec3>& x, const std::vector<softbody::Vec3>& x_ref) {
  double sum = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) sum += (x[i] - x_ref[i]).squaredNorm();
  return sum;
}

}  // namespace

TrajectoryError trajectory_error(const BounceRecord& run, const BounceRecord& reference) {
  TrajectoryError e;
  const std::size_t samples = std::min(run.volume_m3.size(), reference.volume_m3.size());
  e.samples = static_cast<int>(samples);
  double squared_sum = 0.0;
  std::size_t terms = 0;
  for (std::size_t s = 0; s < samples; ++s) {
    e.com_max_m = std::max(e.com_max_m, (run.com_m[s] - reference.com_m[s]).norm());
    e.volume_worst_pct =
        std::max(e.volume_worst_pct, 100.0 * std::abs(run.volume_m3[s] / reference.volume_m3[s] - 1.0));
    if (s == 0) continue;
    squared_sum += squared_distance_sum(run.x_m[s], reference.x_m[s]);
    terms += run.x_m[s].size();
  }
  if (samples > 0) {
    const std::vector<softbody::Vec3>& last = run.x_m[samples - 1];
    e.rms_end_m = std::sqrt(squared_distance_sum(last, reference.x_m[samples - 1]) / static_cast<double>(last.size()));
  }
  if (terms > 0) e.rms_samples_m = std::sqrt(squared_sum / static_cast<double>(terms));
  return e;
}

}  // namespace bench
