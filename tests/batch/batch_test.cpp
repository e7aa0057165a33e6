// Batches of worlds (SPEC 14): world i equals a World of sample i's scene given the same
// actions on any thread count, the sweep's draws, named bodies, resets that evolve as new
// worlds, and bad batches.
#include "asperity/batch/batch.hpp"

#include <gtest/gtest.h>

#include "asperity/error.hpp"
#include "batch/batch_scene.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::act;
using test::pushedBoxes;

// Hashes of a batch after `steps` steps of act()'s actions, from its current state.
std::vector<uint64_t> run(Batch& batch, int steps, int first = 0) {
  for (int s = first; s < first + steps; ++s) {
    act(batch, s);
    batch.step();
  }
  return batch.stateHashes();
}

TEST(Batch, WorldIIsTheWorldOfSampleIOnAnyThreadCount) {
  const int64_t n = 6;
  std::vector<std::vector<uint64_t>> hashes;
  for (int threads : {1, 2, 0}) {
    Batch batch(pushedBoxes(n, threads));
    hashes.push_back(run(batch, 40));
  }
  EXPECT_EQ(hashes[0], hashes[1]);
  EXPECT_EQ(hashes[0], hashes[2]);
  EXPECT_NE(hashes[0][0], hashes[0][1]);
  // The same worlds built and driven by hand.
  const Batch batch(pushedBoxes(n, 1));
  for (int64_t i = 0; i < n; ++i) {
    auto world = test::referenceWorld(batch.desc(), batch.values(i));
    for (int s = 0; s < 40; ++s) test::referenceStep(*world, n, i, s);
    EXPECT_EQ(world->stateHash(), hashes[0][static_cast<size_t>(i)]) << "world " << i;
  }
}

TEST(Batch, ValuesAreTheSweepsDraws) {
  const Batch batch(pushedBoxes(5, 2));
  SweepDesc sweep;
  sweep.scene_json = batch.desc().scene_json;
  sweep.vary = batch.desc().vary;
  sweep.samples = 5;
  sweep.seed = batch.desc().seed;
  const Sweep reference(sweep);
  for (int64_t i = 0; i < 5; ++i) {
    const std::span<const double> got = batch.values(i);
    EXPECT_EQ(std::vector<double>(got.begin(), got.end()), reference.values(i));
    EXPECT_EQ(batch.sample(i), i);
    EXPECT_EQ(batch.world(i).settings().threads, 1);
  }
}

TEST(Batch, NamesBodiesAndJointsInSceneOrder) {
  const Batch batch(pushedBoxes(2, 1));
  EXPECT_EQ(batch.bodyNames(), (std::vector<std::string>{"plate", "box", "tail", "finger"}));
  EXPECT_EQ(batch.jointNames(), (std::vector<std::string>{"tie", "pin"}));
  EXPECT_EQ(batch.bodyIndex("finger"), 3u);
  EXPECT_EQ(batch.jointIndex("pin"), 1u);
  EXPECT_EQ(test::errorOf([&] { batch.bodyIndex("ghost"); }),
            "no body named 'ghost' (bodies: plate, box, tail, finger)");
  EXPECT_NE(test::errorOf([&] { batch.jointIndex("rope"); }).find("no joint named 'rope'"),
            std::string::npos);
}

TEST(Batch, AResetWorldEvolvesAsANewOne) {
  Batch used(pushedBoxes(4, 2)), kept(pushedBoxes(4, 2));
  run(used, 30);
  run(kept, 30);
  // Worlds 0 and 2 start again; 1 and 3 go on.
  const std::vector<uint8_t> mask = {1, 0, 1, 0};
  used.reset(mask);
  Batch fresh(pushedBoxes(4, 1));
  const std::vector<uint64_t> after = run(used, 20), as_new = run(fresh, 20),
                              went_on = run(kept, 20, 30);
  EXPECT_EQ(after[0], as_new[0]);
  EXPECT_EQ(after[2], as_new[2]);
  // The others went on as if nothing happened (act() gives them the same actions every step).
  EXPECT_EQ(after[1], went_on[1]);
  EXPECT_EQ(after[3], went_on[3]);
  EXPECT_NE(after[1], as_new[1]);
  EXPECT_EQ(used.world(1).stepCount(), 50);
  EXPECT_EQ(used.world(0).stepCount(), 20);
}

TEST(Batch, AResetCanMakeAWorldAnotherSample) {
  Batch batch(pushedBoxes(3, 2));
  run(batch, 10);
  const std::vector<int64_t> samples = {7, 8, 9};
  batch.reset(std::vector<uint8_t>{0, 1, 0}, nullptr, samples);
  EXPECT_EQ(batch.sample(1), 8);
  EXPECT_EQ(batch.sample(0), 0);
  const Batch eight(pushedBoxes(9, 1));
  const std::span<const double> got = batch.values(1), want = eight.values(8);
  EXPECT_EQ(std::vector<double>(got.begin(), got.end()),
            std::vector<double>(want.begin(), want.end()));
  const std::vector<uint64_t> hashes = run(batch, 15);
  auto world = test::referenceWorld(batch.desc(), want);
  for (int s = 0; s < 15; ++s) test::referenceStep(*world, 3, 1, s);
  EXPECT_EQ(world->stateHash(), hashes[1]);
}

TEST(Batch, BadBatchesAndResetsAreRejectedNamingTheCulprit) {
  auto expectError = [](BatchDesc d, const std::string& part) {
    const std::string e = test::errorOf([&] { Batch batch(std::move(d)); });
    EXPECT_NE(e.find(part), std::string::npos) << e;
  };
  BatchDesc d = pushedBoxes(0, 1);
  expectError(d, "batch: n must be in 1..1000000, got 0");
  d = pushedBoxes(2, -1);
  expectError(d, "batch: threads must be in 0..");
  d = pushedBoxes(2, 1);
  d.vary.push_back(parseVariation("/settings/nope=uniform(0,1)"));
  expectError(d, "/settings/nope is not in the scene");
  d = pushedBoxes(3, 2);
  d.vary.push_back(parseVariation("/bodies/1/shapes/0/half_extents/0=uniform(-2,-1)"));
  expectError(d, "world 0: pushed_boxes.json: /bodies/1/shapes/0/half_extents/0");
  // Resets: sizes and sample indices, before any world changes.
  Batch batch(pushedBoxes(2, 1));
  EXPECT_EQ(test::errorOf([&] { batch.reset(std::vector<uint8_t>{1}); }),
            "reset: mask needs 2 entries, got 1");
  EXPECT_EQ(test::errorOf([&] {
              batch.reset({}, nullptr, std::vector<int64_t>{0, -3});
            }),
            "reset: samples[1] must be >= 0, got -3");
}

}  // namespace
}  // namespace asperity
