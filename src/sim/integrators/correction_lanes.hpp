// The coarse corrections' passes over a body's constraints, four constraints at once, one per AVX2 lane: each lane
// evaluates the scalar loop's expressions in its order (motion_search.cpp's take_edge_lag and
// constraint_energy_changes, coarse_space.cpp's edge forces), so the results are its bits. (Their gas gradients
// take the vertex lanes' sums: six_volume_gradients_in_lanes, vertex_move_lanes.hpp.)
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "sim/integrators/motion_search.hpp"
#include "sim/integrators/vertex_energy.hpp"
#include "sim/model/body.hpp"
#include "sim/step/part_runner.hpp"

namespace sim {

// Constraints [first, last): their lags at x into scratch (take_edge_lag) and their spring and damper force on their
// first end, (k (l − L0) + (c/ĥ) ĥ l̇) d/l [N], into force[e] (zero where l = 0). Returns the first constraint it left
// to the scalar loop: the tail short of four, or `first` where the lanes do not run (lanes_on).
std::size_t edge_forces_in_lanes(const DistanceConstraints& constraints, const BodySolve& s, std::span<const Vec3> x,
                                 std::size_t first, std::size_t last, MotionScratch& scratch, std::span<Vec3> force);

// The springs' and dampers' change of E along α scratch.motion over constraints [first, last), with scratch's lags at
// x, added to `change` constraint by constraint in order (spring, then damper; none where l = 0) [J]. Returns where
// it stopped, as above.
std::size_t edge_energy_changes_in_lanes(const DistanceConstraints& constraints, const BodySolve& s,
                                         std::span<const Vec3> x, double alpha, const MotionScratch& scratch,
                                         std::size_t first, std::size_t last, double& change);

// V(x) of `faces` as enclosed_volume's sum (forces.hpp: the faces' terms (x_a − x_0)·((x_b − x_0) × (x_c − x_0)) / 6)
// in chunks of faces on runner's threads (none: in turn), each chunk's terms added in face order and the chunks in
// chunk order: the same bits on any number of threads and with the lanes on or off (where they run, four faces' terms
// at a time), not the same bits as the one-pass sum. `partials`: scratch [m³].
double enclosed_volume_in_lanes(std::span<const Triangle> faces, std::span<const Vec3> x, PartRunner* runner,
                                std::vector<double>& partials);

}  // namespace sim
