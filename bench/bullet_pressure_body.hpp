// Bullet's pressure soft body (btSoftBody, kPR) on a static floor: the reference our step is measured against.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "core/vec.hpp"

namespace bench {

// What the Bullet world is built from: our body's triangles and rest positions, and our scene's numbers.
struct BulletBodySpec {
  std::vector<softbody::Vec3> vertices_m;
  std::vector<std::array<int, 3>> triangles;
  double mass_kg = 1.0;
  double pressure = 30.0;  // kPR
  double gravity_m_per_s2 = -9.81;
  double floor_height_m = 0.0;
  softbody::Vec3 velocity_m_per_s = softbody::Vec3::Zero();
  bool floor = true;            // false: no floor box in the world
  int position_iterations = 0;  // btSoftBody's piterations; 0 keeps Bullet's default (1)
};

// A btSoftRigidDynamicsWorld holding one soft body made with btSoftBodyHelpers::CreateFromTriMesh
// (pressure on) and a static floor box whose top face is the floor plane.
class BulletPressureBody {
 public:
  explicit BulletPressureBody(const BulletBodySpec& spec);
  ~BulletPressureBody();
  BulletPressureBody(const BulletPressureBody&) = delete;
  BulletPressureBody& operator=(const BulletPressureBody&) = delete;

  // One fixed step of dt seconds (stepSimulation(dt, 0, dt): exactly one internal step).
  void step(double dt);
  int vertex_count() const;
  // Height of the body's first node [m] (to check that the body moved and stayed finite).
  double first_node_height_m() const;
  // Every node's position [m] and mass [kg], in the order of BulletBodySpec::vertices_m.
  std::vector<softbody::Vec3> node_positions_m() const;
  std::vector<double> node_masses_kg() const;

 private:
  struct Parts;
  std::unique_ptr<Parts> parts_;
};

}  // namespace bench
