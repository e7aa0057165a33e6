// Scenes the Bullet adapter's tests share, built in code (z up, metres): a ground box with a
// surface and one body launched over it.
#pragma once

#include <string>

#include "asperity/scene/scene.hpp"
#include "asperity/world/builders.hpp"

namespace asperity::test {

// A static ground box (top face at z = 0) carrying `surface`, and `body` dropped onto it.
inline SceneDesc groundScene(const Surface& surface, BodyDesc body,
                             const std::string& sampler = "cpu") {
  SceneDesc scene;
  scene.friction_provider = sampler;
  BodyDesc ground = boxDesc("ground", Vec3(1.5, 1.5, 0.05), {Vec3(0, 0, -0.05), Quat::Identity()});
  ground.type = BodyType::Static;
  ground.shapes[0].surface = surface;
  scene.bodies.push_back(ground);
  scene.bodies.push_back(std::move(body));
  return scene;
}

// The sawtooth of the paper's plane (SPEC 7: gain 4, 1 cm period, ramps rising toward +x).
inline Surface sawtoothSurface() {
  Surface s;
  s.source.generator = {"sawtooth", {{"period", "16"}, {"axis", "0"}}, 128, 0};
  s.gain = 4.0;
  s.texture_size = 0.08;
  return s;
}

// A dynamic box of half extents `half` resting on z = 0 at (x, y).
inline BodyDesc restingBox(const std::string& name, const Vec3& half, double x = 0.0,
                           double y = 0.0) {
  return boxDesc(name, half, {Vec3(x, y, half.z()), Quat::Identity()});
}

}  // namespace asperity::test
