// A step allocates nothing once the world warmed up: contacts, the pair buffers of collision,
// the patch rasters and reuse decisions of the sampler, the solver's rows and limit surfaces
// all keep their room from step to step. Every allocation of this test program goes through
// the counting operator new below.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <new>
#include <string>

#include "asperity/scene/scene.hpp"
#include "asperity/world/world.hpp"
#include "support/test_support.hpp"

namespace {
std::atomic<long> g_allocations{0};

void* countedAllocation(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t size) {
  return countedAllocation(size);
}
void* operator new[](std::size_t size) {
  return countedAllocation(size);
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}

namespace asperity {
namespace {

class StepAllocations : public testing::TestWithParam<std::string> {};

TEST_P(StepAllocations, WarmedUpStepsAllocateNothing) {
  for (const int threads : {1, 2}) {
    SceneDesc scene = loadScene(test::sourcePath("scenes/" + GetParam() + ".json"));
    scene.settings.threads = threads;
    const std::unique_ptr<World> world = instantiate(scene);
    size_t most = 0;  // the most contacts a step has had
    for (int i = 0; i < 200; ++i) {
      world->step();
      most = std::max(most, world->contacts().size());
    }
    ASSERT_FALSE(world->contacts().empty());
    // A step that brings more contacts than any before may grow the buffers sized by them
    // (a stack still settling finds new corners); every other step allocates nothing.
    int checked = 0;
    for (int i = 0; i < 10; ++i) {
      const long before = g_allocations.load();
      world->step();
      const long allocations = g_allocations.load() - before;
      if (world->contacts().size() > most) {
        most = world->contacts().size();
        continue;
      }
      ++checked;
      EXPECT_EQ(allocations, 0) << threads << " threads, step " << 201 + i;
    }
    EXPECT_GE(checked, 5) << threads << " threads";
  }
}

// Box faces on textured slabs (cpu sampler, patch reuse), the nut's signed distance field,
// joints, the bolas' swept contacts, and sliding boxes.
INSTANTIATE_TEST_SUITE_P(Scenes, StepAllocations,
                         testing::Values("stacking", "nut_bolt", "crawling_worm",
                                         "chain_bolas_rough", "boxes_on_materials",
                                         "sawtooth_plane"),
                         [](const testing::TestParamInfo<std::string>& scene) {
                           return scene.param;
                         });

}  // namespace
}  // namespace asperity
