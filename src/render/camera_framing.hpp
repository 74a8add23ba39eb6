// The camera a scene without `camera` gets: it looks at the box that the bodies sweep over the whole run (and the
// bounded colliders take, a keyframed one wherever it goes), from the default camera's direction, near enough to
// fill the picture and far enough to keep every body in view with a margin.
#pragma once

#include <span>

#include "render/settings.hpp"
#include "render/shadow_map.hpp"
#include "sim/model/settings.hpp"

namespace render {

// Fraction of the half-width and half-height of the picture kept free around the swept box.
constexpr float kFramingMargin = 0.12f;

// Looks at the centre of `swept` along the default camera's view direction (slightly from above: the
// floor's horizon stays in the picture for any vertical field of view over 2 × 8.2°), at the smallest
// distance at which each of the box's 8 corners lies inside the picture shrunk by `margin`: a corner at
// (x, y, z) in camera axes around the centre (z towards the camera) needs
//   d >= |x| / ((1 − margin) tan(θh)) + z  and  d >= |y| / ((1 − margin) tan(θv)) + z,
// with θv half the vertical field of view and tan(θh) = aspect · tan(θv) (pinhole projection).
// `swept` grown to hold every bounded collider (a plane is unbounded: it does not count).
Bounds including_colliders(const Bounds& swept, std::span<const sim::ColliderGeometry> colliders);

// `swept` grown to hold each keyframed collider (`moving`) where it is at each of `frame_times_s` and at each of its
// keys between the first and the last of them (a key the frames pass between, where a linear motion turns), so that
// a swinging paddle stays in the picture.
Bounds including_moving_colliders(const Bounds& swept, std::span<const sim::Collider> moving,
                                  std::span<const double> frame_times_s);

CameraSettings frame_swept_box(const Bounds& swept, float aspect, float fov_deg, float margin = kFramingMargin);

}  // namespace render
