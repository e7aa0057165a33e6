// World -> RenderScene (see include/asperity/render/world_view.hpp).
#include "asperity/render/world_view.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace asperity::render {
namespace {

// Moller-Trumbore; returns the ray parameter or a negative number for a miss.
double rayTriangle(const Vec3& o, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = d.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < 1e-14) return -1.0;
  const double inv = 1.0 / det;
  const Vec3 s = o - a;
  const double u = s.dot(p) * inv;
  if (u < 0.0 || u > 1.0) return -1.0;
  const Vec3 q = s.cross(e1);
  const double v = d.dot(q) * inv;
  if (v < 0.0 || u + v > 1.0) return -1.0;
  return e2.dot(q) * inv;
}

Transform shapePose(const Body& body, const Shape& shape) {
  return body.pose * shape.local;
}

}  // namespace

Eigen::AlignedBox3d WorldView::focus(const World& world, const WorldViewOptions& options) {
  // Bounds of every non-plane shape's mesh, posed.
  Eigen::AlignedBox3d box;
  const auto bodies = world.bodies();
  for (BodyId id = 0; id < bodies.size(); ++id)
    for (int s = 0; s < static_cast<int>(bodies[id].shapes.size()); ++s) {
      const Shape& shape = bodies[id].shapes[static_cast<size_t>(s)];
      if (shape.type == ShapeType::Plane) continue;
      RenderItem item;
      item.mesh = meshFor(world, id, s, options);
      item.pose = shapePose(bodies[id], shape);
      box.extend(itemBounds(item));
    }
  return box;
}

std::shared_ptr<const ShapeMesh> WorldView::meshFor(const World& world, BodyId body, int shape,
                                                    const WorldViewOptions& options) {
  auto& slot = meshes_[{body, shape}];
  if (slot) return slot;
  const Shape& s = world.bodies()[body].shapes[static_cast<size_t>(shape)];
  ShapeMeshOptions mesh_options;
  mesh_options.segments = options.segments;
  mesh_options.rings = std::max(2, options.segments / 2);
  // Planes: a square ground around the focus, large enough to reach the fog.
  if (s.type == ShapeType::Plane) {
    mesh_options.plane_size = ground_size_;
    mesh_options.plane_centre =
        s.local.applyInverse(world.bodies()[body].pose.applyInverse(ground_centre_));
  }
  // An asset shows its full mesh, whatever hull or simplified mesh it collides with.
  if (s.display_mesh) {
    Shape shown = s;
    shown.type = ShapeType::TriangleMesh;
    shown.mesh = s.display_mesh;
    slot = std::make_shared<const ShapeMesh>(buildShapeMesh(shown, mesh_options));
  } else {
    slot = std::make_shared<const ShapeMesh>(buildShapeMesh(s, mesh_options));
  }
  return slot;
}

void WorldView::update(const World& world, const WorldViewOptions& options, RenderScene& scene) {
  scene.items.clear();
  scene.debug.clear();
  scene.focus = focus(world, options);
  const Eigen::AlignedBox3d f = scene.focus.isEmpty()
                                    ? Eigen::AlignedBox3d(Vec3::Constant(-0.5), Vec3::Constant(0.5))
                                    : scene.focus;
  // The ground follows the focus when it has moved far (a body shot away).
  const double radius = std::max(0.5 * f.diagonal().norm(), 0.1);
  const double size = std::max(20.0, 40.0 * radius);
  if (ground_size_ == 0.0 || (f.center() - ground_centre_).norm() > 0.25 * ground_size_ ||
      size > 1.5 * ground_size_) {
    ground_centre_ = f.center();
    ground_size_ = size;
    // Plane meshes depend on the ground square: rebuild them.
    std::erase_if(meshes_, [&](const auto& entry) {
      const Body& body = world.bodies()[entry.first.first];
      return body.shapes[static_cast<size_t>(entry.first.second)].type == ShapeType::Plane;
    });
  }
  scene.scene_radius = 0.5 * ground_size_;
  // One item per shape of every body.
  const auto bodies = world.bodies();
  for (BodyId id = 0; id < bodies.size(); ++id)
    for (int s = 0; s < static_cast<int>(bodies[id].shapes.size()); ++s) {
      const Shape& shape = bodies[id].shapes[static_cast<size_t>(s)];
      RenderItem item;
      item.mesh = meshFor(world, id, s, options);
      item.pose = shapePose(bodies[id], shape);
      item.normal_map = shape.surface.normal_map;
      item.base_color = shape.surface.base_color;
      item.base_color_texture = shape.surface.base_color_texture;
      item.ground = shape.type == ShapeType::Plane;
      item.highlight = id == options.highlight;
      item.id = id;
      scene.items.push_back(std::move(item));
    }
  // Debug layers of the last step.
  if (options.debug.layers != 0) appendWorldLayers(world, options.debug, scene.debug);
}

Camera WorldView::defaultCamera(const World& world, double aspect) {
  const Eigen::AlignedBox3d f = focus(world, {});
  return frameBox(f, aspect, std::max(20.0, 40.0 * 0.5 * f.diagonal().norm()) * 0.5);
}

std::optional<PickHit> WorldView::pick(const World& world, const Vec3& origin,
                                       const Vec3& direction, bool dynamic_only) {
  std::optional<PickHit> best;
  const auto bodies = world.bodies();
  // Every triangle of every candidate body's meshes, in world space.
  for (BodyId id = 0; id < bodies.size(); ++id) {
    if (dynamic_only && !bodies[id].isDynamic()) continue;
    for (int s = 0; s < static_cast<int>(bodies[id].shapes.size()); ++s) {
      const Shape& shape = bodies[id].shapes[static_cast<size_t>(s)];
      if (shape.type == ShapeType::Plane) continue;
      const ShapeMesh& mesh = *meshFor(world, id, s, {});
      const Transform pose = shapePose(bodies[id], shape);
      for (const auto& t : mesh.triangles) {
        const double hit = rayTriangle(
            origin, direction, pose.apply(mesh.positions[static_cast<size_t>(t[0])].cast<double>()),
            pose.apply(mesh.positions[static_cast<size_t>(t[1])].cast<double>()),
            pose.apply(mesh.positions[static_cast<size_t>(t[2])].cast<double>()));
        if (hit > 0.0 && (!best || hit < best->distance))
          best = PickHit{id, origin + hit * direction, hit};
      }
    }
  }
  return best;
}

RenderScene renderWorld(const World& world, const WorldViewOptions& options) {
  WorldView view;
  RenderScene scene;
  view.update(world, options, scene);
  return scene;
}

}  // namespace asperity::render
