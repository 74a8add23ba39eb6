// The detailed mesh anchored on the proxy.
#include "setup/bind_skin.hpp"

#include "geometry/nearest_triangle.hpp"

namespace setup {

sim::Skin bind_skin(const std::vector<softbody::Vec3>& detailed_x, const std::vector<softbody::Triangle>& detailed_faces,
                    const std::vector<softbody::Vec3>& proxy_x, const std::vector<softbody::Triangle>& proxy_faces, int body) {
  const std::vector<int> nearest = geometry::nearest_triangles(mesh::TriMesh{proxy_x, proxy_faces}, detailed_x);
  std::vector<softbody::Vec3> normals;
  sim::vertex_normals(proxy_x, proxy_faces, normals);
  sim::Skin skin{body, detailed_faces, {}};
  skin.anchors.reserve(detailed_x.size());
  for (std::size_t i = 0; i < detailed_x.size(); ++i) {
    skin.anchors.push_back(sim::anchor_point(detailed_x[i], nearest[i], proxy_x, proxy_faces, normals));
  }
  return skin;
}

}  // namespace setup
