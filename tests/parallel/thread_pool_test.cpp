#include "parallel/thread_pool.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/sampler/cpu_patch_sampler.hpp"
#include "asperity/scene/scene.hpp"
#include "asperity/world/builders.hpp"
#include "asperity/world/world.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

// Every item runs exactly once, whatever the split; slots stay inside the pool.
TEST(ThreadPool, RunsEveryItemOnceInItsSlots) {
  for (int threads : {1, 2, 4}) {
    const ThreadPool pool(threads);
    std::vector<std::atomic<int>> seen(1000);
    std::atomic<bool> slots_ok{true};
    pool.forEach(seen.size(), 7, [&](size_t i) {
      seen[i]++;
      const int slot = pool.slot();
      if (slot < 0 || slot >= pool.concurrency()) slots_ok = false;
    });
    for (const auto& s : seen) EXPECT_EQ(s.load(), 1);
    EXPECT_TRUE(slots_ok);
    EXPECT_EQ(pool.concurrency() == 1, threads == 1);
  }
  EXPECT_THROW(ThreadPool(-1), Error);
}

// A pool used from a thread of a larger arena (a world stepped in a sweep): items that run
// without the pool's arena still get a slot of the pool.
TEST(ThreadPool, SlotsStayInsideThePoolWithinAnotherArena) {
  const ThreadPool pool(2);
  tbb::task_arena outer(8);
  std::atomic<bool> slots_ok{true};
  outer.execute([&] {
    tbb::parallel_for(0, 64, [&](int) {
      pool.forEach(3, 7, [&](size_t) {  // few items: run inline
        const int slot = pool.slot();
        if (slot < 0 || slot >= pool.concurrency()) slots_ok = false;
      });
    });
  });
  EXPECT_TRUE(slots_ok);
}

// The state after each step is the same bits on 1, 2, 4 and 8 threads (SPEC 9).
uint64_t hashAfter(std::unique_ptr<World> world, int threads, int steps) {
  world->settings().threads = threads;
  for (int i = 0; i < steps; ++i) world->step();
  return world->stateHash();
}

std::unique_ptr<World> scene(const std::string& file) {
  return instantiate(loadScene(test::sourcePath("scenes/" + file)));
}

// A dropped pile of 200 cubes with textured friction: many islands, many contacts.
std::unique_ptr<World> pile() {
  auto world = std::make_unique<World>();
  BodyDesc ground = groundPlaneDesc();
  ground.shapes[0].surface.source.generator = {"concrete", {}, 64, 1};
  resolveSurfaces(ground.shapes, world->diagnostics());
  world->createBody(ground);
  addCubePile(*world, 200, 0.1, 8);
  world->setFrictionProvider(std::make_unique<CpuPatchSampler>());
  return world;
}

TEST(ThreadPool, StateHashDoesNotDependOnTheThreadCount) {
  struct Case {
    const char* name;
    std::unique_ptr<World> (*make)();
    int steps;
  };
  const Case cases[] = {
      {"stacking", [] { return scene("stacking.json"); }, 40},
      {"nut_bolt", [] { return scene("nut_bolt.json"); }, 40},
      {"pile", pile, 60},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const uint64_t one = hashAfter(c.make(), 1, c.steps);
    for (int threads : {2, 4, 8}) EXPECT_EQ(hashAfter(c.make(), threads, c.steps), one) << threads;
  }
}

TEST(ThreadPool, BadThreadCountNamesTheSetting) {
  World world;
  world.settings().threads = -3;
  try {
    world.step();
    FAIL() << "negative thread count accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("threads"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace asperity
