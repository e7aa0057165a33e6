// An Asperity scene rebuilt in MuJoCo (mjcf_scene.hpp).
#include "mjcf_scene.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>

#include "asperity/error.hpp"
#include "common/engine_setups.hpp"

namespace asperity::mjcf_scene {

namespace {

std::string numbers(std::initializer_list<double> values) {
  std::string out;
  char buffer[32];
  for (double v : values) {
    std::snprintf(buffer, sizeof buffer, "%s%.17g", out.empty() ? "" : " ", v);
    out += buffer;
  }
  return out;
}

std::string quatText(const Quat& q) {
  return numbers({q.w(), q.x(), q.y(), q.z()});
}

// The geom element of a shape at `pose` (its parent's frame), or an error naming the body.
std::string geomElement(const BodyDesc& body, const Shape& s, const Transform& pose) {
  std::string kind, size;
  Transform at = pose;
  switch (s.type) {
    case ShapeType::Box:
      kind = "box", size = numbers({s.half_extents.x(), s.half_extents.y(), s.half_extents.z()});
      break;
    case ShapeType::Sphere:
      kind = "sphere", size = numbers({s.radius});
      break;
    case ShapeType::Capsule:
    case ShapeType::Cylinder:
      kind = s.type == ShapeType::Capsule ? "capsule" : "cylinder";
      size = numbers({s.radius, s.half_height});
      break;
    case ShapeType::Plane:
      // MuJoCo's plane is z = 0 of its frame: turn z onto the normal, move to the plane.
      kind = "plane", size = "0 0 1";
      at = pose * Transform{s.plane_offset * s.plane_normal,
                            Quat::FromTwoVectors(Vec3::UnitZ(), s.plane_normal)};
      break;
    default:
      throw Error("body \"" + body.name +
                  "\": MuJoCo's side takes boxes, spheres, capsules, "
                  "cylinders and planes");
  }
  const Vec3& p = at.position;
  return "<geom name=\"" + body.name + "\" type=\"" + kind + "\" size=\"" + size + "\" pos=\"" +
         numbers({p.x(), p.y(), p.z()}) + "\" quat=\"" + quatText(at.rotation) + "\" density=\"" +
         numbers({s.density}) + "\"/>";
}

// The joints of a dynamic body: free, or three slides that keep it from turning.
std::string joints(const MjcfOptions& options) {
  if (!options.translation_only) return "<freejoint/>";
  return "<joint type=\"slide\" axis=\"1 0 0\"/><joint type=\"slide\" axis=\"0 1 0\"/>"
         "<joint type=\"slide\" axis=\"0 0 1\"/>";
}

// One body: a world geom when static, else a free body with its geom.
std::string bodyElement(const BodyDesc& b, const MjcfOptions& options) {
  if (b.shapes.size() != 1)
    throw Error("body \"" + b.name + "\": MuJoCo's side takes one shape per body");
  const Shape& s = b.shapes[0];
  if (b.type == BodyType::Static) return "    " + geomElement(b, s, b.pose * s.local) + "\n";
  if (b.type != BodyType::Dynamic)
    throw Error("body \"" + b.name + "\": MuJoCo's side takes static and dynamic bodies");
  const Vec3& p = b.pose.position;
  return "    <body name=\"" + b.name + "\" pos=\"" + numbers({p.x(), p.y(), p.z()}) +
         "\" quat=\"" + quatText(b.pose.rotation) + "\">" + joints(options) +
         geomElement(b, s, s.local) + "</body>\n";
}

// Keyframe "start": each free body's pose and velocity (angular in its own frame); slide
// joints start at 0 with the linear velocity.
std::string keyframe(const SceneDesc& scene, const MjcfOptions& options) {
  std::string qpos, qvel;
  for (const BodyDesc& b : scene.bodies) {
    if (b.type != BodyType::Dynamic) continue;
    const Vec3& p = b.pose.position;
    const Vec3& v = b.linear_velocity;
    const Vec3 w = b.pose.rotation.conjugate() * b.angular_velocity;
    const Quat& q = b.pose.rotation;
    const std::string pose = options.translation_only
                                 ? "0 0 0"
                                 : numbers({p.x(), p.y(), p.z(), q.w(), q.x(), q.y(), q.z()});
    const std::string velocity = options.translation_only
                                     ? numbers({v.x(), v.y(), v.z()})
                                     : numbers({v.x(), v.y(), v.z(), w.x(), w.y(), w.z()});
    qpos.append(qpos.empty() ? "" : " ").append(pose);
    qvel.append(qvel.empty() ? "" : " ").append(velocity);
  }
  return "  <keyframe><key name=\"start\" qpos=\"" + qpos + "\" qvel=\"" + qvel +
         "\"/></keyframe>\n";
}

}  // namespace

MjcfScene fromScene(const SceneDesc& scene, const MjcfOptions& options) {
  if (!scene.joints.empty() || !scene.springs.empty() || !scene.loads.empty())
    throw Error("MuJoCo's side takes no joints, springs or loads");
  const WorldSettings& w = scene.settings;
  const int bodies = static_cast<int>(scene.bodies.size());
  // Room for 16 contacts a body, four pyramid rows each.
  std::string xml =
      "<mujoco model=\"asperity\">\n  <option timestep=\"" + numbers({w.dt}) + "\" gravity=\"" +
      numbers({w.gravity.x(), w.gravity.y(), w.gravity.z()}) + "\" cone=\"" +
      (options.cone == Cone::Elliptic ? "elliptic" : "pyramidal") + "\"/>\n  <size nconmax=\"" +
      std::to_string(16 * bodies + 64) + "\" njmax=\"" + std::to_string(64 * bodies + 256) +
      "\"/>\n" + "  <default><geom condim=\"3\" friction=\"" +
      numbers({w.friction.mu0, 0.005, 0.0001}) + "\"/></default>\n" + "  <worldbody>\n";
  for (const BodyDesc& b : scene.bodies) xml += bodyElement(b, options);
  xml += "  </worldbody>\n" + keyframe(scene, options) + "</mujoco>\n";
  return {xml, engine_setups::surfacesFile(scene)};
}

ModelPtr loadModel(const std::string& xml) {
  // MuJoCo's virtual file system holds the text as a file (mjVFS is large: on the heap).
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  mj_makeEmptyFileVFS(vfs.get(), "model.xml", static_cast<int>(xml.size()));
  std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), "model.xml")], xml.data(), xml.size());
  char error[1000] = "";
  ModelPtr model(mj_loadXML("model.xml", vfs.get(), error, sizeof error));
  mj_deleteVFS(vfs.get());
  if (!model) throw Error(std::string("MuJoCo could not load the model: ") + error);
  return model;
}

