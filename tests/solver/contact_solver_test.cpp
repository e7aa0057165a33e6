// The PGS contact solver on hand-made contacts: normal support, friction bounds of each limit
// surface (SPEC 1 signs), convergence, warm starting and split impulses.
#include "solver/contact_solver.hpp"

#include <gtest/gtest.h>

#include <span>
#include <string>
#include <utility>
#include <vector>

#include "asperity/error.hpp"
#include "parallel/thread_pool.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::near;

constexpr double kDt = 0.01;
constexpr double kG = 9.81;

// A static ground (body 0) and point masses (no rotation) or unit cubes above it.
std::vector<Body> ground() {
  Body g;
  g.type = BodyType::Static;
  return {g};
}

Body particle(const Vec3& position, double mass, const Vec3& velocity) {
  Body b;
  b.pose.position = position;
  b.inverse_mass = 1.0 / mass;
  b.inverse_inertia_local = Vec3::Zero();  // infinite inertia: friction makes no torque
  b.linear_velocity = velocity;
  return b;
}

// A contact of `a` on the ground at `point` with normal +z, frame (x, y, z), given mu.
Contact groundContact(BodyId a, const Vec3& point, const DirectionalMu& mu, uint64_t key = 1) {
  Contact c;
  c.body_a = a;
  c.body_b = 0;
  c.point = c.witness_a = c.witness_b = point;
  c.normal = Vec3::UnitZ();
  c.t = Vec3::UnitX();
  c.b = Vec3::UnitY();
  c.mu = mu;
  c.key = key;
  return c;
}

// mu along +t, +b, -t, -b (N = 4).
DirectionalMu box(float pt, float pb, float nt, float nb) {
  DirectionalMu mu = DirectionalMu::uniform(4, 0.0f);
  mu.mu = {pt, pb, nt, nb};
  return mu;
}

SolverSettings settings(LimitSurfaceKind kind, double coulomb_mu = 0.5) {
  SolverSettings s;
  s.dt = kDt;
  s.limit_surface = kind;
  s.coulomb_mu = coulomb_mu;
  s.warm_starting = false;
  return s;
}

// One solve of `bodies` with `contacts`; returns the solved contacts.
std::vector<Contact> solveOnce(std::vector<Body>& bodies, std::vector<Contact> contacts,
                               const SolverSettings& s, int iterations = 20) {
  ContactSolver solver;
  solver.begin(bodies, s);
  solver.setContacts(contacts, true);
  solver.iterate(iterations);
  solver.finish(bodies, contacts);
  return contacts;
}

TEST(ContactSolver, NormalImpulseStopsFallingMass) {
  // A 2 kg mass that gained -g dt this step: lambda_n = m g dt, v_z -> 0.
  std::vector<Body> bodies = ground();
  bodies.push_back(particle(Vec3(0, 0, 0.1), 2.0, Vec3(0, 0, -kG * kDt)));
  const auto c = solveOnce(bodies, {groundContact(1, Vec3::Zero(), box(1, 1, 1, 1))},
                           settings(LimitSurfaceKind::Box));
  EXPECT_TRUE(near(c[0].lambda_n, 2.0 * kG * kDt, 1e-12));
  EXPECT_TRUE(near(bodies[1].linear_velocity.z(), 0.0, 0.0, 1e-12));
}

TEST(ContactSolver, SeparatingContactPushesNothing) {
  std::vector<Body> bodies = ground();
  bodies.push_back(particle(Vec3(0, 0, 0.1), 1.0, Vec3(0, 0, 1.0)));
  const auto c = solveOnce(bodies, {groundContact(1, Vec3::Zero(), box(1, 1, 1, 1))},
                           settings(LimitSurfaceKind::Box));
  EXPECT_EQ(c[0].lambda_n, 0.0);
  EXPECT_EQ(bodies[1].linear_velocity.z(), 1.0);
}

