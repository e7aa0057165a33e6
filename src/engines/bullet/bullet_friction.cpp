// BulletFriction (asperity/engines/bullet.hpp): Bullet objects registered with ContactFriction,
// and once per step (the solver's prepareSolve) the dispatcher's contact points handed over and
// their frames and bounds written back.
#include "asperity/engines/bullet.hpp"

#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <unordered_map>
#include <utility>

#include "asperity/error.hpp"
#include "collision/bullet_shapes.hpp"
#include "engines/bullet/friction_solver.hpp"
#include "math/stopwatch.hpp"

namespace asperity {

namespace {

using collision_detail::fromBt;
using collision_detail::toBt;

constexpr int kSolverModes =
    SOLVER_ENABLE_FRICTION_DIRECTION_CACHING | SOLVER_USE_2_FRICTION_DIRECTIONS;

// An attached object: its id and how many children its compound shape has (0: not one).
struct Attached {
  ObjectId id = kNoObject;
  int children = 0;
};

int childCount(const btCollisionObject& object) {
  const btCollisionShape* shape = object.getCollisionShape();
  if (shape == nullptr || shape->getShapeType() != COMPOUND_SHAPE_PROXYTYPE) return 0;
  return static_cast<const btCompoundShape*>(shape)->getNumChildShapes();
}

// The object's pose (a rigid body's centre-of-mass frame) and velocities.
ObjectState stateOf(const btCollisionObject& object) {
  const btTransform& t = object.getWorldTransform();
  const btQuaternion q = t.getRotation();
  ObjectState s;
  s.pose.position = fromBt(t.getOrigin());
  s.pose.rotation = Quat(static_cast<double>(q.w()), static_cast<double>(q.x()),
                         static_cast<double>(q.y()), static_cast<double>(q.z()));
  if (const btRigidBody* body = btRigidBody::upcast(&object)) {
    s.linear_velocity = fromBt(body->getLinearVelocity());
    s.angular_velocity = fromBt(body->getAngularVelocity());
  } else {
    s.linear_velocity = fromBt(object.getInterpolationLinearVelocity());
    s.angular_velocity = fromBt(object.getInterpolationAngularVelocity());
  }
  return s;
}

// The shape of a contact side: a compound's child (Bullet's m_index of that side), else 0.
int shapeIndex(const Attached& side, int bullet_index) {
  return side.children > 0 && bullet_index >= 0 && bullet_index < side.children ? bullet_index : 0;
}

}  // namespace

struct BulletFriction::Impl {
  btDiscreteDynamicsWorld& world;
  btConstraintSolver* previous_solver = nullptr;
  int previous_mode = 0;
  ContactFriction friction;
  bullet_detail::PointBounds bounds;
  std::unique_ptr<bullet_detail::FrictionSolver> solver;
  std::unordered_map<const btCollisionObject*, Attached> objects;
  std::vector<const btCollisionObject*> by_id;  // ObjectId -> object (null once detached)
  std::vector<EngineContact> contacts;
  // Parallel to contacts: the manifold point, and whether body 0 is B there.
  struct Point {
    btManifoldPoint* point;
    bool swapped;
  };
  std::vector<Point> points;
  std::span<const ContactFrictionResult> results;
  double last_ms = 0.0;

  Impl(btDiscreteDynamicsWorld& w, ContactFrictionSettings settings)
      : world(w), friction(std::move(settings)) {}

