// The same scene in Bullet 3.24: btDiscreteDynamicsWorld with its default dynamic AABB
// tree broad phase and sequential-impulse solver, the same iterations, friction and dt.
#include <btBulletDynamicsCommon.h>

#include <chrono>
#include <memory>
#include <vector>

#include "bench/rigidbody_granular/engines.hpp"

namespace cosim::bench {

namespace {

struct BulletWorld {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btDefaultMotionState>> motion_states;
  std::vector<std::unique_ptr<btRigidBody>> bodies;

  ~BulletWorld() {
    for (auto& b : bodies) world.removeRigidBody(b.get());
  }

  btRigidBody* add(btCollisionShape* shape, const btVector3& at, btScalar mass, btScalar friction) {
    btVector3 inertia(0, 0, 0);
    if (mass > 0) shape->calculateLocalInertia(mass, inertia);
    btTransform pose;
    pose.setIdentity();
    pose.setOrigin(at);
    motion_states.push_back(std::make_unique<btDefaultMotionState>(pose));
    btRigidBody::btRigidBodyConstructionInfo info(mass, motion_states.back().get(), shape, inertia);
    info.m_friction = friction;
    info.m_restitution = 0;
    bodies.push_back(std::make_unique<btRigidBody>(info));
    world.addRigidBody(bodies.back().get());
    return bodies.back().get();
  }
};

// Debian's Bullet is built in single precision.
btVector3 bt(const Eigen::Vector3d& v) {
  return {static_cast<btScalar>(v.x()), static_cast<btScalar>(v.y()), static_cast<btScalar>(v.z())};
}

}  // namespace

RunResult run_bullet(const PourScene& scene) {
  RunResult r{.engine = "bullet", .bodies = scene.positions.size(), .steps = scene.steps, .dt = scene.dt};
  r.kinetic_every = kinetic_interval(r.steps);
  // Bullet's tolerances are absolute and tuned for bodies of about a metre (its broad
  // phase fattens every box by 5 cm, which at r = 1 cm pairs each sphere with hundreds of
  // others), so it runs the scene in units where r = 1 m: lengths times k, g times k,
  // the same dt and hence the same motion. Equal masses: the mass unit does not matter.
  const double k = 1.0 / scene.radius;
  gContactBreakingThreshold = static_cast<btScalar>(k * scene.margin);
  const double heap_before = heap_in_use();
  auto w = std::make_unique<BulletWorld>();
  w->world.setGravity(bt(Eigen::Vector3d(0, 0, -9.81 * k)));
  w->world.getSolverInfo().m_numIterations = scene.iterations;

  const double wall = k * scene.half_width;
  const Eigen::Vector3d normals[] = {{0, 0, 1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  for (const Eigen::Vector3d& n : normals) {
    // btStaticPlaneShape keeps {n . x <= c} solid with the normal pointing into the box.
    w->shapes.push_back(std::make_unique<btStaticPlaneShape>(bt(n), static_cast<btScalar>(n.z() > 0 ? 0.0 : -wall)));
    w->add(w->shapes.back().get(), {0, 0, 0}, 0.0, static_cast<btScalar>(scene.friction));
  }
  w->shapes.push_back(std::make_unique<btSphereShape>(btScalar(1)));
  btCollisionShape* sphere = w->shapes.back().get();
  std::vector<btRigidBody*> spheres;
  for (std::size_t i = 0; i < scene.positions.size(); ++i) {
    btRigidBody* b = w->add(sphere, bt(k * scene.positions[i]), btScalar(1), static_cast<btScalar>(scene.friction));
    b->setLinearVelocity(bt(k * scene.velocities[i]));
    spheres.push_back(b);
  }

  const auto sample_energy = [&] {
    double e = 0;
    for (const btRigidBody* b : spheres) {
      const btVector3 v = b->getLinearVelocity() / static_cast<btScalar>(k);
      const btVector3& omega = b->getAngularVelocity();
      e += kinetic_energy(scene, {v.x(), v.y(), v.z()}, {omega.x(), omega.y(), omega.z()});
    }
    r.kinetic_energy.push_back(e);
  };

  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = cpu_time();
  sample_energy();
  for (int step = 1; step <= scene.steps; ++step) {
    w->world.stepSimulation(static_cast<btScalar>(scene.dt), 0);
    r.pairs_tested += w->dispatcher.getNumManifolds();
    if (step % r.kinetic_every == 0) sample_energy();
  }
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.cpu_seconds = cpu_time() - cpu_start;
  r.heap_bytes = heap_in_use() - heap_before;
  r.peak_rss_bytes = peak_rss();

  std::vector<Eigen::Vector3d> centres;
  for (btRigidBody* b : spheres) {
    const btVector3& p = b->getWorldTransform().getOrigin();
    centres.push_back(Eigen::Vector3d(p.x(), p.y(), p.z()) / k);
  }
  measure_pile(r, centres, scene.radius, scene.half_width);
  return r;
}

}  // namespace cosim::bench
