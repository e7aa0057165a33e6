// Oracles for chains on rods (SPEC 8), constant Coulomb friction: the in-plane capstan with a
// fine chain, the axial hold of a chain draped over a tilted rod, the wound hold on the chain
// bolas' rod tilt, a chain with heavy ends hanging wound on a rod (joint error, creep), and a
// chain with heavy ends winding itself round a rod it is thrown at.
// Chains are ball-jointed capsules or flat box links; the rod is a static cylinder.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "asperity/world/world.hpp"

namespace asperity {
namespace {

constexpr double kRodZ = 1.5;   // m, height of the rod's centre
constexpr double kLink = 0.01;  // m, link length of the fine chains (half the rod's radius)
constexpr double kLeg = 0.1;    // m, hanging legs

// A rod through (0, 0, kRodZ) along u = (0, cos alpha, sin alpha): tilted alpha from the
// horizontal y axis toward +z.
struct Rod {
  double radius = 0.02;  // m
  double alpha = 0.0;    // rad
  Vec3 axis() const { return Vec3(0, std::cos(alpha), std::sin(alpha)); }
  // The direction perpendicular to the axis that is closest to up.
  Vec3 up() const { return Vec3(0, -std::sin(alpha), std::cos(alpha)); }
  Vec3 centre() const { return Vec3(0, 0, kRodZ); }
};

// A chain: joint points (world), the links between them and the two end weights.
struct Chain {
  std::vector<Vec3> points;  // joint points, first end to last
  double link_radius = 0.004;
  double link_mass = 0.01;       // kg
  double end_mass = 1.0;         // kg, the first end sphere
  double end_mass1 = 1.0;        // kg, the last end sphere
  double end_radius = 0.02;      // m
  Vec3 velocity = Vec3::Zero();  // every body's initial velocity
  bool flat = false;            // flat box links (width 2 radius x thickness radius); else capsules
  Vec3 across = Vec3::UnitY();  // flat links' width lies along this axis (projected)
  double thickness = 0.0;       // flat links' thickness (m); 0: the link radius
};

struct Settings {
  double mu = 0.5;
  int iterations = 20;
  int substeps = 1;
  double dt = 0.001;
};

Shape sphere(double radius) {
  Shape s;
  s.type = ShapeType::Sphere;
  s.radius = radius;
  return s;
}

// A ball joint of a with b at the body-local anchors.
JointDesc ballJoint(BodyId a, BodyId b, const Vec3& anchor_a, const Vec3& anchor_b) {
  JointDesc j;
  j.name = "joint_" + std::to_string(a);
  j.type = JointType::Ball;
  j.body_a = a, j.body_b = b;
  j.anchor_a = anchor_a, j.anchor_b = anchor_b;
  return j;
}

// The world: the rod, the links along the points, an end sphere hanging below (or beyond)
// each end point. Returns the ids of the two end spheres.
std::pair<BodyId, BodyId> build(World& world, const Rod& rod, const Chain& chain) {
  BodyDesc r;
  r.name = "rod";
  r.type = BodyType::Static;
  // The cylinder's axis is its local z.
  r.pose = {rod.centre(), Quat::FromTwoVectors(Vec3::UnitZ(), rod.axis())};
  Shape cylinder;
  cylinder.type = ShapeType::Cylinder;
  cylinder.radius = rod.radius;
  cylinder.half_height = 0.6;
  r.shapes = {cylinder};
  world.createBody(r);
  const std::vector<Vec3>& p = chain.points;
  // An end sphere continues the chain's end segment beyond its end point.
  auto end = [&](const char* name, const Vec3& at, const Vec3& outward, double mass) {
    BodyDesc b;
    b.name = name;
    b.pose = {at + chain.end_radius * outward, Quat::Identity()};
    b.shapes = {sphere(chain.end_radius)};
    b.mass_override = mass;
    b.linear_velocity = chain.velocity;
    return world.createBody(b);
  };
  const Vec3 out0 = (p[0] - p[1]).normalized();
  const BodyId first = end("ball_0", p[0], out0, chain.end_mass);
  BodyId previous = first;
  Vec3 previous_anchor = -chain.end_radius * out0;
  // Link i from p[i] to p[i + 1]: its local z points toward the last end.
  for (size_t i = 0; i + 1 < p.size(); ++i) {
    const Vec3 d = p[i + 1] - p[i];
    const double length = d.norm();
    BodyDesc link;
    link.name = "link_" + std::to_string(i);
    const Vec3 z = d / length;
    const Vec3 x = (chain.across - chain.across.dot(z) * z).normalized();
    Mat3 frame;
    frame << x, z.cross(x), z;
    link.pose = {0.5 * (p[i] + p[i + 1]), Quat(frame)};
    Shape shape;
    if (chain.flat) {
      // Thin along the link's local y (the rod's radial direction), wide along x.
      shape.type = ShapeType::Box;
      const double thickness = chain.thickness > 0 ? chain.thickness : chain.link_radius;
      shape.half_extents = Vec3(chain.link_radius, 0.5 * thickness, 0.5 * length);
    } else {
      shape.type = ShapeType::Capsule;
      shape.radius = chain.link_radius;
      shape.half_height = std::max(0.5 * length - chain.link_radius, 0.25 * length);
    }
    link.shapes = {shape};
    link.mass_override = chain.link_mass;
    link.linear_velocity = chain.velocity;
    const BodyId id = world.createBody(link);
    JointDesc j = ballJoint(previous, id, previous_anchor, Vec3(0, 0, -0.5 * length));
    world.createJoint(j);
    previous = id, previous_anchor = Vec3(0, 0, 0.5 * length);
  }
  const Vec3 out1 = (p.back() - p[p.size() - 2]).normalized();
  const BodyId last = end("ball_1", p.back(), out1, chain.end_mass1);
  const Vec3 local = world.body(last).pose.rotation.conjugate() * (-chain.end_radius * out1);
  world.createJoint(ballJoint(previous, last, previous_anchor, local));
  return {first, last};
}

WorldSettings worldSettings(const Settings& s) {
  WorldSettings w;
  w.dt = s.dt;
  w.iterations = s.iterations;
  w.substeps = s.substeps;
  w.limit_surface = LimitSurfaceKind::Coulomb;
  w.friction.mu0 = s.mu;
  return w;
}

// Points along the rod's surface (offset by the link radius): angle a about the axis from the
// horizontal x, measured toward up(); `advance` m along the axis per radian.
Vec3 around(const Rod& rod, double r, double a, double advance) {
  return rod.centre() + r * (std::cos(a) * Vec3::UnitX() + std::sin(a) * rod.up()) +
         advance * a * rod.axis();
}

// Joint points of a chain laid `wrap` rad round the rod from angle 0 (the +x side) over the
// top, `pitch` m along the axis per turn, with vertical legs of `leg` m, links of `link` m.
std::vector<Vec3> drapedPoints(const Rod& rod, double radius, double wrap, double pitch, double leg,
                               double link) {
  const double r = rod.radius + radius;
  const int arc_links = std::max(2, static_cast<int>(std::ceil(wrap * r / link)));
  const int leg_links = static_cast<int>(std::ceil(leg / link));
  const double advance = pitch / (2 * kPi);
  std::vector<Vec3> arc;
  for (int k = 0; k <= arc_links; ++k) {
    arc.push_back(around(rod, r / std::cos(0.5 * wrap / arc_links), wrap * k / arc_links, advance));
  }
  std::vector<Vec3> points;
  for (int i = leg_links; i >= 1; --i) points.push_back(arc.front() - Vec3(0, 0, i * link));
  points.insert(points.end(), arc.begin(), arc.end());
  for (int i = 1; i <= leg_links; ++i) points.push_back(arc.back() - Vec3(0, 0, i * link));
  return points;
}

// Motion of a chain left for `seconds`: the two end spheres' displacement (m).
struct Motion {
  double drop0 = 0.0, drop1 = 0.0;  // m the ends went down
  double middle_along = 0.0;        // m, the chain's middle link moved along the rod axis
  double joint_error = 0.0;         // m, largest over the run
};

Motion settle(const Rod& rod, const Chain& chain, const Settings& s, double seconds) {
  World world(worldSettings(s));
  const auto [e0, e1] = build(world, rod, chain);
  const Vec3 p0 = world.body(e0).pose.position, p1 = world.body(e1).pose.position;
  const BodyId middle = world.findBody("link_" + std::to_string((chain.points.size() - 1) / 2));
  const Vec3 pm = world.body(middle).pose.position;
  Motion m;
  const int steps = static_cast<int>(std::lround(seconds / s.dt));
  for (int i = 0; i < steps; ++i) {
    world.step();
    for (int j = 0; j < static_cast<int>(world.joints().size()); ++j) {
      m.joint_error = std::max(m.joint_error, world.jointError(j));
    }
  }
  const Vec3 q0 = world.body(e0).pose.position, q1 = world.body(e1).pose.position;
  m.drop0 = p0.z() - q0.z();
  m.drop1 = p1.z() - q1.z();
  m.middle_along = (world.body(middle).pose.position - pm).dot(rod.axis());
  return m;
}

// A fine chain (10 mm links on a 20 mm rod, 0.02 kg links, capsules) draped half a turn
// with vertical legs of 0.1 m; end weights `heavy` and `light`.
Chain fineChain(const Rod& rod, double heavy, double light) {
  Chain c;
  c.link_radius = 0.003;
  c.link_mass = 0.02;
  c.end_mass = heavy;
  c.end_mass1 = light;
  c.across = rod.axis();
  c.points = drapedPoints(rod, c.link_radius, kPi, 0.0, kLeg, kLink);
  return c;
}

// Capstan (SPEC 8) with a fine chain: weights 1 and 0.5 kg, leg tensions at the rod (end
// weight plus the leg's ten links) R = 1.72, mu* = ln R / pi = 0.172. Holding: the heavy end
// sinks less than 1 cm in 3 s; running off: more than 0.1 m.
void expectCapstanThreshold(int iterations, int substeps) {
  const Rod rod;
  const Chain c = fineChain(rod, 1.0, 0.5);
  const double leg = std::ceil(kLeg / kLink) * c.link_mass;
  const double star = std::log((c.end_mass + leg) / (c.end_mass1 + leg)) / kPi;
  ASSERT_NEAR(star, 0.172, 0.001);
  Settings s;
  s.iterations = iterations;
  s.substeps = substeps;
  // 15 % above mu*: holds.
  s.mu = 1.15 * star;
  EXPECT_LT(settle(rod, c, s, 3.0).drop0, 0.01) << iterations << " iterations";
  // 15 % below: the heavy end runs off.
  s.mu = 0.85 * star;
  EXPECT_GT(settle(rod, c, s, 3.0).drop0, 0.1) << iterations << " iterations";
}

TEST(ChainOnRod, FineChainCapstanThresholdIsLnROverPiWhenConverged) {
  expectCapstanThreshold(200, 1);
}

// At the default 20 iterations the chain needs sub-steps: 4 sub-steps of 20 iterations hold at
// 1.15 mu* (0.7 mm in 3 s), where 80 iterations in one solve let it creep 0.1 m in 3 s and
// 2 x 10, 4 x 5 or 10 x 2 (the same 20 sweeps) run off as one solve of 20 does.
TEST(ChainOnRod, FineChainCapstanThresholdIsLnROverPiWithFourSubsteps) {
  expectCapstanThreshold(20, 4);
}

// The same at the default 20 iterations fails: the heavy end creeps. Measured drops in 1 s /
// 3 s: mu 1.5 mu* 3.2 mm / 59 mm, 2 mu* 2.2 / 24 mm, 3 mu* 1.7 / 16 mm (200 iterations: 0.15 /
// 0.32 mm, 0.11 / 0.23, 0.08 / 0.15); at 1.15 mu* 14 mm in 1 s and 0.54 m in 2 s. The creep
// falls with the iteration count, not with mu: PGS has not converged on 0.02 kg links between
// 1 kg ends in 20 sweeps.
TEST(ChainOnRod, DISABLED_FineChainCapstanThresholdIsLnROverPiAtTwentyIterations) {
  expectCapstanThreshold(20, 1);
}

// Axial hold (SPEC 8): equal weights, rod tilted by alpha; stays iff mu >= (2 / pi) tan alpha.
// Flat box links: capsule links on ball joints spin about their own axes and roll down the rod
// at any mu (0.83 m in 1 s at 10 degrees, as on a frictionless incline), as real flat links do
// not. The chain's middle link (on top of the rod) is what holds or slides; the end weights
// also swing along the rod while the drape settles. Measured (20 iterations, 2 s): at 1.25 mu*
// the middle link settles 7 mm at 10 and 20 degrees and then stays; at 0.75 mu* it runs off.
void expectAxialHold(double degrees) {
  Rod rod;
  rod.alpha = degrees * kPi / 180;
  Chain c = fineChain(rod, 1.0, 1.0);
  c.flat = true;
  const double star = 2 / kPi * std::tan(rod.alpha);
  Settings s;
  s.mu = 1.25 * star;
  EXPECT_LT(std::abs(settle(rod, c, s, 1.0).middle_along), 0.01) << degrees << " degrees";
  s.mu = 0.75 * star;
  EXPECT_GT(std::abs(settle(rod, c, s, 1.0).middle_along), 0.1) << degrees << " degrees";
}

TEST(ChainOnRod, DrapedOnATiltedRodHoldsIffMuAboveTwoOverPiTanAlpha) {
  expectAxialHold(10.0);
  expectAxialHold(20.0);
}

// Wound hold (SPEC 8): 1.5 turns on the bolas' rod tilt (0.5 rad, 28.6 degrees) hold from
// mu = tan(0.5) / (3 pi) = 0.058 on; flat links as above.
TEST(ChainOnRod, WoundOneAndAHalfTurnsHoldsAtMuPoint3SlidesAtPoint03) {
  Rod rod;
  rod.alpha = 0.5;
  Chain c = fineChain(rod, 1.0, 1.0);
  c.flat = true;
  c.points = drapedPoints(rod, 0.5 * c.link_radius, 3 * kPi, 6 * c.link_radius, kLeg, kLink);
  Settings s;
  s.mu = 0.3;
  EXPECT_LT(std::abs(settle(rod, c, s, 1.0).middle_along), 0.01);
  s.mu = 0.03;
  EXPECT_GT(std::abs(settle(rod, c, s, 1.0).middle_along), 0.1);
}

// Heavy ends on a light chain: the chain bolas' own chain (23 flat links of 5 x 40 x 25 mm and
// 0.08 kg between two 2 kg spheres, 25 bodies) wound 1.5 turns on its rod (radius 19.5 mm,
// tilted 28.6 degrees), the ends swinging at 0.5 m/s, mu 0.4, 20 iterations, one sub-step.
// Measured: joint error 0.1 mm; after settling (0.5 s) the middle link creeps 1.7 mm along the
// rod in 1.5 s while the ends swing (1.2 mm with 4 sub-steps; 100 iterations do not change
// it, so it is not the solver's convergence); the ends stay within 1 cm in height.
TEST(ChainOnRod, HeavyEndsOnALightChainHoldWoundAndKeepTheirJoints) {
  Rod rod;
  rod.alpha = 0.5;
  rod.radius = 0.0195;
  Chain c;
  c.flat = true;
  c.link_radius = 0.0125;  // 25 mm wide
  c.thickness = 0.005;
  c.link_mass = 0.08;
  c.end_mass = c.end_mass1 = 2.0;
  c.end_radius = 0.0266;
  c.across = rod.axis();
  c.points = drapedPoints(rod, 0.5 * c.thickness, 3 * kPi, 0.03, 0.32, 0.04);
  c.points.insert(c.points.begin(), c.points.front() - Vec3(0, 0, 0.04));
  ASSERT_EQ(c.points.size() - 1, 23u);
  c.velocity = Vec3(0.5, 0, 0);
  Settings s;
  s.mu = 0.4;
  // Settling and swinging in the first half second; no creep after it.
  const Motion early = settle(rod, c, s, 0.5), late = settle(rod, c, s, 2.0);
  EXPECT_LT(late.joint_error, 0.001);
  EXPECT_LT(std::abs(late.middle_along - early.middle_along), 0.003);
  EXPECT_LT(std::abs(late.drop0 - early.drop0), 0.005);
}

// The offset of p from the rod's axis, perpendicular to it.
Vec3 radial(const Rod& rod, const Vec3& p) {
  const Vec3 d = p - rod.centre();
  return d - d.dot(rod.axis()) * rod.axis();
}

// Contacts of a chain lying on a rod: a fine chain of flat links (6 mm wide, 10 mm long,
// 2 mm thick) draped half a turn over a horizontal rod of radius 20 mm, crossing it straight
// (a chain hung straight over it) or at 30 degrees (a turn of a helix), settles in 1 s. Every
// link lying on the rod (its centre within a millimetre of the rod's surface plus half its
// thickness) touches it with two points, at the two ends of the line its face lies along,
// and carries a normal force; there are as many as the wrap's arc holds (the arc of half a
// turn over links of 10 mm: 7 or 8).
TEST(ChainOnRod, DrapedFlatLinksEachTouchTheRodAtTwoPoints) {
  for (double cross_deg : {0.0, 30.0}) {
    const Rod rod;
    Chain c = fineChain(rod, 1.0, 1.0);
    c.flat = true;
    c.thickness = 0.002;
    const double pitch = 2 * kPi * (rod.radius + 0.001) * std::tan(cross_deg * kPi / 180);
    c.points = drapedPoints(rod, 0.5 * c.thickness, kPi, pitch, kLeg, kLink);
    Settings s;
    World world(worldSettings(s));
    build(world, rod, c);
    for (int i = 0; i < 1000; ++i) world.step();
    const BodyId r = world.findBody("rod");
    int lying = 0;
    for (BodyId id = 0; id < world.bodies().size(); ++id) {
      const Body& b = world.body(id);
      if (b.name.rfind("link_", 0) != 0) continue;
      if (radial(rod, b.pose.position).norm() > rod.radius + 0.5 * c.thickness + 0.001) continue;
      ++lying;
      int points = 0;
      double normal = 0.0;
      for (const Contact& k : world.contacts()) {
        if ((k.body_a == id && k.body_b == r) || (k.body_a == r && k.body_b == id)) {
          ++points;
          normal += k.lambda_n;
        }
      }
      EXPECT_EQ(points, 2) << b.name << ", crossing at " << cross_deg << " degrees";
      EXPECT_GT(normal, 0.0) << b.name << ", crossing at " << cross_deg << " degrees";
    }
    EXPECT_GE(lying, 7) << "crossing at " << cross_deg << " degrees";
  }
}

// Winding (SPEC 8): the signed angle the chain's joint points turn through about the rod's axis,
// in turns, counting the segments whose two ends lie within `near` of the axis.
double turnsAbout(const Rod& rod, const std::vector<Vec3>& points, double near) {
  const Vec3 x = Vec3::UnitX(), y = rod.up();
  double angle = 0.0;
  for (size_t i = 0; i + 1 < points.size(); ++i) {
    const Vec3 ra = radial(rod, points[i]), rb = radial(rod, points[i + 1]);
    if (ra.norm() > near || rb.norm() > near) continue;
    angle += std::remainder(std::atan2(rb.dot(y), rb.dot(x)) - std::atan2(ra.dot(y), ra.dot(x)),
                            2 * kPi);
  }
  return std::abs(angle) / (2 * kPi);
}

// Winding: the bolas' chain (2 kg ends, 23 flat links of 0.08 kg, 40 mm apart) hanging straight
// down with its middle at a fixed horizontal rod, thrown at it at 6 m/s, the ends also moving
// 1 m/s along the rod in opposite senses (so that they pass each other behind the rod instead
// of colliding there), mu 0.5, 20 iterations. The ends whip round the rod: the count of turns
// grows and both ends finish within four link lengths of the rod's surface. Measured: 1.43
// turns at 0.25 s, 3.97 at 2 s, ends 0.12 and 0.08 m from the axis; thrown at 4 m/s the chain
// winds 2.9 turns with an end 0.25 m out, at 2 m/s it stays draped (0.9 turns).
TEST(ChainOnRod, ThrownAtItsMiddleTheChainWindsRoundTheRod) {
  Rod rod;
  rod.radius = 0.0195;
  Chain c;
  c.flat = true;
  c.link_radius = 0.0125;
  c.thickness = 0.005;
  c.link_mass = 0.08;
  c.end_mass = c.end_mass1 = 2.0;
  c.end_radius = 0.0266;
  c.across = rod.axis();
  c.velocity = Vec3(6, 0, 0);
  for (int i = 0; i <= 23; ++i) c.points.push_back(Vec3(-0.1, 0, kRodZ + 0.46 - 0.04 * i));
  Settings s;
  s.mu = 0.5;
  World world(worldSettings(s));
  const std::pair<BodyId, BodyId> ends = build(world, rod, c);
  // Plain variables, not a structured binding: clang 14 cannot capture those in a lambda.
  const BodyId e0 = ends.first, e1 = ends.second;
  world.body(e0).linear_velocity += rod.axis();
  world.body(e1).linear_velocity -= rod.axis();
  auto joints = [&] {
    std::vector<Vec3> p = {world.body(e0).pose.position};
    for (int i = 0; i < 23; ++i)
      p.push_back(world.body(world.findBody("link_" + std::to_string(i))).pose.position);
    p.push_back(world.body(e1).pose.position);
    return p;
  };
  const double near = rod.radius + 0.06;  // within one and a half links of the rod
  for (int i = 0; i < 250; ++i) world.step();
  const double early = turnsAbout(rod, joints(), near);
  for (int i = 0; i < 1750; ++i) world.step();
  const double late = turnsAbout(rod, joints(), near);
  EXPECT_GT(late, early + 1.0) << early << " turns at 0.25 s, " << late << " at 2 s";
  EXPECT_GT(late, 2.5);
  const double reach = rod.radius + 4 * 0.04;
  EXPECT_LT(radial(rod, world.body(e0).pose.position).norm(), reach);
  EXPECT_LT(radial(rod, world.body(e1).pose.position).norm(), reach);
}

}  // namespace
}  // namespace asperity