  ObjectId add(btCollisionObject* object, const ObjectDesc& desc);
  void update();
  void gather();
  void gatherManifold(const btPersistentManifold& manifold, const Attached& body0,
                      const Attached& body1, bool swap);
  void writeBack();
  // Clears the frames set on the points of `object` (null: of every attached object).
  void clearFrames(const btCollisionObject* object);
};

ObjectId BulletFriction::Impl::add(btCollisionObject* object, const ObjectDesc& desc) {
  const std::string what = "bullet object '" + desc.name + "'";
  if (object == nullptr) throw Error(what + ": the object is null");
  if (objects.count(object)) throw Error(what + ": the object is attached already");
  // One shape for the whole object, or one per child of its compound, in child order.
  const int children = childCount(*object);
  const size_t count = desc.shapes.size();
  if (count != 1 && (children == 0 || count != static_cast<size_t>(children)))
    throw Error(what + ": has " + std::to_string(count) + " shapes; give 1" +
                (children > 0 ? " or " + std::to_string(children) + " (its compound's children)"
                              : std::string()));
  const ObjectId id = friction.addObject(desc);
  objects.emplace(object, Attached{id, count == 1 ? 0 : children});
  by_id.resize(std::max<size_t>(by_id.size(), id + 1), nullptr);
  by_id[id] = object;
  return id;
}

void BulletFriction::Impl::update() {
  Stopwatch clock;
  gather();
  // Every attached object's pose and velocities, then the batch (ContactFriction's stages).
  for (size_t id = 0; id < by_id.size(); ++id)
    if (by_id[id] != nullptr) friction.setState(static_cast<ObjectId>(id), stateOf(*by_id[id]));
  results = friction.compute(contacts);
  writeBack();
  last_ms = clock.total();
}

void BulletFriction::Impl::gather() {
  contacts.clear();
  points.clear();
  btDispatcher& dispatcher = *world.getDispatcher();
  // The manifolds Bullet will solve whose two objects are attached, in the dispatcher's order.
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold& manifold = *dispatcher.getManifoldByIndexInternal(m);
    const btCollisionObject* body0 = manifold.getBody0();
    const btCollisionObject* body1 = manifold.getBody1();
    if (body0->isStaticOrKinematicObject() && body1->isStaticOrKinematicObject()) continue;
    if (!body0->isActive() && !body1->isActive()) continue;
    const auto a = objects.find(body0), b = objects.find(body1);
    if (a == objects.end() || b == objects.end()) continue;
    // Asperity's A/B rule: a lone dynamic object is A (the patch sampler rasterises A whole
    // and B only where A lies, so a small A is cheaper than a large ground).
    const bool swap = body0->isStaticOrKinematicObject();
    gatherManifold(manifold, a->second, b->second, swap);
  }
}

void BulletFriction::Impl::gatherManifold(const btPersistentManifold& manifold,
                                          const Attached& body0, const Attached& body1, bool swap) {
  for (int j = 0; j < manifold.getNumContacts(); ++j) {
    // The points Bullet makes rows of (convertContact's test).
    auto& point = const_cast<btManifoldPoint&>(manifold.getContactPoint(j));
    if (point.getDistance() > manifold.getContactProcessingThreshold()) continue;
    // m_normalWorldOnB points from body 1 toward body 0: body 0 is A unless swapped (SPEC 1).
    EngineContact c;
    c.object_a = swap ? body1.id : body0.id;
    c.object_b = swap ? body0.id : body1.id;
    c.shape_a = swap ? shapeIndex(body1, point.m_index1) : shapeIndex(body0, point.m_index0);
    c.shape_b = swap ? shapeIndex(body0, point.m_index0) : shapeIndex(body1, point.m_index1);
    c.point = 0.5 * (fromBt(point.getPositionWorldOnA()) + fromBt(point.getPositionWorldOnB()));
    c.normal = (swap ? -1.0 : 1.0) * fromBt(point.m_normalWorldOnB).normalized();
    c.depth = std::max(0.0, -static_cast<double>(point.getDistance()));
    contacts.push_back(c);
    points.push_back({&point, swap});
  }
}

void BulletFriction::Impl::writeBack() {
  bounds.clear();
  bounds.reserve(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    btManifoldPoint& point = *points[i].point;
    const ContactFrictionResult& r = results[i];
    // The frame Bullet's rows follow (kept: friction direction caching).
    point.m_lateralFrictionDir1 = toBt(r.t);
    point.m_lateralFrictionDir2 = toBt(r.b);
    point.m_contactPointFlags |= BT_CONTACT_FLAG_LATERAL_FRICTION_INITIALIZED;
    // Bullet's rows push body 0: when it is B, its friction along +d is A's along -d.
    const BoxLimit& box = r.bounds;
    bounds[&point] =
        points[i].swapped ? BoxLimit{box.mu_neg_t, box.mu_neg_b, box.mu_pos_t, box.mu_pos_b} : box;
    // Bullet's own coefficient, read by nothing here: the largest bound, for its tools.
    point.m_combinedFriction =
        static_cast<btScalar>(std::max({box.mu_pos_t, box.mu_pos_b, box.mu_neg_t, box.mu_neg_b}));
  }
}