// A mass sliding at v along direction (cos a, sin a) with normal load m g dt.
struct Slide {
  double lambda_t, lambda_b, vx, vy;
};
Slide slide(LimitSurfaceKind kind, const DirectionalMu& mu, double angle, double speed) {
  std::vector<Body> bodies = ground();
  const double m = 1.0;
  bodies.push_back(particle(Vec3(0, 0, 0.1), m,
                            Vec3(speed * std::cos(angle), speed * std::sin(angle), -kG * kDt)));
  const auto c = solveOnce(bodies, {groundContact(1, Vec3::Zero(), mu)}, settings(kind, 0.3));
  return {c[0].lambda_t, c[0].lambda_b, bodies[1].linear_velocity.x(),
          bodies[1].linear_velocity.y()};
}

TEST(ContactSolver, BoxLimitResistsEachDirectionWithItsOwnMu) {
  // SPEC 1: A sliding along +t is resisted along -t, bounded by mu_{-t}; and so on.
  const DirectionalMu mu = box(0.1f, 0.2f, 0.3f, 0.4f);
  const double ln = kG * kDt;
  const Slide pt = slide(LimitSurfaceKind::Box, mu, 0.0, 1.0);
  EXPECT_TRUE(near(pt.lambda_t, -0.3 * ln, 1e-6));
  const Slide nt = slide(LimitSurfaceKind::Box, mu, kPi, 1.0);
  EXPECT_TRUE(near(nt.lambda_t, 0.1 * ln, 1e-6));
  const Slide pb = slide(LimitSurfaceKind::Box, mu, 0.5 * kPi, 1.0);
  EXPECT_TRUE(near(pb.lambda_b, -0.4 * ln, 1e-6));
  const Slide nb = slide(LimitSurfaceKind::Box, mu, 1.5 * kPi, 1.0);
  EXPECT_TRUE(near(nb.lambda_b, 0.2 * ln, 1e-6));
  // The velocity drops by exactly the bounded impulse (m = 1).
  EXPECT_TRUE(near(pt.vx, 1.0 - 0.3 * ln, 1e-7));
}

TEST(ContactSolver, SlowSlideSticksWithinTheBound) {
  // Tangential momentum below mu lambda_n: friction stops the mass completely.
  const Slide s = slide(LimitSurfaceKind::Box, box(0.5f, 0.5f, 0.5f, 0.5f), 0.3, 0.01);
  EXPECT_TRUE(near(s.vx, 0.0, 0.0, 1e-12));
  EXPECT_TRUE(near(s.vy, 0.0, 0.0, 1e-12));
}

TEST(ContactSolver, CoulombUsesMu0InEveryDirection) {
  // The disc of radius mu0 lambda_n, whatever the contact's coefficients say.
  const DirectionalMu ignored = box(2.0f, 2.0f, 2.0f, 2.0f);
  for (int k = 0; k < 8; ++k) {
    const double angle = 2.0 * kPi * k / 8;
    const Slide s = slide(LimitSurfaceKind::Coulomb, ignored, angle, 1.0);
    EXPECT_TRUE(near(std::hypot(s.lambda_t, s.lambda_b), 0.3 * kG * kDt, 1e-9)) << k;
    // Friction opposes the sliding direction.
    EXPECT_TRUE(
        near(std::atan2(-s.lambda_b, -s.lambda_t), std::remainder(angle, 2 * kPi), 0.0, 1e-9))
        << k;
  }
}

TEST(ContactSolver, PolygonLimitBoundsDiagonalSlides) {
  // Isotropic N = 8 polygon of radius 0.4: a diagonal slide is resisted by the polygon's
  // vertex (mu 0.4 along the diagonal), not the box's corner (0.4 sqrt 2).
  const DirectionalMu mu = DirectionalMu::uniform(8, 0.4f);
  const Slide s = slide(LimitSurfaceKind::Polygon, mu, 0.25 * kPi, 1.0);
  EXPECT_TRUE(near(std::hypot(s.lambda_t, s.lambda_b), 0.4 * kG * kDt, 1e-6));
}

