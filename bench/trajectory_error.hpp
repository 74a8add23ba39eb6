// How far one recorded bounce is from a reference run: centre-of-mass path, volume and vertex positions.
#pragma once

#include "bounce_run.hpp"

namespace bench {

struct TrajectoryError {
  double com_max_m = 0.0;         // max over samples of |c − c_ref| (c: centre of mass) [m]
  double volume_worst_pct = 0.0;  // max over samples of |V / V_ref − 1| [%]
  double rms_end_m = 0.0;         // √(mean over vertices of |x_i − x_ref,i|²) at the last sample [m]
  double rms_samples_m = 0.0;     // the same mean taken over every sample after t = 0 and every vertex [m]
  int samples = 0;                // samples compared (the run's, when it stopped early)
};

// `run` against `reference` over the samples both have; both must be of the same mesh.
TrajectoryError trajectory_error(const BounceRecord& run, const BounceRecord& reference);

}  // namespace bench
