// Asperity's friction inside a Bullet world built the usual Bullet way (docs/engines.md): a box
// launched at 1 m/s up the ramps and another against the steep faces of a sawtooth ground
// stop after different distances, because the adapter's solver bounds each friction row by
// its own sense. Exits 1 if they do not.
#include <btBulletDynamicsCommon.h>
#include <asperity/engines/bullet.hpp>

#include <cmath>
#include <cstdio>

namespace {

// Distance (m) a 20 cm box slides in 2 s after being launched along x at `speed` (m/s).
double slide(float speed) {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher(&config);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
  world.setGravity(btVector3(0, 0, -9.81f));
  btBoxShape ground_shape(btVector3(1.5f, 0.5f, 0.05f)), box_shape(btVector3(0.1f, 0.1f, 0.1f));
  btRigidBody ground(0.0f, nullptr, &ground_shape);
  ground.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(0, 0, -0.05f)));
  btVector3 inertia;
  box_shape.calculateLocalInertia(8.0f, inertia);
  btRigidBody box(8.0f, nullptr, &box_shape, inertia);
  box.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(0, 0, 0.1f)));
  box.setLinearVelocity(btVector3(speed, 0, 0));
  world.addRigidBody(&ground);
  world.addRigidBody(&box);
  {
    // Asperity's friction: a sawtooth on the ground (ridges across x), the box flat.
    asperity::ContactFrictionSettings settings;  // mu0 0.2, world frame
    settings.provider = "cpu";                   // the patch sampler (default: cones)
    asperity::BulletFriction friction(world, settings);
    asperity::Surface sawtooth;
    sawtooth.source.generator = {"sawtooth", {{"period", "16"}, {"axis", "0"}}, 128, 1};
    sawtooth.gain = 4.0;
    sawtooth.texture_size = 0.08;
    friction.attach(&ground, "ground", sawtooth);
    friction.attach(&box, "box", asperity::Surface{});
    for (int i = 0; i < 200; ++i) world.stepSimulation(0.01f, 0);
  }
  world.removeRigidBody(&box);
  world.removeRigidBody(&ground);
  return std::abs(static_cast<double>(box.getWorldTransform().getOrigin().x()));
}

}  // namespace

int main() {
  const double up = slide(1.0f), against = slide(-1.0f);
  std::printf("up the ramps %.4f m, against the steep faces %.4f m\n", up, against);
  return up > 2.0 * against ? 0 : 1;
}
