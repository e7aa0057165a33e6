// A box pushed at 1 m/s along +x and another along -x over a sawtooth plane (SPEC 7, Fig. 8):
// the patch sampler makes the ramps grip one way and the steep faces the other, so the two
// boxes stop after different distances. Exits 1 if they do not.
#include <asperity/asperity.hpp>

#include <cmath>
#include <cstdio>
#include <memory>

namespace {

// A 3 m slab whose top carries sawtooth ridges across x (texture repeat 8 cm, gain 4).
asperity::BodyDesc sawtoothSlab() {
  asperity::Shape slab;
  slab.type = asperity::ShapeType::Box;
  slab.half_extents = asperity::Vec3(1.5, 0.5, 0.05);
  slab.surface.source.generator = {"sawtooth", {{"period", "16"}, {"axis", "0"}}, 128, 1};
  slab.surface.gain = 4.0;
  slab.surface.texture_size = 0.08;
  asperity::BodyDesc desc;
  desc.name = "slab";
  desc.type = asperity::BodyType::Static;
  desc.pose.position = asperity::Vec3(0.0, 0.0, -0.05);
  desc.shapes.push_back(slab);
  return desc;
}

// Distance (m) a 20 cm box slides in 2 s after being pushed along x at `speed` (m/s).
double slideDistance(double speed) {
  asperity::World world;
  world.setFrictionProvider(std::make_unique<asperity::CpuPatchSampler>());
  // The world reads no files and runs no generators: surfaces are resolved first.
  asperity::BodyDesc slab = sawtoothSlab();
  asperity::resolveSurfaces(slab.shapes, world.diagnostics());
  world.createBody(slab);
  asperity::Transform start;
  start.position = asperity::Vec3(0.0, 0.0, 0.1);
  asperity::BodyDesc box = asperity::boxDesc("box", asperity::Vec3(0.1, 0.1, 0.1), start);
  box.linear_velocity = asperity::Vec3(speed, 0.0, 0.0);
  const asperity::BodyId id = world.createBody(box);
  while (world.time() < 2.0) world.step();
  return std::abs(world.body(id).pose.position.x());
}

}  // namespace

int main() {
  try {
    const double forward = slideDistance(1.0);
    const double backward = slideDistance(-1.0);
    std::printf("slide along +x: %.3f m\nslide along -x: %.3f m\n", forward, backward);
    const double ratio = std::max(forward, backward) / std::min(forward, backward);
    std::printf("ratio: %.2f\n", ratio);
    return ratio > 1.2 ? 0 : 1;
  } catch (const asperity::Error& e) {
    std::fprintf(stderr, "sawtooth_box: %s\n", e.what());
    return 1;
  }
}
