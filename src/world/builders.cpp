// Small scene builders shared by tests, benchmarks and examples.
#include "asperity/world/builders.hpp"

#include <cmath>

namespace asperity {

BodyDesc groundPlaneDesc(const Vec3& normal, const Vec3& point) {
  BodyDesc d;
  d.name = "ground";
  d.type = BodyType::Static;
  Shape plane;
  plane.type = ShapeType::Plane;
  plane.plane_normal = normal.normalized();
  plane.plane_offset = plane.plane_normal.dot(point);
  d.shapes.push_back(plane);
  return d;
}

BodyDesc boxDesc(const std::string& name, const Vec3& half, const Transform& pose, double density) {
  BodyDesc d;
  d.name = name;
  d.pose = pose;
  Shape box;
  box.type = ShapeType::Box;
  box.half_extents = half;
  box.density = density;
  d.shapes.push_back(box);
  return d;
}

std::vector<BodyId> addCubeStack(World& world, const std::string& prefix, double x, double y,
                                 int count, double size, double density) {
  std::vector<BodyId> ids;
  const Vec3 half = Vec3::Constant(0.5 * size);
  for (int i = 0; i < count; ++i) {
    const Transform pose{Vec3(x, y, 0.5 * size + i * size), Quat::Identity()};
    ids.push_back(world.createBody(boxDesc(prefix + std::to_string(i), half, pose, density)));
  }
  return ids;
}

std::vector<BodyId> addCubePile(World& world, int count, double size, int per_layer) {
  std::vector<BodyId> ids;
  const double spacing = 1.5 * size;
  const double extent = spacing * (per_layer - 1);
  for (int i = 0; i < count; ++i) {
    const int layer = i / (per_layer * per_layer);
    const int cell = i % (per_layer * per_layer);
    // Odd layers sit half a cube off, so the pile settles into a heap.
    const double shift = (layer % 2) * 0.5 * size;
    const Vec3 p(-0.5 * extent + spacing * (cell % per_layer) + shift,
                 -0.5 * extent + spacing * (cell / per_layer) + shift,
                 0.5 * size + 0.01 * size + layer * 1.1 * size);
    ids.push_back(world.createBody(
        boxDesc("cube" + std::to_string(i), Vec3::Constant(0.5 * size), {p, Quat::Identity()})));
  }
  return ids;
}

}  // namespace asperity
