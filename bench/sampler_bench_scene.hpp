// The scene both patch-sampler benchmarks measure (SPEC 3): a stone-textured plane (gain 2)
// and `count` contacts at the bottom corners of oak-textured 0.2 m boxes resting on it, in rows
// of 100 and each turned a little more about z (phi = 0.1 mm, world frame). A quarter of every
// patch is covered by both surfaces.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "asperity/collision/contact.hpp"
#include "asperity/dynamics/body.hpp"
#include "asperity/texture/generators.hpp"

namespace asperity::bench {

struct SamplerScene {
  std::vector<Body> bodies;  // bodies[0] is the plane
  std::vector<Contact> contacts;
};

// A 256 x 256 normal map from the named generator with its default parameters.
inline std::shared_ptr<const NormalMap> material(const std::string& name) {
  GeneratorSpec spec;
  spec.name = name;
  spec.size = 256;
  return std::make_shared<NormalMap>(generateNormalMap(spec));
}

// The static plane z = 0 with the stone texture, 0.25 m per repeat.
inline Body texturedPlane() {
  Body b;
  b.type = BodyType::Static;
  Shape s;
  s.type = ShapeType::Plane;
  s.surface.normal_map = material("stone");
  s.surface.texture_size = 0.25;
  s.surface.gain = 2.0;
  b.shapes.push_back(s);
  return b;
}

inline SamplerScene boxesOnPlane(int count) {
  SamplerScene scene;
  scene.bodies.push_back(texturedPlane());
  const auto oak = material("oak");
  const int boxes = (count + 3) / 4;
  for (int i = 0; i < boxes; ++i) {
    Body b;
    b.pose.position = Vec3(0.3 * (i % 100), 0.3 * (i / 100), 0.1 - 1e-4);
    b.pose.rotation = Quat(Eigen::AngleAxisd(0.1 * i, Vec3::UnitZ()));
    Shape s;
    s.type = ShapeType::Box;
    s.half_extents = Vec3(0.1, 0.1, 0.1);
    s.surface.normal_map = oak;
    s.surface.gain = 2.0;
    b.shapes.push_back(s);
    scene.bodies.push_back(b);
    for (int k = 0; k < 4 && static_cast<int>(scene.contacts.size()) < count; ++k) {
      Contact c;
      c.body_a = static_cast<BodyId>(i + 1);
      c.body_b = 0;
      c.shape_a = c.shape_b = 0;
      const Vec3 corner(k & 1 ? 0.1 : -0.1, k & 2 ? 0.1 : -0.1, -0.1);
      c.point = b.pose.apply(corner) + Vec3(0, 0, 0.5e-4);
      c.phi = 1e-4;
      c.normal = Vec3::UnitZ();
      c.t = Vec3::UnitX();
      c.b = Vec3::UnitY();
      scene.contacts.push_back(c);
    }
  }
  return scene;
}

}  // namespace asperity::bench
