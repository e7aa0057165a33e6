// BulletScene (asperity/engines/bullet_scene.hpp): an Asperity scene's bodies as Bullet rigid
// bodies, with Asperity's friction attached or Bullet's own.
#include "asperity/engines/bullet_scene.hpp"

#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "asperity/error.hpp"
#include "collision/bullet_shapes.hpp"
#include "scene/scene_resources.hpp"

namespace asperity {

namespace {

using collision_detail::toBt;

// Throws unless the scene holds bodies only.
void checkSupported(const SceneDesc& scene) {
  const std::string file = scene.source_file.empty() ? "scene" : scene.source_file;
  auto fail = [&](const std::string& what) {
    throw Error(file + ": " + what + " are not supported in a Bullet scene (bodies only)");
  };
  if (!scene.joints.empty()) fail("joints");
  if (!scene.springs.empty()) fail("springs");
  if (!scene.loads.empty()) fail("loads");
  if (!scene.meshes.empty()) fail("meshes read from files");
}

// The Bullet rigid body of one Asperity body and the shapes it points into.
struct BulletBody {
  std::vector<collision_detail::BulletShape> shapes;
  std::unique_ptr<btCompoundShape> compound;
  std::unique_ptr<btRigidBody> body;
};

// The body's collision shape: Bullet's shape of each of its shapes (owned by `out`).
btCollisionShape* collisionShape(const Body& body, BulletBody& out) {
  for (const Shape& s : body.shapes)
    out.shapes.push_back(collision_detail::makeBulletShape(s, body.type));
  // One shape in the centre-of-mass frame as it is; otherwise a compound of them.
  const Transform& local = body.shapes[0].local;
  if (body.shapes.size() == 1 && local.position.isZero(0.0) &&
      local.rotation.isApprox(Quat::Identity(), 0.0))
    return out.shapes[0].shape.get();
  out.compound = std::make_unique<btCompoundShape>();
  for (size_t i = 0; i < body.shapes.size(); ++i)
    out.compound->addChildShape(toBt(body.shapes[i].local), out.shapes[i].shape.get());
  return out.compound.get();
}

// Mass, inertia, pose and velocities as a World's body has them (makeBody).
BulletBody makeBulletBody(const Body& body, btScalar friction) {
  BulletBody out;
  btCollisionShape* shape = collisionShape(body, out);
  const bool dynamic = body.isDynamic();
  const Vec3& inv_inertia = body.inverse_inertia_local;
  auto inverse = [&](double x) {
    return static_cast<btScalar>(dynamic && x > 0.0 ? 1.0 / x : 0.0);
  };
  btRigidBody::btRigidBodyConstructionInfo info(
      inverse(body.inverse_mass), nullptr, shape,
      btVector3(inverse(inv_inertia.x()), inverse(inv_inertia.y()), inverse(inv_inertia.z())));
  info.m_friction = friction;
  info.m_startWorldTransform = toBt(body.pose);
  out.body = std::make_unique<btRigidBody>(info);
  if (body.type == BodyType::Kinematic)
    out.body->setCollisionFlags(out.body->getCollisionFlags() |
                                btCollisionObject::CF_KINEMATIC_OBJECT);
  out.body->setLinearVelocity(toBt(body.linear_velocity));
  out.body->setAngularVelocity(toBt(body.angular_velocity));
  out.body->setActivationState(DISABLE_DEACTIVATION);
  return out;
}

}  // namespace

ContactFrictionSettings contactFrictionSettings(const SceneDesc& scene) {
  const WorldSettings& w = scene.settings;
  ContactFrictionSettings s;
  s.friction = w.friction;
  s.provider = scene.friction_provider;
  s.frame = w.frame;
  s.threads = w.threads;
  return s;
}

struct BulletScene::Impl {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};
  std::vector<BulletBody> bodies;
  std::map<std::string, btCollisionObject*> objects;
  std::map<std::string, btRigidBody*, std::less<>> by_name;
  std::unique_ptr<BulletFriction> friction;
  double dt = 0.01;
  int steps = 0;
  Diagnostics diagnostics;  // warnings found while the scene's maps loaded

  ~Impl() {
    friction.reset();
    for (BulletBody& b : bodies) world.removeRigidBody(b.body.get());
  }
  void addBodies(const SceneDesc& scene, btScalar body_friction);
};