// A column of `n` unit-mass cubes (rotating) on the ground with 4 corner contacts each.
struct Column {
  std::vector<Body> bodies;
  std::vector<Contact> contacts;
};
Column column(int n) {
  Column col{ground(), {}};
  const double h = 0.1;
  for (int i = 0; i < n; ++i) {
    Body b = particle(Vec3(0, 0, h + 2 * h * i), 1.0, Vec3(0, 0, -kG * kDt));
    b.inverse_inertia_local = Vec3::Constant(1.0 / (2.0 / 3.0 * h * h));
    col.bodies.push_back(b);
    for (int k = 0; k < 4; ++k) {
      const Vec3 corner((k & 1) ? h : -h, (k & 2) ? h : -h, 2 * h * i);
      Contact c = groundContact(static_cast<BodyId>(i + 1), corner, box(0.5f, 0.5f, 0.5f, 0.5f),
                                static_cast<uint64_t>(4 * i + k + 1));
      c.body_b = static_cast<BodyId>(i);
      col.contacts.push_back(c);
    }
  }
  return col;
}

// Distance of the body velocities after `iterations` sweeps from a converged reference (the
// velocities are unique; the four coplanar contacts' impulse split is not).
double velocityError(int iterations) {
  Column ref = column(6);
  solveOnce(ref.bodies, ref.contacts, settings(LimitSurfaceKind::Box), 20000);
  Column col = column(6);
  solveOnce(col.bodies, col.contacts, settings(LimitSurfaceKind::Box), iterations);
  double err = 0.0;
  for (size_t i = 0; i < ref.bodies.size(); ++i) {
    err += (ref.bodies[i].linear_velocity - col.bodies[i].linear_velocity).squaredNorm() +
           (ref.bodies[i].angular_velocity - col.bodies[i].angular_velocity).squaredNorm();
  }
  return std::sqrt(err);
}

TEST(ContactSolver, ResidualFallsAsIterationsGrow) {
  const double e5 = velocityError(5), e20 = velocityError(20), e80 = velocityError(80);
  EXPECT_LT(e20, 0.7 * e5);
  EXPECT_LT(e80, 0.5 * e20);
  // And the sweep's own change measure falls too.
  Column a = column(6), b = column(6);
  ContactSolver sa, sb;
  sa.begin(a.bodies, settings(LimitSurfaceKind::Box));
  sa.setContacts(a.contacts, true);
  sa.iterate(5);
  sb.begin(b.bodies, settings(LimitSurfaceKind::Box));
  sb.setContacts(b.contacts, true);
  sb.iterate(80);
  EXPECT_LT(sb.lastDelta(), 0.1 * sa.lastDelta());
}

TEST(ContactSolver, ColumnSupportsItsWeight) {
  // Converged: the bottom contacts carry the whole column, n m g dt.
  Column col = column(6);
  const auto c = solveOnce(col.bodies, col.contacts, settings(LimitSurfaceKind::Box), 20000);
  double bottom = 0.0;
  for (int k = 0; k < 4; ++k) bottom += c[static_cast<size_t>(k)].lambda_n;
  EXPECT_TRUE(near(bottom, 6.0 * kG * kDt, 1e-6));
}

TEST(ContactSolver, WarmStartReusesLastImpulsesByKey) {
  // Same contacts twice: the second solve starts converged, so one sweep barely changes it.
  Column col = column(6);
  SolverSettings s = settings(LimitSurfaceKind::Box);
  s.warm_starting = true;
  ContactSolver solver;
  std::vector<Contact> contacts = col.contacts;
  std::vector<Body> bodies = col.bodies;
  solver.begin(bodies, s);
  solver.setContacts(contacts, true);
  solver.iterate(20000);
  solver.finish(bodies, contacts);
  const double cold = [&] {
    Column fresh = column(6);
    ContactSolver cs;
    cs.begin(fresh.bodies, s);
    cs.setContacts(fresh.contacts, true);
    cs.iterate(1);
    return cs.lastDelta();
  }();
  std::vector<Body> again = column(6).bodies;
  solver.begin(again, s);
  solver.setContacts(col.contacts, true);
  solver.iterate(1);
  EXPECT_LT(solver.lastDelta(), 1e-6 * cold);
}

