// No vertex inside a mesh collider deeper than its contact model allows, at any frame, for every integrator at the
// step "auto" chooses, on two gallery scenes: the ball bouncing down the stairs (scenes/stairs.json: the top tread,
// the next one's edge and the tread below, in 1.2 s) and the ball pushed through the ring narrower than itself
// (scenes/ring.json: through the hole in 0.6 s). Both balls are coarser than the gallery's, to keep the test fast.
// Inside is told by the generalised winding number over the collider's triangles (both meshes are closed); the depth
// of a vertex inside is its distance to the nearest triangle. The impulse models put every vertex back on the surface
// after each step: none inside. The smooth contact lets a vertex sink until its spring m/τ² has stopped it: about
// v τ for an impact at v, plus the smoothing depth δ over which the spring ramps up, with v bounded by the energy the
// scene starts with (its speed and its fall to the lowest surface it reaches).
// That bound is one vertex's: it holds while a vertex's contact spring is not much softer than the body's springs
// around it. The stairs' firm ball as an icosphere:2 (162 vertices of 3 g, contact springs of 770 N/m against some
// 15,000 N/m of edge springs) lands nearly rigid on a few contact springs and sinks up to 23 mm at the default τ
// (docs/notes/2026-12-05-colliders-loose-ends.md); as an icosphere:1 (42 vertices of 12 g) it stays within the bound.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scene/scene_json.hpp"
#include "sim/contact/body_collision.hpp"
#include "sim/contact/collider_mesh.hpp"
#include "sim/step/world.hpp"
#include "test_helpers.hpp"

namespace {

using softbody::Vec3;

constexpr double kGravity_m_per_s2 = 9.81;
constexpr double kTimeConstant_s = 0.002;  // the smooth contact's τ (the default)
constexpr double kSmoothing_m = 0.002;     // its δ (the default)

struct GalleryCase {
  const char* scene;            // under scenes/
  const char* ball;             // the body's mesh, coarser than the gallery's
  double duration_s;            // long enough for the contacts named above
  double impact_speed_m_per_s;  // the fastest the ball can meet the collider: √(v0² + 2 g Δh)
};

// The stairs: thrown at (0.9, 0.5) m/s from a lowest point at 1.49 m, onto the third tread (0.5 m) by 1.2 s.
// The ring: thrown down at 6 m/s from a lowest point at 1.75 m onto the ring's top at about 1.3 m.
const GalleryCase kStairs{"stairs", "icosphere:1", 1.2,
                          std::sqrt(0.9 * 0.9 + 0.5 * 0.5 + 2.0 * kGravity_m_per_s2 * (1.49 - 0.5))};
const GalleryCase kRing{"ring", "icosphere:2", 0.6, std::sqrt(6.0 * 6.0 + 2.0 * kGravity_m_per_s2 * (1.75 - 1.3))};

std::string file_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The gallery scene with a coarser ball, the test's duration, the integrator at its automatic step and `contact` on
// the collider; the collider's mesh file is named from tests/ (where the test's scene text is read as if it were).
std::string gallery_scene(const GalleryCase& gallery, const std::string& contact,
                          const sim::IntegratorInfo& integrator) {
  const std::filesystem::path file =
      std::filesystem::path(SOFTBODY_SOURCE_DIR) / "scenes" / (std::string(gallery.scene) + ".json");
  nlohmann::json scene = scene::parse_scene_text(file_text(file.string()), file);
  scene["duration"] = gallery.duration_s;
  scene["solver"] = {{"integrator", std::string(integrator.name)}};
  scene["solver"][integrator.frame_substeps ? "substeps" : "dt"] = "auto";
  scene["bodies"][0]["mesh"] = gallery.ball;
  nlohmann::json& collider = scene["colliders"][0];
  const std::string mesh = collider["mesh"];
  if (mesh.find(':') == std::string::npos) collider["mesh"] = "../scenes/" + mesh;
  collider["contact"] = contact;
  return scene.dump();
}

// The collider's triangles in the world.
std::vector<Vec3> world_vertices(const sim::ColliderGeometry& collider) {
  std::vector<Vec3> world;
  for (const Vec3& q : collider.mesh->vertices_m) world.push_back(collider.position_m + collider.rotation * q);
  return world;
}

// The deepest any vertex is inside the (closed) mesh collider at any frame [m].
double deepest_at_frames(const std::string& text) {
  double deepest = 0.0;
  testing_support::run_scene_frames(text, [&](double, const sim::World& world) {
    const sim::ColliderGeometry& collider = world.model.colliders.at(0).geometry;
    EXPECT_TRUE(collider.mesh->closed);
    const std::vector<Vec3> corners = world_vertices(collider);
    for (const Vec3& x : world.state.x) {
      if (sim::winding_number(corners, collider.mesh->triangles, x) < 0.5) continue;
      deepest = std::max(deepest, std::abs(sim::nearest_surface(collider, x).distance_m));
    }
  });
  return deepest;
}

void expect_no_vertex_inside(const GalleryCase& gallery, const std::string& contact) {
  for (const sim::IntegratorInfo& integrator : sim::kIntegrators) {
    const double deepest = deepest_at_frames(gallery_scene(gallery, contact, integrator));
    EXPECT_LT(deepest, 1e-12) << gallery.scene << ", " << contact << ", " << integrator.name;
  }
}

void expect_smooth_contact_within_its_skin(const GalleryCase& gallery) {
  const double skin = gallery.impact_speed_m_per_s * kTimeConstant_s + kSmoothing_m;  // v τ + δ
  for (const sim::IntegratorInfo& integrator : sim::kIntegrators) {
    const double deepest = deepest_at_frames(gallery_scene(gallery, "smooth", integrator));
    std::printf("%s, smooth, %-10s %.2f mm (skin %.2f mm)\n", gallery.scene, std::string(integrator.name).c_str(),
                1e3 * deepest, 1e3 * skin);
    EXPECT_LT(deepest, skin) << gallery.scene << ", " << integrator.name;
  }
}

TEST(GalleryColliderDepth, StairsPaperContactLeavesNoVertexInside) { expect_no_vertex_inside(kStairs, "paper"); }

TEST(GalleryColliderDepth, StairsFrictionContactLeavesNoVertexInside) { expect_no_vertex_inside(kStairs, "friction"); }

TEST(GalleryColliderDepth, StairsSmoothContactStaysWithinItsSkin) { expect_smooth_contact_within_its_skin(kStairs); }

TEST(GalleryColliderDepth, RingImpulseContactsLeaveNoVertexInside) {
  expect_no_vertex_inside(kRing, "paper");
  expect_no_vertex_inside(kRing, "friction");
}

TEST(GalleryColliderDepth, RingSmoothContactStaysWithinItsSkin) { expect_smooth_contact_within_its_skin(kRing); }

}  // namespace