void BulletScene::Impl::addBodies(const SceneDesc& scene, btScalar body_friction) {
  scene::ResourceCache cache(scene.base_dir);
  const std::string file = scene.source_file.empty() ? "scene" : scene.source_file;
  for (size_t i = 0; i < scene.bodies.size(); ++i) {
    BodyDesc desc = scene.bodies[i];
    // A body without shapes (a static anchor) touches nothing.
    if (desc.shapes.empty()) continue;
    try {
      // Surfaces resolved as instantiate() resolves them (paths relative to the scene).
      for (Shape& s : desc.shapes) {
        s.surface.normal_map = cache.normalMap(s.surface, diagnostics);
        s.surface.mask = cache.mask(s.surface.source.mask_file);
      }
      const Body body = makeBody(desc);
      bodies.push_back(makeBulletBody(body, body_friction));
      btRigidBody* rigid = bodies.back().body.get();
      world.addRigidBody(rigid);
      objects[desc.name] = rigid;
      by_name[desc.name] = rigid;
      // The body's shapes as a World holds them: relative to its centre of mass.
      if (friction) friction->attach(rigid, ObjectDesc{desc.name, body.shapes, body.frame_axis});
    } catch (const Error& e) {
      throw Error(file + ": /bodies/" + std::to_string(i) + ": " + e.what());
    }
  }
}

BulletScene::BulletScene(const SceneDesc& scene, const BulletSceneOptions& options)
    : impl_(std::make_unique<Impl>()) {
  checkSupported(scene);
  Impl& m = *impl_;
  const WorldSettings& w = scene.settings;
  m.dt = w.dt;
  m.world.setGravity(toBt(w.gravity));
  m.world.getSolverInfo().m_numIterations = w.iterations;
  // Asperity's friction, or mu0 from Bullet's product of the two objects' frictions.
  if (options.asperity_friction) {
    ContactFrictionSettings settings = contactFrictionSettings(scene);
    if (options.frame_mode) settings.frame.mode = *options.frame_mode;
    m.friction = std::make_unique<BulletFriction>(m.world, settings);
  } else if (options.two_friction_directions) {
    m.world.getSolverInfo().m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
  }
  m.addBodies(scene, static_cast<btScalar>(std::sqrt(w.friction.mu0)));
}

BulletScene::~BulletScene() = default;

void BulletScene::step() {
  impl_->world.stepSimulation(static_cast<btScalar>(impl_->dt), 0);
  ++impl_->steps;
}

double BulletScene::time() const {
  return impl_->steps * impl_->dt;
}

btDiscreteDynamicsWorld& BulletScene::world() {
  return impl_->world;
}

btRigidBody& BulletScene::body(std::string_view name) {
  const auto it = impl_->by_name.find(name);
  if (it == impl_->by_name.end())
    throw Error("bullet scene: no body named '" + std::string(name) + "'");
  return *it->second;
}

Vec3 BulletScene::position(std::string_view name) {
  return collision_detail::fromBt(body(name).getWorldTransform().getOrigin());
}

const std::map<std::string, btCollisionObject*>& BulletScene::objects() const {
  return impl_->objects;
}

BulletFriction* BulletScene::friction() {
  return impl_->friction.get();
}

namespace {

// The dynamic bodies' names in scene order.
std::vector<std::string> dynamicBodies(const SceneDesc& scene) {
  std::vector<std::string> names;
  for (const BodyDesc& b : scene.bodies)
    if (b.type == BodyType::Dynamic) names.push_back(b.name);
  return names;
}

// A displacement's length across gravity (in the plane gravity is normal to).
double across(const Vec3& moved, const Vec3& gravity) {
  const double g = gravity.norm();
  if (!(g > 0.0)) return moved.norm();
  const Vec3 down = gravity / g;
  return (moved - moved.dot(down) * down).norm();
}

}  // namespace

std::vector<std::pair<std::string, double>> slideDistances(const SceneDesc& scene,
                                                           SceneEngine engine, double seconds,
                                                           BulletSceneOptions options) {
  const std::vector<std::string> names = dynamicBodies(scene);
  const auto steps = static_cast<int64_t>(std::llround(seconds / scene.settings.dt));
  std::vector<Vec3> start, end;
  // Asperity's own World, instantiated as `asperity run` does.
  if (engine == SceneEngine::Asperity) {
    auto world = instantiate(scene);
    auto at = [&](const std::string& n) { return world->body(world->findBody(n)).pose.position; };
    for (const std::string& n : names) start.push_back(at(n));
    for (int64_t i = 0; i < steps; ++i) world->step();
    for (const std::string& n : names) end.push_back(at(n));
  } else {
    options.asperity_friction = engine == SceneEngine::Bullet;
    BulletScene bullet(scene, options);
    for (const std::string& n : names) start.push_back(bullet.position(n));
    for (int64_t i = 0; i < steps; ++i) bullet.step();
    for (const std::string& n : names) end.push_back(bullet.position(n));
  }
  std::vector<std::pair<std::string, double>> out;
  for (size_t i = 0; i < names.size(); ++i)
    out.emplace_back(names[i], across(end[i] - start[i], scene.settings.gravity));
  return out;
}

}  // namespace asperity