// Warm starting matches a contact to last step's impulse only when its key was unique, and
// finds the same matches when its contacts are split over threads (from 256 contacts on).
TEST(ContactSolver, WarmStartSkipsRepeatedKeysOnAnyThreadCount) {
  for (const int threads : {1, 2}) {
    const ThreadPool pool(threads);
    Column col = column(70);                        // 280 contacts
    col.contacts[101].key = col.contacts[100].key;  // two corners of one pair share a key
    SolverSettings s = settings(LimitSurfaceKind::Box);
    s.warm_starting = true;
    ContactSolver solver;
    solver.setThreadPool(&pool);
    std::vector<Contact> solved = col.contacts;
    solver.begin(col.bodies, s);
    solver.setContacts(solved, true);
    solver.iterate(200);
    solver.finish(col.bodies, solved);
    // The same contacts again: no sweep, only the warm start.
    std::vector<Contact> again = col.contacts;
    solver.begin(column(70).bodies, s);
    solver.setContacts(again, true);
    solver.iterate(0);
    solver.finish(col.bodies, again);
    for (size_t i = 0; i < again.size(); ++i) {
      const bool repeated = i == 100 || i == 101;
      EXPECT_EQ(again[i].lambda_n, repeated ? 0.0 : solved[i].lambda_n)
          << "contact " << i << ", " << threads << " threads";
    }
  }
}

TEST(ContactSolver, RowsBuiltBeforeTheCoefficientsGiveTheBitsOfRowsBuiltAfter) {
  // The solve stage builds the rows while a GPU may still compute the coefficients, then adds
  // the limit surfaces: rows must not read mu. Rows built from contacts whose mu is still
  // unset give the same impulses and velocities, bit for bit, as rows built from contacts
  // that carry it, warm started from a first solve, on one thread and two.
  for (const int threads : {1, 2}) {
    const ThreadPool pool(threads);
    Column col = column(70);  // 280 contacts
    for (size_t i = 0; i < col.contacts.size(); ++i) {
      const float m = 0.3f + 0.05f * static_cast<float>(i % 7);
      col.contacts[i].mu = box(m, 0.8f * m, 1.2f * m, m);
    }
    auto solve = [&](bool split) {
      ContactSolver solver;
      solver.setThreadPool(&pool);
      const SolverSettings s = settings(LimitSurfaceKind::Polygon);
      std::vector<Body> bodies = col.bodies;
      std::vector<Contact> contacts = col.contacts;
      for (int step = 0; step < 2; ++step) {
        solver.begin(bodies, s);
        if (split) {
          // The coefficients arrive only after the rows are built.
          std::vector<Contact> pending = contacts;
          for (Contact& c : pending) c.mu = box(9.0f, 9.0f, 9.0f, 9.0f);
          solver.setContactRows(pending, true);
          for (size_t i = 0; i < pending.size(); ++i) pending[i].mu = contacts[i].mu;
          solver.setContactLimits(pending);
          solver.warmStart(pending);
        } else {
          solver.setContacts(contacts, true);
        }
        solver.iterate(10);
        solver.finish(bodies, contacts);
      }
      return std::make_pair(bodies, contacts);
    };
    const auto [whole_bodies, whole] = solve(false);
    const auto [split_bodies, split] = solve(true);
    for (size_t i = 0; i < whole.size(); ++i) {
      EXPECT_EQ(split[i].lambda_n, whole[i].lambda_n) << "contact " << i;
      EXPECT_EQ(split[i].lambda_t, whole[i].lambda_t) << "contact " << i;
      EXPECT_EQ(split[i].lambda_b, whole[i].lambda_b) << "contact " << i;
    }
    for (size_t b = 0; b < whole_bodies.size(); ++b) {
      EXPECT_EQ(split_bodies[b].linear_velocity, whole_bodies[b].linear_velocity) << "body " << b;
      EXPECT_EQ(split_bodies[b].angular_velocity, whole_bodies[b].angular_velocity) << "body " << b;
    }
  }
}

