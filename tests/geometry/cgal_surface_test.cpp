// The TriMesh <-> CGAL Surface_mesh bridge keeps every vertex, every triangle and its orientation.
#include <gtest/gtest.h>

#include "geometry/cgal_surface.hpp"
#include "mesh/generators.hpp"

namespace {

TEST(CgalSurface, RoundTripKeepsVerticesTrianglesAndVolume) {
  const mesh::TriMesh sphere = mesh::icosphere(2);
  const geometry::SurfaceMesh surface = geometry::to_surface_mesh(sphere);
  EXPECT_EQ(surface.number_of_vertices(), sphere.vertices.size());
  EXPECT_EQ(surface.number_of_faces(), sphere.triangles.size());
  EXPECT_TRUE(CGAL::is_closed(surface));

  const mesh::TriMesh back = geometry::to_trimesh(surface);
  ASSERT_EQ(back.vertices.size(), sphere.vertices.size());
  ASSERT_EQ(back.triangles.size(), sphere.triangles.size());
  for (std::size_t i = 0; i < sphere.vertices.size(); ++i) EXPECT_EQ(back.vertices[i], sphere.vertices[i]);
  for (std::size_t t = 0; t < sphere.triangles.size(); ++t) {
    // A face may start at another corner; the cyclic order (the orientation) must be the same.
    const mesh::Triangle& a = sphere.triangles[t];
    const mesh::Triangle& b = back.triangles[t];
    const bool same_cycle =
        (a == b) || (a == mesh::Triangle{b[1], b[2], b[0]}) || (a == mesh::Triangle{b[2], b[0], b[1]});
    EXPECT_TRUE(same_cycle) << "triangle " << t;
  }
  EXPECT_DOUBLE_EQ(mesh::signed_volume(back), mesh::signed_volume(sphere));
  EXPECT_GT(mesh::signed_volume(back), 0.0);
}

}  // namespace
