// The 3×3 Jacobian blocks of one spring-damper, for the implicit integrators.
#pragma once

#include <Eigen/Core>

#include "core/vec.hpp"

namespace sim {

using softbody::Vec3;

// −∂f_i/∂x_i of a Hooke spring f_i = −k (|d| − L0) d̂, d = x_i − x_j [N/m]:
//   K = k [ d̂d̂ᵀ + max(0, 1 − L0/|d|) (I − d̂d̂ᵀ) ]
// (Baraff & Witkin 1998, Sect. 5; the max(0, ·) is the definiteness fix for compressed springs, which
// keeps K positive semi-definite). ∂f_i/∂x_j = +K, ∂f_j/∂x_j = −K. Zero for a zero-length spring.
Eigen::Matrix3d spring_stiffness_block(const Vec3& d, double rest_length_m, double k);

// The same without the clamp: the exact Hessian block of ½ k (|d| − L0)², indefinite for a compressed spring.
Eigen::Matrix3d spring_hessian_block(const Vec3& d, double rest_length_m, double k);

// −∂f_i/∂v_i of a damper along the spring, f_i = −c ((v_i − v_j)·d̂) d̂: C = c d̂d̂ᵀ [N·s/m].
Eigen::Matrix3d damper_block(const Vec3& d, double c);

}  // namespace sim
