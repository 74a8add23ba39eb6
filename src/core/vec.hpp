// Vector types shared by every stage: double precision for physics.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <array>
#include <vector>

namespace softbody {

using Vec3 = Eigen::Vector3d;
using Triangle = std::array<int, 3>;  // vertex indices, counter-clockwise seen from outside
using Uv = std::array<double, 2>;     // texture coordinates (u, v) as the mesh file gives them
using CornerUvs = std::array<Uv, 3>;  // a triangle's texture coordinates at its corners, in its vertex order

}  // namespace softbody