RunResult run(const SceneDesc& scene, double seconds, bool with_asperity,
              const MjcfOptions& options) {
  const MjcfScene mjcf = fromScene(scene, options);
  ModelPtr model = loadModel(mjcf.xml);
  DataPtr data(mj_makeData(model.get()));
  mj_resetDataKeyframe(model.get(), data.get(), 0);
  std::unique_ptr<MujocoFriction> friction;
  if (with_asperity)
    friction = std::make_unique<MujocoFriction>(
        model.get(), parseEngineSurfaces(mjcf.surfaces, scene.source_file));
  // Steps of the model's timestep, with or without Asperity's edit.
  RunResult out;
  const auto steps = std::llround(seconds / model->opt.timestep);
  for (long long i = 0; i < steps; ++i) {
    if (friction)
      friction->step(data.get());
    else
      mj_step(model.get(), data.get());
    out.trajectory.insert(out.trajectory.end(), data->qpos, data->qpos + model->nq);
  }
  if (friction) out.stats = friction->lastStats();
  // Each body's frame at the end (kinematics of the last qpos).
  mj_kinematics(model.get(), data.get());
  for (int b = 1; b < model->nbody; ++b) {
    const mjtNum* p = data->xpos + 3 * b;
    out.positions[mj_id2name(model.get(), mjOBJ_BODY, b)] = Vec3(p[0], p[1], p[2]);
  }
  return out;
}

}  // namespace asperity::mjcf_scene
