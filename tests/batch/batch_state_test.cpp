// A batch's state arrays: each world's bodies in the scene's frame, resets to a given state
// equal to a World set to that state with its history forgotten, and bad states.
#include <gtest/gtest.h>

#include "asperity/batch/batch.hpp"
#include "asperity/error.hpp"
#include "batch/batch_scene.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::pushedBoxes;

// Row (i, b) of a state array of width W.
std::vector<double> row(const std::vector<double>& a, size_t bodies, size_t i, size_t b,
                        size_t width) {
  const auto begin = a.begin() + static_cast<std::ptrdiff_t>((i * bodies + b) * width);
  return std::vector<double>(begin, begin + static_cast<std::ptrdiff_t>(width));
}

TEST(BatchState, RowsAreEachWorldsBodiesInTheScenesFrame) {
  Batch batch(pushedBoxes(3, 2));
  test::act(batch, 0);
  batch.step(12);
  const BatchState& s = batch.state();
  const size_t bodies = batch.bodyNames().size();
  for (size_t i = 0; i < 3; ++i) {
    for (size_t b = 0; b < bodies; ++b) {
      const Body& body = batch.world(static_cast<int64_t>(i)).bodies()[b];
      const Transform pose = body.descriptionPose();
      const Vec3 v = body.pointVelocity(pose.position);
      const Quat& q = pose.rotation;
      EXPECT_EQ(row(s.positions, bodies, i, b, 3),
                (std::vector<double>{pose.position.x(), pose.position.y(), pose.position.z()}));
      EXPECT_EQ(row(s.orientations, bodies, i, b, 4),
                (std::vector<double>{q.w(), q.x(), q.y(), q.z()}));
      EXPECT_EQ(row(s.linear_velocities, bodies, i, b, 3),
                (std::vector<double>{v.x(), v.y(), v.z()}));
      EXPECT_EQ(row(s.angular_velocities, bodies, i, b, 3),
                (std::vector<double>{body.angular_velocity.x(), body.angular_velocity.y(),
                                     body.angular_velocity.z()}));
    }
  }
  // The box moved: the rows follow the steps.
  EXPECT_GT(std::abs(s.positions[1 * 3]), 1e-3);
}

TEST(BatchState, AResetToAGivenStateIsAWorldSetToIt) {
  const int64_t n = 3;
  Batch batch(pushedBoxes(n, 2));
  const BatchState initial = batch.state();
  test::act(batch, 0);
  batch.step(25);
  // World 1 to a state of its own: the box moved and turned; velocities as the scene's.
  BatchState given;
  given.positions = initial.positions;
  given.orientations = initial.orientations;
  const size_t box = (1 * 4 + 1);
  given.positions[box * 3] = 0.4;
  given.orientations[box * 4] = std::cos(0.3), given.orientations[box * 4 + 3] = std::sin(0.3);
  given.orientations[box * 4 + 1] = given.orientations[box * 4 + 2] = 0.0;
  batch.reset(std::vector<uint8_t>{0, 1, 0}, &given);
  // By hand: the scene's world, the box put there, its history forgotten.
  auto world = test::referenceWorld(batch.desc(), batch.values(1));
  Body& b = world->body(1);
  b.pose.position = Vec3(0.4, given.positions[box * 3 + 1], given.positions[box * 3 + 2]);
  b.pose.rotation = Quat(std::cos(0.3), 0, 0, std::sin(0.3)).normalized();
  world->forgetContactHistory();
  EXPECT_EQ(world->stateHash(), batch.stateHashes()[1]);
  for (int s = 0; s < 20; ++s) {
    test::act(batch, s);
    batch.step();
    test::referenceStep(*world, n, 1, s);
  }
  EXPECT_EQ(world->stateHash(), batch.stateHashes()[1]);
  // The parts not given are the scene's: the box's start velocity as drawn.
  EXPECT_EQ(batch.world(1).stepCount(), 20);
}

TEST(BatchState, BadStatesAreRejectedBeforeAnyWorldChanges) {
  Batch batch(pushedBoxes(2, 1));
  batch.step(3);
  const std::vector<uint64_t> before = batch.stateHashes();
  const std::vector<uint8_t> second = {0, 1};
  auto error = [&](const BatchState& s) { return test::errorOf([&] { batch.reset(second, &s); }); };
  BatchState s;
  s.positions.assign(5, 0.0);
  EXPECT_EQ(error(s), "reset: positions needs 24 numbers (n x 4 x 3), got 5");
  s.positions = batch.state().positions;
  s.positions[4 * 3 + 2] = std::nan("");
  EXPECT_EQ(error(s), "reset: positions of world 1 is not finite");
  s = BatchState();
  s.orientations = batch.state().orientations;
  std::fill(s.orientations.begin() + 4 * 4 + 8, s.orientations.begin() + 4 * 4 + 12, 0.0);
  EXPECT_EQ(error(s), "reset: orientations of world 1 body 2 is a zero quaternion");
  EXPECT_EQ(batch.stateHashes(), before);
  // Rows of worlds not reset are not read.
  s = BatchState();
  s.linear_velocities.assign(24, 0.0);
  s.linear_velocities[0] = std::nan("");
  batch.reset(second, &s);
  EXPECT_EQ(batch.stateHashes()[0], before[0]);
}

}  // namespace
}  // namespace asperity
