// Vector types shared by every stage: double precision for physics.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <array>
#include <vector>

namespace softbody {

using Vec3 = Eigen::Vector3d;
using Triangle = std::array<int, 3>;  // vertex indices, counter-clockwise seen from outside

}  // namespace softbody
