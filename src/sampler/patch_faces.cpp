// The faces of a contact's shapes in the contact frame (patch_faces.hpp).
#include "sampler/patch_faces.hpp"

#include <cmath>

#include "asperity/error.hpp"
#include "geometry/shape_mesh_internal.hpp"

namespace asperity::patch {

Placement place(const Volume& volume, const Transform& pose) {
  const Mat3 at = volume.axes.transpose();
  return {at * pose.rotation.toRotationMatrix(), at * (pose.position - volume.origin)};
}

int facingBoxFaces(const Shape& box, const Placement& pl, Side side, std::array<BoxFace, 6>& out) {
  static const std::array<SurfaceFrame, 6> kFaces = {boxFaceFrame(0), boxFaceFrame(1),
                                                     boxFaceFrame(2), boxFaceFrame(3),
                                                     boxFaceFrame(4), boxFaceFrame(5)};
  const Vec3 h = box.half_extents;
  int count = 0;
  // A face faces the other body when its outward normal does.
  for (const SurfaceFrame& f : kFaces) {
    const Vec3 nc = pl.m * f.n;
    if (!facesOther(side, nc.z())) continue;
    out[static_cast<size_t>(count++)] = {f, f.n.cwiseProduct(h), f.t.cwiseProduct(h),
                                         f.b.cwiseProduct(h), nc};
  }
  return count;
}

namespace {

// Corner k of a box face in the box frame, counter-clockwise seen from outside.
constexpr double kCornerT[4] = {-1, 1, 1, -1}, kCornerB[4] = {-1, -1, 1, 1};
[[gnu::always_inline]] inline Vec3 localCorner(const BoxFace& face, size_t k) {
  return face.centre + kCornerT[k] * face.et + kCornerB[k] * face.eb;
}

}  // namespace

std::array<FaceCorner, 4> boxFaceCorners(const Shape& box, const Placement& pl, const BoxFace& face,
                                         double scale, const std::array<Vec3, 4>& positions) {
  const SurfaceFrame tex = rotateTexture(face.frame, box.surface.texture_rotation);
  // uv through the face's (rotated) texture axes; the frame is the face's, rotated.
  const Vec3 tc = pl.m * tex.t, bc = pl.m * tex.b;
  std::array<FaceCorner, 4> corners;
  for (size_t k = 0; k < 4; ++k) {
    const Vec3 p = localCorner(face, k);
    corners[k] = {positions[k], scale * p.dot(tex.t), scale * p.dot(tex.b), tc, bc, face.normal};
  }
  return corners;
}

std::array<Vec3, 4> boxFacePositions(const Placement& pl, const BoxFace& face) {
  std::array<Vec3, 4> corners;
  for (size_t k = 0; k < 4; ++k) corners[k] = pl.m * localCorner(face, k) + pl.o;
  return corners;
}

bool facingPlane(const Shape& plane, const Placement& pl, Side side, FacingPlane& out) {
  // The plane {n.x = offset} in the contact frame; skip it edge-on or facing away.
  const double len = plane.plane_normal.norm();
  if (!(len > 0.0)) throw Error("plane shape: plane_normal is zero");
  out.local_normal = plane.plane_normal / len;
  out.normal = pl.m * out.local_normal;
  if (!facesOther(side, out.normal.z()) || std::abs(out.normal.z()) < 1e-9) return false;
  out.point = pl.m * (plane.plane_offset / len * out.local_normal) + pl.o;
  // uv through the shape frame's texture axes.
  out.texture = rotateTexture(detail::planeFrame(out.local_normal), plane.surface.texture_rotation);
  out.scale = detail::textureScale(plane);
  out.t = pl.m * out.texture.t;
  out.b = pl.m * out.texture.b;
  return true;
}

Aabb volumeBoxInShape(const Volume& volume, const Placement& pl) {
  const Mat3 to_local = pl.m.transpose();
  Aabb box;
  for (int c = 0; c < 8; ++c) {
    const Vec3 corner(c & 1 ? 0.5 * volume.width : -0.5 * volume.width,
                      c & 2 ? 0.5 * volume.width : -0.5 * volume.width,
                      c & 4 ? volume.half_depth : -volume.half_depth);
    box.grow(Vec3f((to_local * (corner - pl.o)).cast<float>()));
  }
  return box;
}

std::array<FaceCorner, 3> meshTriangleCorners(const ShapeMesh& mesh, int triangle,
                                              const Placement& pl) {
  const auto& tri = mesh.triangles[static_cast<size_t>(triangle)];
  std::array<FaceCorner, 3> corners;
  for (size_t k = 0; k < 3; ++k) {
    const auto vi = static_cast<size_t>(tri[k]);
    corners[k] = {pl.m * mesh.positions[vi].cast<double>() + pl.o,
                  mesh.uvs[vi].x(),
                  mesh.uvs[vi].y(),
                  pl.m * mesh.tangents[vi].cast<double>(),
                  pl.m * mesh.bitangents[vi].cast<double>(),
                  pl.m * mesh.normals[vi].cast<double>()};
  }
  return corners;
}

}  // namespace asperity::patch
