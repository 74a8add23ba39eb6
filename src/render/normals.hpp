// Smooth vertex normals of a deforming surface, recomputed from its current positions.
#pragma once

#include <span>
#include <vector>

#include <glm/vec3.hpp>

namespace render {

// Area-weighted vertex normals: each triangle adds its area vector ½ (b − a) × (c − a) to its three
// corners (so bigger faces count more), and each sum is normalised. `normals` is resized to fit.
// A vertex whose faces cancel (degenerate) gets (0, 1, 0) rather than NaN.
void area_weighted_normals(std::span<const glm::vec3> positions, std::span<const glm::uvec3> triangles,
                           std::vector<glm::vec3>& normals);

}  // namespace render
