// Soak: every scene in scenes/ runs ASPERITY_SOAK_SECONDS of simulated time (2 s in the test
// suite; `make soak` runs 600) and must stay finite (World::step checks every step), keep
// every body inside the scene's bounds, and keep resting bodies at rest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "asperity/scene/scene.hpp"
#include "asperity/world/world.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

// Simulated seconds per scene: ASPERITY_SOAK_SECONDS, else a short run for `make test`.
double soakSeconds() {
  const char* text = std::getenv("ASPERITY_SOAK_SECONDS");
  return text != nullptr ? std::atof(text) : 2.0;
}

// The scene's bounds: the box around every body's starting position, grown by its largest
// side and at least 2 m each way (bodies slide, tumble and get thrown, but never that far).
// Along an axis that lies in a static plane the scene has no edge: a worm may crawl on for
// ever, but nothing may fall through the plane.
struct Bounds {
  Vec3 lo, hi;
  bool contains(const Vec3& p) const {
    return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
  }
};

Bounds sceneBounds(const World& world) {
  Bounds b{Vec3::Constant(1e300), Vec3::Constant(-1e300)};
  for (const Body& body : world.bodies()) {
    b.lo = b.lo.cwiseMin(body.pose.position);
    b.hi = b.hi.cwiseMax(body.pose.position);
  }
  const double grow = std::max(2.0, (b.hi - b.lo).maxCoeff());
  b.lo -= Vec3::Constant(grow);
  b.hi += Vec3::Constant(grow);
  for (const Body& body : world.bodies())
    for (const Shape& shape : body.shapes) {
      if (body.type != BodyType::Static || shape.type != ShapeType::Plane) continue;
      const Vec3 n = body.descriptionPose().rotation * (shape.local.rotation * shape.plane_normal);
      for (int axis = 0; axis < 3; ++axis)
        if (std::abs(n[axis]) < 1e-9) {
          b.lo[axis] = -std::numeric_limits<double>::infinity();
          b.hi[axis] = std::numeric_limits<double>::infinity();
        }
    }
  return b;
}

class Soak : public ::testing::TestWithParam<std::string> {};

TEST_P(Soak, StaysFiniteInBoundsAndAtRest) {
  const std::unique_ptr<World> world = instantiate(loadScene(test::sourcePath(GetParam())));
  const Bounds bounds = sceneBounds(*world);
  const double dt = world->settings().dt;
  const auto steps = static_cast<int64_t>(std::ceil(soakSeconds() / dt - 1e-9));
  const int64_t window = std::max<int64_t>(1, static_cast<int64_t>(std::round(1.0 / dt)));
  const size_t n = world->bodies().size();
  // Fastest speed of each body in the second before the last one, and in the last one.
  std::vector<double> before(n, 0.0), last(n, 0.0);
  for (int64_t i = 1; i <= steps; ++i) {
    // A NaN or runaway speed throws StepError naming the body and the step.
    ASSERT_NO_THROW(world->step()) << GetParam() << " at step " << i;
    for (BodyId id = 0; id < n; ++id) {
      const Body& body = world->body(id);
      if (!body.isDynamic()) continue;
      ASSERT_TRUE(bounds.contains(body.pose.position))
          << GetParam() << ": body '" << body.name
          << "' left the scene's bounds at t = " << world->time()
          << " s (z = " << body.pose.position.z() << " m)";
      const double speed = body.linear_velocity.norm();
      if (i > steps - 2 * window && i <= steps - window) before[id] = std::max(before[id], speed);
      if (i > steps - window) last[id] = std::max(last[id], speed);
    }
  }
  // A body that rested (under 1 cm/s) for a whole second does not wake up by itself.
  for (BodyId id = 0; id < n; ++id) {
    if (steps >= 2 * window && world->body(id).isDynamic() && before[id] < 0.01) {
      EXPECT_LT(last[id], 0.05) << GetParam() << ": resting body '" << world->body(id).name
                                << "' moved at " << last[id] << " m/s in the last second";
    }
  }
  std::printf("soak %s: %.0f s simulated, 0 NaN, all bodies in bounds\n", GetParam().c_str(),
              world->time());
}

INSTANTIATE_TEST_SUITE_P(Scenes, Soak, ::testing::ValuesIn(test::experimentScenes()),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           return std::filesystem::path(param.param).stem().string();
                         });

}  // namespace
}  // namespace asperity
