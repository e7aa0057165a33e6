// Bullet shapes from asperity shapes (see bullet_shapes.hpp).
#include "collision/bullet_shapes.hpp"

#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <LinearMath/btConvexHullComputer.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "asperity/error.hpp"

namespace asperity::collision_detail {

namespace {

Vec3 meshExtent(const TriangleMeshData& mesh) {
  if (mesh.vertices.empty()) return Vec3::Zero();
  Vec3 lo = mesh.vertices.front(), hi = lo;
  for (const Vec3& v : mesh.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  return hi - lo;
}

std::string meshName(const Shape& shape) {
  return shape.mesh && !shape.mesh->source_file.empty() ? " '" + shape.mesh->source_file + "'"
                                                        : std::string();
}

// The convex hull of the points, with polyhedral features for face clipping against boxes
// and hulls (exact); Bullet's other convex algorithms see it grown by its margin.
std::unique_ptr<btCollisionShape> makeHull(const Shape& shape, double margin) {
  if (!shape.mesh || shape.mesh->vertices.size() < 4) {
    throw Error("collision: convex hull" + meshName(shape) + " needs at least 4 points");
  }
  std::vector<double> coords;
  coords.reserve(shape.mesh->vertices.size() * 3);
  for (const Vec3& v : shape.mesh->vertices) coords.insert(coords.end(), {v.x(), v.y(), v.z()});
  btConvexHullComputer hull;
  const int count = static_cast<int>(shape.mesh->vertices.size());
  if (hull.compute(coords.data(), 3 * sizeof(double), count, 0, 0) < 0 ||
      hull.vertices.size() < 4 || hull.faces.size() < 4) {
    throw Error("collision: convex hull" + meshName(shape) + " is flat or degenerate");
  }
  auto out = std::make_unique<btConvexHullShape>();
  for (int i = 0; i < hull.vertices.size(); ++i) out->addPoint(hull.vertices[i], false);
  out->recalcLocalAabb();
  out->setMargin(static_cast<btScalar>(margin));
  out->initializePolyhedralFeatures();
  return out;
}

// A static BVH over the mesh's triangles; the arrays live in `out`.
void makeStaticMesh(const Shape& shape, double size, BulletShape& out) {
  const TriangleMeshData& mesh = *shape.mesh;
  out.vertices.reserve(mesh.vertices.size() * 3);
  for (const Vec3& v : mesh.vertices) {
    out.vertices.insert(out.vertices.end(), {static_cast<float>(v.x()), static_cast<float>(v.y()),
                                             static_cast<float>(v.z())});
  }
  const int vertex_count = static_cast<int>(mesh.vertices.size());
  for (const auto& tri : mesh.triangles) {
    for (int i : tri) {
      if (i < 0 || i >= vertex_count) {
        throw Error("collision: mesh" + meshName(shape) + " has a vertex index out of range");
      }
      out.indices.push_back(i);
    }
  }
  out.mesh_interface = std::make_unique<btTriangleIndexVertexArray>(
      static_cast<int>(mesh.triangles.size()), out.indices.data(),
      3 * static_cast<int>(sizeof(int)), vertex_count, out.vertices.data(),
      3 * static_cast<int>(sizeof(float)));
  auto bvh = std::make_unique<btBvhTriangleMeshShape>(out.mesh_interface.get(), true);
  // Triangles grow outward by their margin: keep it a small fraction of the mesh.
  bvh->setMargin(static_cast<btScalar>(0.05 * marginFor(size)));
  out.shape = std::move(bvh);
}

}  // namespace

btTransform toBt(const Transform& t) {
  const Quat q = t.rotation.normalized();
  return btTransform(btQuaternion(static_cast<btScalar>(q.x()), static_cast<btScalar>(q.y()),
                                  static_cast<btScalar>(q.z()), static_cast<btScalar>(q.w())),
                     toBt(t.position));
}

double bulletScale(std::span<const Body> bodies) {
  double smallest = 0.0;
  for (const Body& body : bodies) {
    if (body.type != BodyType::Dynamic) continue;
    for (const Shape& shape : body.shapes) {
      const double size = shapeSize(shape);
      if (size > 0 && (smallest == 0 || size < smallest)) smallest = size;
    }
  }
  double scale = 1.0;
  while (smallest > 0 && smallest * scale < 0.2 && scale < 1e6) scale *= 2;
  return scale;
}

Shape scaledShape(const Shape& shape, double scale) {
  if (scale == 1.0) return shape;
  Shape out = shape;
  out.local.position *= scale;
  out.half_extents *= scale;
  out.radius *= scale;
  out.half_height *= scale;
  out.plane_offset *= scale;
  if (shape.mesh) {
    auto mesh = std::make_shared<TriangleMeshData>(*shape.mesh);
    for (Vec3& v : mesh->vertices) v *= scale;
    out.mesh = std::move(mesh);
  }
  return out;
}

btTransform toBt(const Transform& t, double scale) {
  return toBt(Transform{t.position * scale, t.rotation});
}

double boundingRadius(const Shape& shape) {
  switch (shape.type) {
    case ShapeType::Box:
      return shape.half_extents.norm();
    case ShapeType::Sphere:
      return shape.radius;
    case ShapeType::Capsule:
      return shape.radius + shape.half_height;
    case ShapeType::Cylinder:
      return std::hypot(shape.radius, shape.half_height);
    case ShapeType::Plane:
      return 0.0;
    case ShapeType::ConvexHull:
    case ShapeType::TriangleMesh: {
      // The farthest vertex from the shape's origin.
      double r2 = 0.0;
      if (shape.mesh)
        for (const Vec3& v : shape.mesh->vertices) r2 = std::max(r2, v.squaredNorm());
      return std::sqrt(r2);
    }
  }
  return 0.0;
}

double shapeSize(const Shape& shape) {
  switch (shape.type) {
    case ShapeType::Box:
      return 2.0 * shape.half_extents.minCoeff();
    case ShapeType::Sphere:
    case ShapeType::Capsule:
      return 2.0 * shape.radius;
    case ShapeType::Cylinder:
      return 2.0 * std::min(shape.radius, shape.half_height);
    case ShapeType::Plane:
      return 1.0;
    case ShapeType::ConvexHull:
    case ShapeType::TriangleMesh: {
      if (!shape.mesh) return 0.0;
      const Vec3 e = meshExtent(*shape.mesh);
      // A flat mesh (a ground made of triangles) uses its smallest non-zero extent.
      double smallest = e.maxCoeff();
      for (int a = 0; a < 3; ++a) {
        if (e[a] > 1e-9 * e.maxCoeff()) smallest = std::min(smallest, e[a]);
      }
      return smallest;
    }
  }
  return 0.0;
}

double marginFor(double size) {
  return std::min(0.04, 0.02 * size);
}

void BoxPolyhedra::apply(btBoxShape& box) {
  const btVector3 half = box.getHalfExtentsWithoutMargin();
  auto& made = made_[{half.x(), half.y(), half.z(), box.getMargin()}];
  if (made) {
    box.setPolyhedralFeatures(*made);
    return;
  }
  box.initializePolyhedralFeatures();
  made = std::make_unique<btConvexPolyhedron>(*box.getConvexPolyhedron());
}

BulletShape makeBulletShape(const Shape& shape, BodyType body_type, BoxPolyhedra* boxes) {
  BulletShape out;
  const double size = shapeSize(shape);
  const auto margin = static_cast<btScalar>(marginFor(size));
  switch (shape.type) {
    case ShapeType::Box: {
      // Box margins lie inside the box: the corners stay exact.
      auto box = std::make_unique<btBoxShape>(toBt(shape.half_extents));
      box->setMargin(margin);
      if (boxes) {
        boxes->apply(*box);
      } else {
        box->initializePolyhedralFeatures();
      }
      out.shape = std::move(box);
      break;
    }
    case ShapeType::Sphere:
      out.shape = std::make_unique<btSphereShape>(static_cast<btScalar>(shape.radius));
      break;
    case ShapeType::Capsule:
      out.shape = std::make_unique<btCapsuleShapeZ>(static_cast<btScalar>(shape.radius),
                                                    static_cast<btScalar>(2 * shape.half_height));
      break;
    case ShapeType::Cylinder: {
      auto cylinder = std::make_unique<btCylinderShapeZ>(
          btVector3(static_cast<btScalar>(shape.radius), static_cast<btScalar>(shape.radius),
                    static_cast<btScalar>(shape.half_height)));
      cylinder->setMargin(margin);
      out.shape = std::move(cylinder);
      break;
    }
    case ShapeType::Plane:
      if (body_type == BodyType::Dynamic) {
        throw Error("collision: a plane shape needs a static or kinematic body");
      }
      out.shape = std::make_unique<btStaticPlaneShape>(toBt(shape.plane_normal.normalized()),
                                                       static_cast<btScalar>(shape.plane_offset));
      break;
    case ShapeType::ConvexHull:
      out.shape = makeHull(shape, marginFor(size));
      break;
    case ShapeType::TriangleMesh:
      if (!shape.mesh || shape.mesh->triangles.empty()) {
        throw Error("collision: triangle mesh" + meshName(shape) + " has no triangles");
      }
      // Dynamic concave meshes collide as their convex hull (SDF pairs aside).
      if (body_type == BodyType::Dynamic) {
        out.shape = makeHull(shape, marginFor(size));
      } else {
        makeStaticMesh(shape, size, out);
      }
      break;
  }
  return out;
}

}  // namespace asperity::collision_detail
