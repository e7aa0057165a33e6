// Restarting from a state (World::forgetContactHistory): two worlds set to the same body states
// evolve bit for bit alike, whatever each did before; without forgetting, they do not.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "asperity/scene/scene.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

struct BodyState {
  Transform pose;
  Vec3 linear_velocity, angular_velocity;
};

std::unique_ptr<World> load(const std::string& scene, double reuse_pixels = 0.0) {
  SceneDesc desc = loadScene(test::sourcePath("scenes/" + scene));
  desc.settings.friction.reuse_pixels = reuse_pixels;
  return instantiate(desc);
}

std::vector<BodyState> stateOf(const World& world) {
  std::vector<BodyState> out;
  for (const Body& b : world.bodies())
    out.push_back({b.pose, b.linear_velocity, b.angular_velocity});
  return out;
}

void setState(World& world, const std::vector<BodyState>& state, bool forget) {
  for (BodyId i = 0; i < state.size(); ++i) {
    world.body(i).pose = state[i].pose;
    world.body(i).linear_velocity = state[i].linear_velocity;
    world.body(i).angular_velocity = state[i].angular_velocity;
  }
  if (forget) world.forgetContactHistory();
}

void steps(World& world, int n) {
  for (int k = 0; k < n; ++k) world.step();
}

// The state after `at` steps of `scene`, restarted in a new world and in one that ran `before`
// steps of its own first: the hashes after `after` more steps.
std::pair<uint64_t, uint64_t> restartedTwice(const std::string& scene, int at, int before,
                                             int after, bool forget, double reuse_pixels = 0.0) {
  auto source = load(scene, reuse_pixels);
  steps(*source, at);
  const std::vector<BodyState> state = stateOf(*source);
  auto fresh = load(scene, reuse_pixels);
  setState(*fresh, state, forget);
  auto used = load(scene, reuse_pixels);
  steps(*used, before);
  setState(*used, state, forget);
  steps(*fresh, after);
  steps(*used, after);
  return {fresh->stateHash(), used->stateHash()};
}

TEST(Restart, SlidingBoxesWithTexturedFrictionRestartAlike) {
  // boxes_on_materials: four boxes sliding on the cpu sampler; with patch reuse on as well.
  for (const double reuse : {0.0, 0.1}) {
    const auto [fresh, used] = restartedTwice("boxes_on_materials.json", 60, 23, 100, true, reuse);
    EXPECT_EQ(fresh, used) << "reuse_pixels " << reuse;
  }
}

TEST(Restart, AJointedChainRestartsAlike) {
  // chain_draped_rough: joints (their warm-start impulses) and contacts on a rod.
  const auto [fresh, used] = restartedTwice("chain_draped_rough.json", 80, 37, 120, true);
  EXPECT_EQ(fresh, used);
}

TEST(Restart, WithoutForgettingTheHistoryDecides) {
  // The same restart keeping each world's contact points and warm starts: the worlds part.
  const auto [fresh, used] = restartedTwice("boxes_on_materials.json", 60, 23, 100, false);
  EXPECT_NE(fresh, used);
}

}  // namespace
}  // namespace asperity
