// The faces of a contact's shapes in the contact frame, as both patch samplers see them: box
// faces, planes and mesh triangles with uv and tangent frames. The CPU rasteriser
// (patch_geometry.cpp) and the GL sampler's triangles (patch_triangles.cpp) both build their
// primitives from these, so the two samplers cannot drift apart.
#pragma once

#include <array>

#include "asperity/geometry/shape_mesh.hpp"
#include "geometry/bvh.hpp"
#include "sampler/patch_raster.hpp"

namespace asperity::patch {

// Where the shape frame sits in the contact frame: p_c = m p_local + o.
struct Placement {
  Mat3 m;
  Vec3 o;
};
Placement place(const Volume& volume, const Transform& pose);

// A fragment of `side` is kept only if the geometric normal faces the other body (SPEC 3).
inline bool facesOther(Side side, double normal_z) {
  return side == Side::B ? normal_z > 0.0 : normal_z < 0.0;
}

// A corner of a face in the contact frame: position (relative to the contact point), uv in
// texture repeats, and the tangent frame.
struct FaceCorner {
  Vec3 p;
  double u = 0.0, v = 0.0;
  Vec3 t, b, n;
};

// One face of a box: its frame, centre and edge half-vectors in the box frame, and its outward
// normal in the contact frame.
struct BoxFace {
  SurfaceFrame frame;
  Vec3 centre, et, eb;
  Vec3 normal;
};

// The faces of a box shape that face the other body, in face order (boxFaceFrame); returns
// how many of `out` are set.
int facingBoxFaces(const Shape& box, const Placement& pl, Side side, std::array<BoxFace, 6>& out);

// A box face's four corners' positions (contact frame), counter-clockwise seen from outside
// the box.
std::array<Vec3, 4> boxFacePositions(const Placement& pl, const BoxFace& face);
// The same corners (`positions` from boxFacePositions) with uv (`scale` repeats per metre, the
// surface's texture rotation) and the face's tangent frame.
std::array<FaceCorner, 4> boxFaceCorners(const Shape& box, const Placement& pl, const BoxFace& face,
                                         double scale, const std::array<Vec3, 4>& positions);

// A plane shape {n . x = offset} that faces the other body, in the contact frame.
struct FacingPlane {
  Vec3 local_normal;     // unit, shape frame
  Vec3 normal;           // contact frame
  Vec3 point;            // the plane's point nearest the shape origin, contact frame
  SurfaceFrame texture;  // shape frame, rotated by the surface's texture rotation
  Vec3 t, b;             // texture.t and texture.b in the contact frame
  double scale = 1.0;    // texture repeats per metre
};
// False when the plane faces away from the other body or is seen edge-on. Throws
// asperity::Error for a zero plane_normal.
bool facingPlane(const Shape& plane, const Placement& pl, Side side, FacingPlane& out);

// The viewing volume's box in the shape frame: the candidate triangles of a shape's BVH are
// those whose boxes overlap it.
Aabb volumeBoxInShape(const Volume& volume, const Placement& pl);

// The corners of a mesh triangle in the contact frame, with the mesh's uv and frames.
std::array<FaceCorner, 3> meshTriangleCorners(const ShapeMesh& mesh, int triangle,
                                              const Placement& pl);

// Whether a triangle's corners, wound counter-clockwise seen from outside, face the other body.
inline bool triangleFacesOther(Side side, const std::array<FaceCorner, 3>& c) {
  const Vec3 e1 = c[1].p - c[0].p, e2 = c[2].p - c[0].p;
  return facesOther(side, e1.x() * e2.y() - e1.y() * e2.x());
}

}  // namespace asperity::patch
