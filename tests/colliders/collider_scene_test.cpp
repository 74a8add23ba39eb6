// The "colliders" key: shapes read into their geometry, contact keys defaulting to the floor's, and clear errors
// naming the key for a shape's missing or foreign keys and for a mesh file that is not there.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "test_helpers.hpp"

namespace {

using testing_support::scene_refusal;

std::string with_colliders(const std::string& floor, const std::string& colliders) {
  return R"({ )" + floor + R"( "colliders": )" + colliders + R"(, "bodies": [ { "mesh": "icosphere:1" } ] })";
}

TEST(ColliderScene, ReadsShapesAndTakesTheFloorsContactKeys) {
  const scene::Scene s = testing_support::scene_from_text(
      with_colliders(R"("floor": {"contact": "smooth", "restitution": 0.2, "friction": 0.7, "time_constant": 0.003},)",
                     R"([{"shape": "box", "size": [1, 2, 4], "position": [0, 1, 0]},
          {"shape": "capsule", "radius": 0.1, "length": 0.6, "contact": "friction", "friction": 0.1},
          {"shape": "plane", "normal": [0, 0, 2]}])"));
  ASSERT_EQ(s.colliders.size(), 3u);
  const sim::Collider& box = s.colliders[0];
  EXPECT_EQ(box.geometry.shape, sim::ColliderShape::Box);
  EXPECT_EQ(box.geometry.half_size_m, softbody::Vec3(0.5, 1, 2));
  EXPECT_EQ(box.contact, sim::FloorContact::Smooth);  // the floor's
  EXPECT_EQ(box.material.restitution, 0.2);
  EXPECT_EQ(box.material.friction, 0.7);
  EXPECT_EQ(box.smooth.time_constant_s, 0.003);
  const sim::Collider& capsule = s.colliders[1];
  EXPECT_EQ(capsule.contact, sim::FloorContact::Friction);
  EXPECT_EQ(capsule.material.friction, 0.1);
  EXPECT_EQ(capsule.material.restitution, 0.2);
  EXPECT_EQ(capsule.geometry.half_length_m, 0.3);
  EXPECT_EQ(s.colliders[2].geometry.plane_normal, softbody::Vec3::UnitZ());  // normalised
}

TEST(ColliderScene, WithoutAFloorTheFloorsDefaultsApply) {
  const scene::Scene s = testing_support::scene_from_text(with_colliders("", R"([{"shape": "sphere", "radius": 1}])"));
  const sim::Floor defaults;
  EXPECT_EQ(s.colliders.at(0).contact, defaults.contact);
  EXPECT_EQ(s.colliders.at(0).material.restitution, defaults.material.restitution);
  EXPECT_EQ(s.colliders.at(0).smooth.smoothing_m, defaults.smooth.smoothing_m);
}

TEST(ColliderScene, RefusesMissingForeignAndUnsupportedKeys) {
  EXPECT_NE(scene_refusal(with_colliders("", R"([{"shape": "sphere"}])"))
                .find("colliders.0.radius: expected it for a sphere"),
            std::string::npos);
  EXPECT_NE(scene_refusal(with_colliders("", R"([{"shape": "box", "size": [1, 1, 1], "radius": 1}])"))
                .find("colliders.0.radius: a box takes no \"radius\""),
            std::string::npos);
  EXPECT_NE(scene_refusal(with_colliders("", R"([{"shape": "box", "size": [1, 0, 1]}])")).find("colliders.0.size"),
            std::string::npos);
  EXPECT_NE(
      scene_refusal(with_colliders("", R"([{"shape": "plane", "normal": [0, 0, 0]}])")).find("colliders.0.normal"),
      std::string::npos);
  EXPECT_NE(scene_refusal(with_colliders("", R"([{"shape": "mesh", "mesh": "no_such_file.obj"}])"))
                .find("colliders.0.mesh: mesh file"),
            std::string::npos);
  EXPECT_NE(
      scene_refusal(with_colliders("", R"([{"shape": "mesh"}])")).find("colliders.0.mesh: expected it for a mesh"),
      std::string::npos);
  EXPECT_NE(scene_refusal(with_colliders("", "[]")).find("colliders: expected an array of at least one collider"),
            std::string::npos);
  EXPECT_NE(scene_refusal(with_colliders("", R"([{"shape": "sphere", "radius": 1, "heigth": 2}])")).find("unknown key"),
            std::string::npos);
}

}  // namespace
