// MuJoCo geoms as ContactFriction objects (mujoco_geoms.hpp).
#include "engines/mujoco/mujoco_geoms.hpp"

#include <algorithm>
#include <optional>

#include "asperity/error.hpp"

namespace asperity::mujoco_detail {

namespace {

// The Asperity shape of a geom in its own frame, when Asperity has one (MuJoCo's capsules and
// cylinders run along local z with size = (radius, half length), as Asperity's do).
std::optional<Shape> geomShape(const mjModel* m, int geom) {
  const mjtNum* size = m->geom_size + 3 * geom;
  Shape s;
  switch (m->geom_type[geom]) {
    case mjGEOM_PLANE:
      s.type = ShapeType::Plane;
      break;
    case mjGEOM_SPHERE:
      s.type = ShapeType::Sphere;
      s.radius = size[0];
      break;
    case mjGEOM_CAPSULE:
    case mjGEOM_CYLINDER:
      s.type = m->geom_type[geom] == mjGEOM_CAPSULE ? ShapeType::Capsule : ShapeType::Cylinder;
      s.radius = size[0];
      s.half_height = size[1];
      break;
    case mjGEOM_BOX:
      s.type = ShapeType::Box;
      s.half_extents = Vec3(size[0], size[1], size[2]);
      break;
    default:
      return std::nullopt;
  }
  return s;
}

// Every surface of the file must name a geom of the model.
void checkNames(const mjModel* m, const EngineSurfaces& surfaces) {
  for (const EngineSurface& e : surfaces.surfaces)
    if (mj_name2id(m, mjOBJ_GEOM, e.name.c_str()) < 0)
      surfaces.failAt(e.name, "the model has no geom named \"" + e.name + "\"");
}

// A textured geom needs friction rows (condim 3 or more) and a shape Asperity knows.
void checkTextured(const mjModel* m, int geom, bool has_shape) {
  const std::string what = "geom \"" + geomName(m, geom) + "\"";
  if (m->geom_condim[geom] == 1)
    throw Error(what + " has condim 1 and an Asperity surface: friction needs condim 3 or more");
  if (!has_shape)
    throw Error(what +
                " has an Asperity surface but is not a plane, sphere, capsule, cylinder "
                "or box");
}

// Explicit <pair> elements override the geoms' condim.
void checkPairs(const mjModel* m, const std::vector<uint8_t>& textured) {
  for (int p = 0; p < m->npair; ++p) {
    const int g1 = m->pair_geom1[p], g2 = m->pair_geom2[p];
    if (m->pair_dim[p] == 1 && (textured[g1] || textured[g2]))
      throw Error("contact pair of geoms \"" + geomName(m, g1) + "\" and \"" + geomName(m, g2) +
                  "\" has condim 1 and an Asperity surface: friction needs condim 3 or more");
  }
}

}  // namespace

std::string geomName(const mjModel* m, int geom) {
  const char* name = mj_id2name(m, mjOBJ_GEOM, geom);
  return name != nullptr && name[0] != '\0' ? name : "geom " + std::to_string(geom);
}

GeomObjects registerGeoms(const mjModel* m, const EngineSurfaces& surfaces,
                          ContactFriction& friction) {
  checkNames(m, surfaces);
  GeomObjects out;
  out.object.assign(static_cast<size_t>(m->ngeom), kNoObject);
  out.textured.assign(static_cast<size_t>(m->ngeom), 0);
  for (int g = 0; g < m->ngeom; ++g) {
    const std::string name = geomName(m, g);
    const Surface* surface = surfaces.find(name);
    std::optional<Shape> shape = geomShape(m, g);
    if (surface != nullptr) checkTextured(m, g, shape.has_value());
    if (!shape) continue;
    // Untextured geoms take part flat (gain 1, no normal map: they add nothing).
    if (surface != nullptr) shape->surface = *surface;
    out.textured[static_cast<size_t>(g)] = surface != nullptr;
    out.object[static_cast<size_t>(g)] = friction.addObject({name, {*shape}, Vec3::Zero()});
  }
  checkPairs(m, out.textured);
  return out;
}

double contactDepth(const mjModel* m, const mjContact& c) {
  const bool box_box = m->geom_type[c.geom1] == mjGEOM_BOX && m->geom_type[c.geom2] == mjGEOM_BOX;
  return std::max(0.0, -c.dist) * (box_box ? 2.0 : 1.0);
}

ObjectState geomState(const mjModel* m, const mjData* d, int geom) {
  ObjectState s;
  const mjtNum* p = d->geom_xpos + 3 * geom;
  const mjtNum* r = d->geom_xmat + 9 * geom;  // row major
  Mat3 rotation;
  rotation << r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8];
  s.pose = {Vec3(p[0], p[1], p[2]), Quat(rotation).normalized()};
  // MuJoCo's 6D velocity at the geom's centre, world axes: angular first, then linear.
  mjtNum v[6];
  mj_objectVelocity(m, d, mjOBJ_GEOM, geom, v, 0);
  s.angular_velocity = Vec3(v[0], v[1], v[2]);
  s.linear_velocity = Vec3(v[3], v[4], v[5]);
  return s;
}

}  // namespace asperity::mujoco_detail
