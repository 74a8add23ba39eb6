// Rotations given as Euler angles in degrees, [rx, ry, rz] applied about the world's X, then Y, then Z axes
// (Blender's default "XYZ Euler"), as bodies and colliders take them in scene files.
#pragma once

#include <numbers>

#include "core/vec.hpp"

namespace softbody {

using Mat3 = Eigen::Matrix3d;

// R = R_z(rz) R_y(ry) R_x(rx): a vector is turned about X first, then Y, then Z (all world axes). [0, 0, 0] gives the
// identity exactly (cos 0 = 1, sin 0 = 0).
inline Mat3 rotation_xyz_degrees(const Vec3& degrees) {
  const Vec3 radians = degrees * (std::numbers::pi / 180.0);
  return (Eigen::AngleAxisd(radians.z(), Vec3::UnitZ()) * Eigen::AngleAxisd(radians.y(), Vec3::UnitY()) *
          Eigen::AngleAxisd(radians.x(), Vec3::UnitX()))
      .toRotationMatrix();
}

}  // namespace softbody
