// The solver that BulletFriction installs: each friction row is bounded by the coefficient of
// its own sense (SPEC 4, box), in every solver mode Bullet offers, and joints are solved as
// Bullet solves them. Oracle for friction: a thin slab sliding on the sawtooth loses mu g dt of
// speed in one step, with mu the bound of the sense its friction acts in (the slab is too flat
// to tip: its half height is a tenth of its half width).
#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "asperity/engines/bullet_scene.hpp"
#include "engines/bullet/bullet_test_scenes.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

constexpr double kG = 9.81;

// The bound of the friction on `object` along world +x at a contact (its frame is the world's:
// t = x), whichever side of the contact the object is on (SPEC 1: bounds are on A).
double boundAlongX(const EngineContact& c, const ContactFrictionResult& r, ObjectId object,
                   int sense) {
  const bool along_t = r.t.x() * sense > 0.0;
  const bool on_a = c.object_a == object;
  return along_t == on_a ? r.bounds.mu_pos_t : r.bounds.mu_neg_t;
}

struct OneStep {
  double dv = 0.0;      // change of the slab's x velocity in the step
  double bound = 0.0;   // mean bound of the friction against its sliding
  double spread = 0.0;  // largest bound minus smallest
};

// The slab settles for 0.2 s, is launched along x at `vx`, and takes one step.
OneStep launchSlab(double vx, int solver_mode_extra) {
  BulletScene scene(
      test::groundScene(test::sawtoothSurface(), test::restingBox("slab", Vec3(0.1, 0.1, 0.01))));
  scene.world().getSolverInfo().m_solverMode |= solver_mode_extra;
  for (int i = 0; i < 20; ++i) scene.step();
  btRigidBody& slab = scene.body("slab");
  slab.setLinearVelocity(btVector3(static_cast<btScalar>(vx), 0, 0));
  scene.step();
  // The bounds of the friction on the slab against its sliding (along -sign(vx) x).
  const ObjectId id = scene.friction()->contactFriction().findObject("slab");
  const auto contacts = scene.friction()->lastContacts();
  const auto results = scene.friction()->lastResults();
  OneStep out;
  double lo = 1e9, hi = 0.0;
  for (size_t i = 0; i < contacts.size(); ++i) {
    const double mu = boundAlongX(contacts[i], results[i], id, vx > 0.0 ? -1 : 1);
    out.bound += mu / static_cast<double>(contacts.size());
    lo = std::min(lo, mu), hi = std::max(hi, mu);
  }
  out.spread = hi - lo;
  out.dv = static_cast<double>(slab.getLinearVelocity().x()) - vx;
  EXPECT_EQ(contacts.size(), 4u);
  return out;
}

TEST(BulletFrictionSolver, EachFrictionRowIsBoundedByItsOwnSense) {
  const OneStep up = launchSlab(1.0, 0);     // up the ramps
  const OneStep down = launchSlab(-1.0, 0);  // against the steep faces
  // The two senses differ several times over, and each step loses mu g dt of its speed.
  EXPECT_GT(down.bound, 3.0 * up.bound);
  for (const OneStep& s : {up, down}) {
    EXPECT_LT(s.spread, 0.02 * s.bound);
    EXPECT_TRUE(test::near(std::abs(s.dv), s.bound * kG * 0.01, 0.03)) << s.dv << " " << s.bound;
  }
  EXPECT_LT(up.dv, 0.0);
  EXPECT_GT(down.dv, 0.0);
}

TEST(BulletFrictionSolver, EverySolverModeBoundsRowsBySense) {
  // Interleaved contact and friction rows, and a shuffled row order, as Bullet solves them.
  for (const int mode :
       {SOLVER_INTERLEAVE_CONTACT_AND_FRICTION_CONSTRAINTS, SOLVER_RANDMIZE_ORDER, SOLVER_SIMD}) {
    for (const double vx : {1.0, -1.0}) {
      const OneStep s = launchSlab(vx, mode);
      EXPECT_TRUE(test::near(std::abs(s.dv), s.bound * kG * 0.01, 0.03))
          << "mode " << mode << " vx " << vx << ": " << s.dv << " " << s.bound;
    }
  }
}

TEST(BulletFrictionSolver, JointsAreSolvedAsBulletSolvesThem) {
  // A box swinging from a pin, touching nothing: the same bits as Bullet's own solver.
  SceneDesc scene;
  BodyDesc box = test::restingBox("box", Vec3(0.1, 0.05, 0.05), 0.0, 0.0);
  box.linear_velocity = Vec3(0.0, 1.0, 0.0);
  scene.bodies.push_back(box);
  BulletSceneOptions plain;
  plain.asperity_friction = false;
  BulletScene ours(scene), bullets(scene, plain);
  std::vector<std::unique_ptr<btPoint2PointConstraint>> pins;
  for (BulletScene* s : {&ours, &bullets}) {
    pins.push_back(
        std::make_unique<btPoint2PointConstraint>(s->body("box"), btVector3(0.3f, 0, 0)));
    s->world().addConstraint(pins.back().get());
  }
  for (int i = 0; i < 100; ++i) ours.step(), bullets.step();
  EXPECT_EQ(ours.position("box"), bullets.position("box"));
  EXPECT_GT((ours.position("box") - Vec3(0, 0, 0.05)).norm(), 0.05);  // it swung
  ours.world().removeConstraint(pins[0].get());
  bullets.world().removeConstraint(pins[1].get());
}

}  // namespace
}  // namespace asperity
