// Binding a body's detailed mesh to the proxy it is simulated on, once at setup.
#pragma once

#include <vector>

#include "core/vec.hpp"
#include "sim/model/skin.hpp"

namespace setup {

// The skin of the detailed surface (vertices `detailed_x`, triangles `detailed_faces`, placed) on proxy body
// `body` (vertices `proxy_x`, triangles `proxy_faces`, placed): each detailed vertex anchored on its nearest
// proxy triangle (geometry::nearest_triangles, an AABB tree). On the proxy at `proxy_x` the skin gives back
// `detailed_x` to round-off.
sim::Skin bind_skin(const std::vector<softbody::Vec3>& detailed_x,
                    const std::vector<softbody::Triangle>& detailed_faces, const std::vector<softbody::Vec3>& proxy_x,
                    const std::vector<softbody::Triangle>& proxy_faces, int body);

}  // namespace setup
