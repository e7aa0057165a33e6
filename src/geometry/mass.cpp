// Mass properties from shapes and densities (box, sphere, capsule, cylinder in closed form;
// convex hulls and closed triangle meshes by the divergence theorem; compounds by summation).
#include "geometry/mass.hpp"

#include <LinearMath/btConvexHullComputer.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "asperity/error.hpp"

namespace asperity {

namespace {

// Closed triangle soup, outward facing, in the shape frame.
struct Triangles {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;
};

// Eberly's subexpressions of the polyhedral integrals for one coordinate.
struct Sub {
  double f1, f2, f3, g0, g1, g2;
};
Sub subexpressions(double w0, double w1, double w2) {
  const double temp0 = w0 + w1;
  const double temp1 = w0 * w0;
  const double temp2 = temp1 + w1 * temp0;
  Sub s{};
  s.f1 = temp0 + w2;
  s.f2 = temp2 + w2 * s.f1;
  s.f3 = w0 * temp1 + w1 * temp2 + w2 * s.f2;
  s.g0 = s.f2 + w0 * (s.f1 + w0);
  s.g1 = s.f2 + w1 * (s.f1 + w1);
  s.g2 = s.f2 + w2 * (s.f1 + w2);
  return s;
}

// Volume integrals of 1, x, y, z, x^2, y^2, z^2, xy, yz, zx over a closed mesh via the
// divergence theorem (Eberly, "Polyhedral Mass Properties (Revisited)").
MassProperties meshProperties(const Triangles& mesh, double density, const std::string& what) {
  std::array<double, 10> in{};
  for (const auto& tri : mesh.triangles) {
    const Vec3& p0 = mesh.vertices[static_cast<size_t>(tri[0])];
    const Vec3& p1 = mesh.vertices[static_cast<size_t>(tri[1])];
    const Vec3& p2 = mesh.vertices[static_cast<size_t>(tri[2])];
    const Vec3 d = (p1 - p0).cross(p2 - p0);
    const Sub x = subexpressions(p0.x(), p1.x(), p2.x());
    const Sub y = subexpressions(p0.y(), p1.y(), p2.y());
    const Sub z = subexpressions(p0.z(), p1.z(), p2.z());
    in[0] += d.x() * x.f1;
    in[1] += d.x() * x.f2;
    in[2] += d.y() * y.f2;
    in[3] += d.z() * z.f2;
    in[4] += d.x() * x.f3;
    in[5] += d.y() * y.f3;
    in[6] += d.z() * z.f3;
    in[7] += d.x() * (p0.y() * x.g0 + p1.y() * x.g1 + p2.y() * x.g2);
    in[8] += d.y() * (p0.z() * y.g0 + p1.z() * y.g1 + p2.z() * y.g2);
    in[9] += d.z() * (p0.x() * z.g0 + p1.x() * z.g1 + p2.x() * z.g2);
  }
  const std::array<double, 10> scale{1.0 / 6,  1.0 / 24, 1.0 / 24,  1.0 / 24,  1.0 / 60,
                                     1.0 / 60, 1.0 / 60, 1.0 / 120, 1.0 / 120, 1.0 / 120};
  for (size_t i = 0; i < in.size(); ++i) in[i] *= scale[i];
  // An inward-facing mesh gives a negative volume: flip every integral.
  if (in[0] < 0.0) {
    for (double& v : in) v = -v;
  }
  if (!(in[0] > 1e-18)) throw Error(what + ": mesh encloses no volume (is it closed?)");
  const double volume = in[0];
  const Vec3 c(in[1] / volume, in[2] / volume, in[3] / volume);
  // Inertia about the centroid (unit density), then scaled by the density.
  Mat3 inertia;
  inertia(0, 0) = in[5] + in[6] - volume * (c.y() * c.y() + c.z() * c.z());
  inertia(1, 1) = in[4] + in[6] - volume * (c.z() * c.z() + c.x() * c.x());
  inertia(2, 2) = in[4] + in[5] - volume * (c.x() * c.x() + c.y() * c.y());
  inertia(0, 1) = inertia(1, 0) = -(in[7] - volume * c.x() * c.y());
  inertia(1, 2) = inertia(2, 1) = -(in[8] - volume * c.y() * c.z());
  inertia(0, 2) = inertia(2, 0) = -(in[9] - volume * c.z() * c.x());
  return {density * volume, c, density * inertia};
}

// Hull faces of a point cloud (Bullet's exact convex hull), mapped back to the input points
// so the integrals run in double precision.
Triangles convexHullTriangles(const TriangleMeshData& data, const std::string& what) {
  if (data.vertices.size() < 4) throw Error(what + ": convex hull needs at least 4 points");
  btConvexHullComputer hull;
  hull.compute(data.vertices.front().data(), static_cast<int>(sizeof(Vec3)),
               static_cast<int>(data.vertices.size()), 0.0, 0.0);
  // Each hull vertex is one of the inputs: find it (nearest point).
  std::vector<int> source(static_cast<size_t>(hull.vertices.size()));
  for (int i = 0; i < hull.vertices.size(); ++i) {
    const Vec3 p(hull.vertices[i].x(), hull.vertices[i].y(), hull.vertices[i].z());
    double best = 1e300;
    for (size_t j = 0; j < data.vertices.size(); ++j) {
      const double d2 = (data.vertices[j] - p).squaredNorm();
      if (d2 < best) best = d2, source[static_cast<size_t>(i)] = static_cast<int>(j);
    }
  }
  // Fan-triangulate every (planar, counter-clockwise) face.
  Triangles out{data.vertices, {}};
  for (int f = 0; f < hull.faces.size(); ++f) {
    const btConvexHullComputer::Edge* first = &hull.edges[hull.faces[f]];
    const int v0 = source[static_cast<size_t>(first->getSourceVertex())];
    const btConvexHullComputer::Edge* e = first->getNextEdgeOfFace();
    while (e->getTargetVertex() != first->getSourceVertex()) {
      out.triangles.push_back({v0, source[static_cast<size_t>(e->getSourceVertex())],
                               source[static_cast<size_t>(e->getTargetVertex())]});
      e = e->getNextEdgeOfFace();
    }
  }
  return out;
}

// Closed-form properties of a primitive about its own centre, in its shape frame.
MassProperties primitiveProperties(const Shape& s) {
  const double rho = s.density;
  MassProperties p;
  switch (s.type) {
    case ShapeType::Box: {
      const Vec3 h = s.half_extents;
      p.mass = rho * 8.0 * h.x() * h.y() * h.z();
      const Vec3 sq = h.cwiseProduct(h);
      p.inertia =
          (p.mass / 3.0 * Vec3(sq.y() + sq.z(), sq.z() + sq.x(), sq.x() + sq.y())).asDiagonal();
      break;
    }
    case ShapeType::Sphere: {
      const double r = s.radius;
      p.mass = rho * 4.0 / 3.0 * kPi * r * r * r;
      p.inertia = Mat3::Identity() * (0.4 * p.mass * r * r);
      break;
    }
    case ShapeType::Cylinder: {
      const double r = s.radius, h = s.half_height;
      p.mass = rho * kPi * r * r * 2.0 * h;
      const double side = p.mass * (3.0 * r * r + 4.0 * h * h) / 12.0;
      p.inertia = Vec3(side, side, 0.5 * p.mass * r * r).asDiagonal();
      break;
    }
    case ShapeType::Capsule: {
      // Cylinder plus two hemispheres (each 83/320 m r^2 about its own centre, which sits
      // 3r/8 beyond the cylinder's end).
      const double r = s.radius, h = s.half_height;
      const double mc = rho * kPi * r * r * 2.0 * h;
      const double ms = rho * 4.0 / 3.0 * kPi * r * r * r;
      const double arm = h + 3.0 * r / 8.0;
      const double side =
          mc * (3.0 * r * r + 4.0 * h * h) / 12.0 + ms * (83.0 / 320.0 * r * r + arm * arm);
      const double axial = 0.5 * mc * r * r + 0.4 * ms * r * r;
      p.mass = mc + ms;
      p.inertia = Vec3(side, side, axial).asDiagonal();
      break;
    }
    default:
      break;
  }
  return p;
}

}  // namespace

MassProperties shapeMassProperties(const Shape& shape) {
  const std::string what = "shape of type " + std::to_string(static_cast<int>(shape.type));
  if (!(shape.density >= 0.0)) throw Error(what + ": density must be >= 0");
  MassProperties local;
  switch (shape.type) {
    case ShapeType::Plane:
      return {};
    case ShapeType::ConvexHull:
    case ShapeType::TriangleMesh: {
      if (!shape.mesh) throw Error(what + ": mesh data missing");
      // A hull given with triangles uses them; a bare point cloud is hulled first.
      const bool has_triangles = !shape.mesh->triangles.empty();
      if (shape.type == ShapeType::TriangleMesh && !has_triangles) {
        throw Error(what + ": triangle mesh has no triangles");
      }
      const Triangles tris = has_triangles ? Triangles{shape.mesh->vertices, shape.mesh->triangles}
                                           : convexHullTriangles(*shape.mesh, what);
      local = meshProperties(tris, shape.density, what);
      break;
    }
    default:
      local = primitiveProperties(shape);
  }
  // Into the body frame: rotate the tensor, move the centre.
  const Mat3 r = shape.local.rotation.toRotationMatrix();
  return {local.mass, shape.local.apply(local.centre), r * local.inertia * r.transpose()};
}

MassProperties compoundMassProperties(std::span<const Shape> shapes) {
  std::vector<MassProperties> parts;
  MassProperties total;
  Vec3 moment = Vec3::Zero();
  // Total mass and centre of mass.
  for (const Shape& s : shapes) {
    parts.push_back(shapeMassProperties(s));
    total.mass += parts.back().mass;
    moment += parts.back().mass * parts.back().centre;
  }
  if (total.mass <= 0.0) return total;
  total.centre = moment / total.mass;
  // Parallel-axis theorem: I += m (|d|^2 1 - d d^T) for each part's offset d.
  for (const MassProperties& p : parts) {
    const Vec3 d = p.centre - total.centre;
    total.inertia += p.inertia + p.mass * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
  }
  return total;
}

PrincipalFrame principalFrame(std::span<const Shape> shapes) {
  PrincipalFrame out;
  out.properties = compoundMassProperties(shapes);
  out.com_frame.position = out.properties.centre;
  if (out.properties.mass <= 0.0) return out;
  // Already diagonal (boxes, cylinders, spheres at rest): keep the body's own axes.
  const Mat3& inertia = out.properties.inertia;
  const double off =
      std::max({std::abs(inertia(0, 1)), std::abs(inertia(1, 2)), std::abs(inertia(0, 2))});
  if (off <= 1e-12 * inertia.trace()) {
    out.principal_inertia = inertia.diagonal();
    return out;
  }
  // Symmetric tensor: real eigenvalues, orthonormal eigenvectors.
  Eigen::SelfAdjointEigenSolver<Mat3> solver(inertia);
  Mat3 axes = solver.eigenvectors();
  // Keep the frame right-handed.
  if (axes.determinant() < 0.0) axes.col(2) = -axes.col(2);
  out.com_frame.rotation = Quat(axes).normalized();
  out.principal_inertia = solver.eigenvalues();
  return out;
}

}  // namespace asperity
