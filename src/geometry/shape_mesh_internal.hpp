// Helpers shared by the analytic texture mapping and the shape mesh builders (shape_mesh.hpp).
// Frames here are in metres (uv not yet scaled by 1 / texture_size nor rotated).
#pragma once

#include <array>

#include "asperity/geometry/shape_mesh.hpp"

namespace asperity::detail {

// Sphere-like frame at longitude/latitude: uv = (r lon, v_offset + r lat), T east, B north.
SurfaceFrame sphereFrame(double radius, double lon, double lat, double v_offset);
// Planar projection frame of a face with unit normal n along its dominant axis (box face T).
SurfaceFrame dominantAxisFrame(const Vec3& n);
// Tangent frame of a triangle from its UV gradients (uv in repeats), orthogonalised against n.
SurfaceFrame gradientFrame(const std::array<Vec3, 3>& v, const std::array<Vec2, 3>& uv,
                           const Vec3& n);
// Gram-Schmidt of T against N, B = sign N x T with the sign of the given B.
SurfaceFrame orthogonalFrame(const Vec3& t, const Vec3& b, const Vec3& n);
// Barycentric coordinates of p (projected onto the triangle's plane).
Vec3 barycentric(const std::array<Vec3, 3>& v, const Vec3& p);
// Frame of a plane with this normal (uv origin at the shape origin).
SurfaceFrame planeFrame(const Vec3& normal);
// 1 / texture_size; throws asperity::Error when texture_size is not positive and finite.
double textureScale(const Shape& shape);

}  // namespace asperity::detail
