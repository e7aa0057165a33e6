// What the collision stage keeps per shape: one Bullet collision object per shape of a body,
// its pose this call, and what the exact contact paths need. Private to src/collision.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "asperity/collision/contact.hpp"
#include "collision/bullet_shapes.hpp"

namespace asperity::collision_detail {

struct ShapeRecord {
  BodyId body = kNoBody;
  int index = -1;  // into the body's shapes
  BodyType body_type = BodyType::Dynamic;
  Shape shape;
  BulletShape bullet;
  std::unique_ptr<btCollisionObject> object;
  bool closed_mesh = false;       // a TriangleMesh bounding a volume (signed distance path)
  std::vector<Vec4> hull_planes;  // outward unit normal and offset per face (hull shapes)
  Transform world;                // shape frame in world, this call
  Mat3 axes;                      // boxes: world.rotation as a matrix (face normals), this call
  double bounding_radius = 0.0;   // boundingRadius(shape) (m)
  double size = 0.0;              // shapeSize(shape) (m)
  Vec3 velocity = Vec3::Zero();   // of the shape frame's origin, this call (m/s)
  double angular_speed = 0.0;     // |w| of the body, this call (rad/s)
};

// SPEC 1 and collision_detector.hpp: the dynamic body is A against a static or kinematic one,
// otherwise the lower id.
inline bool isA(const ShapeRecord& x, const ShapeRecord& y) {
  const bool xd = x.body_type == BodyType::Dynamic, yd = y.body_type == BodyType::Dynamic;
  if (xd != yd) return xd;
  return x.body < y.body;
}

// splitmix64 finaliser over a running combination: keys that differ in any field differ.
inline uint64_t mixKey(uint64_t h, uint64_t v) {
  h ^= v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
  h ^= h >> 30, h *= 0xbf58476d1ce4e5b9ull;
  h ^= h >> 27, h *= 0x94d049bb133111ebull;
  return h ^ (h >> 31);
}

// A contact's key from its bodies, shapes and an id of the point within the pair.
inline uint64_t contactKey(const Contact& c, uint64_t point_id) {
  uint64_t h = mixKey(0, c.body_a);
  h = mixKey(h, c.body_b);
  h = mixKey(h, static_cast<uint64_t>(static_cast<uint32_t>(c.shape_a)));
  h = mixKey(h, static_cast<uint64_t>(static_cast<uint32_t>(c.shape_b)));
  return mixKey(h, point_id);
}

// Tags keeping the point ids of the contact paths apart.
inline constexpr uint64_t kPlanePointTag = uint64_t{1} << 61;
inline constexpr uint64_t kSdfPointTag = uint64_t{1} << 62;
inline constexpr uint64_t kSweptPointTag = uint64_t{1} << 60;
inline constexpr uint64_t kCylinderPointTag = uint64_t{1} << 59;

}  // namespace asperity::collision_detail