// Islands are swept two at a time, one in each lane of a vector register, and an odd one
// alone: each must get the same bits whatever island sits beside it and in which lane. Four
// columns of unequal heights (the longer of a pair finishes alone), sliding and sticking rows,
// penetrations that need position rows, separated rows, warm starting, every limit surface;
// solved as they are, and again behind one more island, which shifts every column to another
// partner or lane (the last one from a lane to sweeping alone).
TEST(ContactSolver, IslandsSweptSideBySideGiveTheBitsOfEachAlone) {
  const int heights[] = {5, 2, 4, 3};
  // Turned off the axes, so that every product rounds (a lane summing in another order fails).
  const Mat3 turn = Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  auto turned = [&](Column col) {
    for (Body& body : col.bodies) {
      body.pose.position = turn * body.pose.position;
      body.linear_velocity = turn * body.linear_velocity;
      body.angular_velocity = turn * body.angular_velocity;
    }
    for (Contact& c : col.contacts) {
      c.point = c.witness_a = c.witness_b = turn * c.point;
      c.normal = turn * c.normal;
      c.t = turn * c.t;
      c.b = turn * c.b;
    }
    return col;
  };
  auto scene = [&](bool extra_island) {
    Column all{ground(), {}};
    if (extra_island) {
      all.bodies.push_back(particle(Vec3(-3, 0, 0.1), 2.0, Vec3(0.3, 0, -kG * kDt)));
      Contact c = groundContact(1, Vec3(-3, 0, 0), box(0.4f, 0.4f, 0.4f, 0.4f));
      c.phi = 0.002;
      all.contacts.push_back(c);
    }
    for (int j = 0; j < 4; ++j) {
      Column col = column(heights[j]);
      const auto first = static_cast<BodyId>(all.bodies.size());
      for (size_t i = 1; i < col.bodies.size(); ++i) {
        Body body = col.bodies[i];
        body.pose.position.x() += 3.0 * j;
        body.linear_velocity += Vec3(0.05 * (j + 1) * static_cast<double>(i), -0.02 * j, 0.0);
        body.angular_velocity = Vec3(0.1, -0.2 * j, 0.3 * static_cast<double>(i));
        all.bodies.push_back(body);
      }
      for (size_t k = 0; k < col.contacts.size(); ++k) {
        Contact c = col.contacts[k];
        c.point.x() += 3.0 * j;
        c.body_a += first - 1;
        if (c.body_b != 0) c.body_b += first - 1;
        const float m = 0.2f + 0.07f * static_cast<float>((k + static_cast<size_t>(j)) % 5);
        c.mu = box(m, 0.8f * m, 1.3f * m, 0.9f * m);
        c.phi = k % 4 == 3 ? -0.002 : 0.001 * static_cast<double>(k % 3);
        all.contacts.push_back(c);
      }
    }
    return turned(all);
  };
  for (const LimitSurfaceKind kind :
       {LimitSurfaceKind::Coulomb, LimitSurfaceKind::Box, LimitSurfaceKind::Polygon}) {
    SolverSettings s = settings(kind);
    s.warm_starting = true;
    auto solve = [&](Column col) {
      ContactSolver solver;
      for (int step = 0; step < 2; ++step) {
        solver.begin(col.bodies, s);
        solver.setContacts(col.contacts, true);
        solver.iterate(7);
        solver.finish(col.bodies, col.contacts);
      }
      std::vector<Vec3> pseudo;
      for (BodyId b = 0; b < col.bodies.size(); ++b) {
        pseudo.push_back(solver.pseudoLinear(b));
        pseudo.push_back(solver.pseudoAngular(b));
      }
      return std::make_pair(col, pseudo);
    };
    const auto [as_is, as_is_pseudo] = solve(scene(false));
    const auto [shifted, shifted_pseudo] = solve(scene(true));
    for (size_t b = 1; b < as_is.bodies.size(); ++b) {
      EXPECT_EQ(as_is.bodies[b].linear_velocity, shifted.bodies[b + 1].linear_velocity) << b;
      EXPECT_EQ(as_is.bodies[b].angular_velocity, shifted.bodies[b + 1].angular_velocity) << b;
      EXPECT_EQ(as_is_pseudo[2 * b], shifted_pseudo[2 * b + 2]) << "body " << b;
      EXPECT_EQ(as_is_pseudo[2 * b + 1], shifted_pseudo[2 * b + 3]) << "body " << b;
    }
    for (size_t k = 0; k < as_is.contacts.size(); ++k) {
      EXPECT_EQ(as_is.contacts[k].lambda_n, shifted.contacts[k + 1].lambda_n) << "contact " << k;
      EXPECT_EQ(as_is.contacts[k].lambda_t, shifted.contacts[k + 1].lambda_t) << "contact " << k;
      EXPECT_EQ(as_is.contacts[k].lambda_b, shifted.contacts[k + 1].lambda_b) << "contact " << k;
    }
    // Not a trivial agreement: the columns move and push.
    EXPECT_GT(as_is.contacts[0].lambda_n, 0.0);
    EXPECT_NE(as_is_pseudo[2], Vec3::Zero());
  }
}