void BulletFriction::Impl::clearFrames(const btCollisionObject* object) {
  btDispatcher& dispatcher = *world.getDispatcher();
  auto mine = [&](const btCollisionObject* o) {
    return object != nullptr ? o == object : objects.count(o) > 0;
  };
  // Bullet would keep reusing the frames set here (friction direction caching).
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    btPersistentManifold& manifold = *dispatcher.getManifoldByIndexInternal(m);
    if (!mine(manifold.getBody0()) && !mine(manifold.getBody1())) continue;
    for (int j = 0; j < manifold.getNumContacts(); ++j)
      manifold.getContactPoint(j).m_contactPointFlags &=
          ~BT_CONTACT_FLAG_LATERAL_FRICTION_INITIALIZED;
  }
}

BulletFriction::BulletFriction(btDiscreteDynamicsWorld& world, ContactFrictionSettings settings)
    : impl_(std::make_unique<Impl>(world, std::move(settings))) {
  Impl& m = *impl_;
  m.solver = std::make_unique<bullet_detail::FrictionSolver>([&m] { m.update(); }, m.bounds);
  // Installed in the world; its previous solver and modes come back with the destructor.
  m.previous_solver = world.getConstraintSolver();
  m.previous_mode = world.getSolverInfo().m_solverMode;
  world.setConstraintSolver(m.solver.get());
  world.getSolverInfo().m_solverMode |= kSolverModes;
}

BulletFriction::~BulletFriction() {
  Impl& m = *impl_;
  m.world.setConstraintSolver(m.previous_solver);
  m.world.getSolverInfo().m_solverMode = m.previous_mode;
  m.clearFrames(nullptr);
}

ObjectId BulletFriction::attach(btCollisionObject* object, const ObjectDesc& desc) {
  return impl_->add(object, desc);
}

ObjectId BulletFriction::attach(btCollisionObject* object, const std::string& name,
                                const Surface& surface) {
  if (object == nullptr || object->getCollisionShape() == nullptr)
    throw Error("bullet object '" + name + "': the object or its collision shape is null");
  ObjectDesc desc;
  desc.name = name;
  desc.shapes =
      shapesOfBulletShape(*object->getCollisionShape(), surface, "bullet object '" + name + "'");
  resolveSurfaces(desc.shapes, impl_->friction.diagnostics());
  return impl_->add(object, desc);
}

void BulletFriction::attach(const EngineSurfaces& file,
                            const std::map<std::string, btCollisionObject*>& objects) {
  // Every name first, so that a bad file attaches nothing; the error lists the known ones.
  std::string known;
  for (const auto& entry : objects) known += (known.empty() ? "\"" : ", \"") + entry.first + "\"";
  for (const EngineSurface& e : file.surfaces)
    if (!objects.count(e.name))
      file.failAt(e.name, "unknown object \"" + e.name + "\" (" +
                              (known.empty() ? std::string("the engine named no objects") : known) +
                              ")");
  for (const EngineSurface& e : file.surfaces) attach(objects.at(e.name), e.name, e.surface);
}

void BulletFriction::detach(btCollisionObject* object) {
  const auto it = impl_->objects.find(object);
  if (it == impl_->objects.end()) return;
  impl_->by_id[it->second.id] = nullptr;
  impl_->objects.erase(it);
  impl_->clearFrames(object);
}

std::span<const EngineContact> BulletFriction::lastContacts() const {
  return impl_->contacts;
}
std::span<const ContactFrictionResult> BulletFriction::lastResults() const {
  return impl_->results;
}
double BulletFriction::lastUpdateMs() const {
  return impl_->last_ms;
}
ContactFriction& BulletFriction::contactFriction() {
  return impl_->friction;
}

}  // namespace asperity
