// Builds and steps the Bullet reference world. Bullet is linked into the benchmark only, never the core.
#include "bullet_pressure_body.hpp"

#include <BulletSoftBody/btSoftBodyHelpers.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <btBulletDynamicsCommon.h>

namespace bench {

struct BulletPressureBody::Parts {
  btSoftBodyRigidBodyCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btSoftRigidDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
  btBoxShape floor_shape{btVector3(50, 1, 50)};
  std::unique_ptr<btDefaultMotionState> floor_motion;
  std::unique_ptr<btRigidBody> floor;
  btSoftBody* body = nullptr;  // owned here, removed from the world before deletion
  bool floor_added = true;
};

BulletPressureBody::BulletPressureBody(const BulletBodySpec& spec) : parts_(std::make_unique<Parts>()) {
  Parts& p = *parts_;
  const auto g = static_cast<btScalar>(spec.gravity_m_per_s2);
  p.world.setGravity(btVector3(0, g, 0));
  btSoftBodyWorldInfo& info = p.world.getWorldInfo();
  info.m_gravity.setValue(0, g, 0);
  info.m_sparsesdf.Initialize();

  btTransform floor_pose;
  floor_pose.setIdentity();
  floor_pose.setOrigin(btVector3(0, static_cast<btScalar>(spec.floor_height_m - 1.0), 0));
  p.floor_motion = std::make_unique<btDefaultMotionState>(floor_pose);
  p.floor =
      std::make_unique<btRigidBody>(btRigidBody::btRigidBodyConstructionInfo(0, p.floor_motion.get(), &p.floor_shape));
  if (spec.floor) p.world.addRigidBody(p.floor.get());
  p.floor_added = spec.floor;

  std::vector<btScalar> xyz;
  for (const softbody::Vec3& x : spec.vertices_m) {
    for (int k = 0; k < 3; ++k) xyz.push_back(static_cast<btScalar>(x[k]));
  }
  std::vector<int> indices;
  for (const auto& t : spec.triangles) indices.insert(indices.end(), t.begin(), t.end());
  p.body =
      btSoftBodyHelpers::CreateFromTriMesh(info, xyz.data(), indices.data(), static_cast<int>(spec.triangles.size()));
  p.body->m_cfg.kPR = static_cast<btScalar>(spec.pressure);
  p.body->m_cfg.kDP = static_cast<btScalar>(0.001);
  p.body->m_cfg.collisions = btSoftBody::fCollision::SDF_RS;
  if (spec.position_iterations > 0) p.body->m_cfg.piterations = spec.position_iterations;
  p.body->setTotalMass(static_cast<btScalar>(spec.mass_kg), true);
  p.body->setVelocity(btVector3(static_cast<btScalar>(spec.velocity_m_per_s.x()),
                                static_cast<btScalar>(spec.velocity_m_per_s.y()),
                                static_cast<btScalar>(spec.velocity_m_per_s.z())));
  p.world.addSoftBody(p.body);
}

BulletPressureBody::~BulletPressureBody() {
  parts_->world.removeSoftBody(parts_->body);
  delete parts_->body;
  if (parts_->floor_added) parts_->world.removeRigidBody(parts_->floor.get());
}

void BulletPressureBody::step(double dt) {
  const auto h = static_cast<btScalar>(dt);
  parts_->world.stepSimulation(h, 0, h);
}

int BulletPressureBody::vertex_count() const { return parts_->body->m_nodes.size(); }

double BulletPressureBody::first_node_height_m() const { return parts_->body->m_nodes[0].m_x.y(); }

std::vector<softbody::Vec3> BulletPressureBody::node_positions_m() const {
  std::vector<softbody::Vec3> x;
  x.reserve(static_cast<std::size_t>(vertex_count()));
  for (int i = 0; i < vertex_count(); ++i) {
    const btVector3& p = parts_->body->m_nodes[i].m_x;
    x.emplace_back(p.x(), p.y(), p.z());
  }
  return x;
}

std::vector<double> BulletPressureBody::node_masses_kg() const {
  std::vector<double> masses;
  masses.reserve(static_cast<std::size_t>(vertex_count()));
  for (int i = 0; i < vertex_count(); ++i) masses.push_back(1.0 / static_cast<double>(parts_->body->m_nodes[i].m_im));
  return masses;
}

}  // namespace bench