TEST(ContactSolver, LimitsForOtherContactsThanTheRowsAreAnError) {
  Column col = column(2);
  ContactSolver solver;
  solver.begin(col.bodies, settings(LimitSurfaceKind::Box));
  solver.setContactRows(col.contacts, true);
  const std::span<const Contact> fewer(col.contacts.data(), 3);
  EXPECT_THROW(
      {
        try {
          solver.setContactLimits(fewer);
        } catch (const Error& e) {
          EXPECT_NE(std::string(e.what()).find("setContactLimits got 3 contacts"),
                    std::string::npos)
              << e.what();
          throw;
        }
      },
      Error);
}

TEST(ContactSolver, SplitImpulseCorrectsPenetrationWithoutVelocity) {
  // 1 cm deep, at rest: pseudo-velocity pushes out (baumgarte (phi - slop) / dt), the real
  // velocity stays zero (no energy added).
  std::vector<Body> bodies = ground();
  bodies.push_back(particle(Vec3(0, 0, 0.1), 1.0, Vec3::Zero()));
  Contact c = groundContact(1, Vec3::Zero(), box(0.5f, 0.5f, 0.5f, 0.5f));
  c.phi = 0.01;
  SolverSettings s = settings(LimitSurfaceKind::Box);
  s.slop = 0.001;
  ContactSolver solver;
  std::vector<Contact> contacts{c};
  solver.begin(bodies, s);
  solver.setContacts(contacts, true);
  solver.iterate(20);
  solver.finish(bodies, contacts);
  EXPECT_TRUE(near(solver.pseudoLinear(1).z(), 0.2 * 0.009 / kDt, 1e-9));
  EXPECT_EQ(bodies[1].linear_velocity.z(), 0.0);
}

TEST(ContactSolver, SpeculativeContactLetsTheGapClose) {
  // 1 mm apart, approaching at 5 cm/s: the contact allows 0.1 m/s of approach, so no impulse.
  std::vector<Body> bodies = ground();
  bodies.push_back(particle(Vec3(0, 0, 0.1), 1.0, Vec3(0, 0, -0.05)));
  Contact c = groundContact(1, Vec3::Zero(), box(0.5f, 0.5f, 0.5f, 0.5f));
  c.phi = -0.001;
  const auto out = solveOnce(bodies, {c}, settings(LimitSurfaceKind::Box));
  EXPECT_EQ(out[0].lambda_n, 0.0);
  EXPECT_EQ(bodies[1].linear_velocity.z(), -0.05);
}

}  // namespace
}  // namespace asperity
