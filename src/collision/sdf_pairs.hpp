// The signed-distance path of the collision stage: a dynamic closed TriangleMesh (a nut,
// whose bore a convex hull would fill) against another closed mesh or a primitive (box,
// sphere, capsule, cylinder). Each side's surface sample points are queried against the
// other side's signed distance: a grid field for meshes, the exact distance for primitives.
#pragma once

#include <map>
#include <memory>
#include <vector>

#include "collision/collision_detector.hpp"
#include "collision/sdf_contacts.hpp"
#include "collision/shape_record.hpp"

namespace asperity::collision_detail {

// Whether a pair takes the signed-distance path (MeshPairMode::Auto).
bool isSdfPair(const ShapeRecord& x, const ShapeRecord& y);

// Fields and sample points, built on first use and shared by shapes with the same mesh.
class SdfResources {
 public:
  // New bodies: sample points are rebuilt; fields are kept unless the resolution changes.
  void reset(const CollisionSettings& settings);
  const SignedDistanceField& field(const ShapeRecord& r);
  const SurfaceSamples& samples(const ShapeRecord& r);
  // The queries' buffers (pairs are collected one after the other).
  SdfHitBuffers& hitBuffers() { return hit_buffers_; }

 private:
  CollisionSettings settings_;
  std::map<std::shared_ptr<const TriangleMeshData>, std::shared_ptr<const SignedDistanceField>>
      fields_;
  std::map<std::pair<BodyId, int>, SurfaceSamples> samples_;
  SdfHitBuffers hit_buffers_;
};

// Contacts of one signed-distance pair, appended to `out` (SPEC 1 conventions).
void sdfPairContacts(const ShapeRecord& x, const ShapeRecord& y, const CollisionSettings& settings,
                     SdfResources& resources, std::vector<Contact>& out);

}  // namespace asperity::collision_detail
