// Mass properties of shapes from their density: volume, centre of mass and inertia tensor
// (box, sphere, capsule, cylinder in closed form; convex hulls and closed triangle meshes by
// the divergence theorem; compounds by the parallel-axis theorem).
#pragma once

#include <span>

#include "asperity/geometry/shape.hpp"
#include "asperity/math/types.hpp"

namespace asperity {

struct MassProperties {
  double mass = 0.0;            // kg
  Vec3 centre = Vec3::Zero();   // centre of mass in the frame the shapes are given in (m)
  Mat3 inertia = Mat3::Zero();  // about `centre`, axes of that frame (kg m^2)
};

// Mass properties of one shape (in the body frame, i.e. including shape.local). Planes have
// none. Throws asperity::Error for a mesh without triangles or with a non-positive volume.
MassProperties shapeMassProperties(const Shape& shape);

// Sum over shapes (parallel-axis theorem about the common centre of mass).
MassProperties compoundMassProperties(std::span<const Shape> shapes);

// A body frame at the centre of mass with principal axes.
struct PrincipalFrame {
  MassProperties properties;              // centre and inertia in the ORIGINAL body frame
  Transform com_frame;                    // principal frame relative to the original body frame
  Vec3 principal_inertia = Vec3::Zero();  // diagonal of the inertia in com_frame (kg m^2)
};

// Diagonalises the compound inertia (Eigen SelfAdjointEigenSolver; right-handed axes).
PrincipalFrame principalFrame(std::span<const Shape> shapes);

}  // namespace asperity
