// Writing scenes back to JSON: the exact inverse of the reader (every number printed so that it
// reads back bit for bit, surfaces with their file or generator spec, meshes with their OBJ).
#include <charconv>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "asperity/error.hpp"
#include "asperity/math/atomic_file.hpp"
#include "asperity/scene/scene.hpp"
#include "scene/scene_common.hpp"

namespace asperity {

namespace scene {

namespace {

using nlohmann::json;

json toJson(const Vec3& v) {
  return json::array({v.x(), v.y(), v.z()});
}
json toJson(const Quat& q) {
  return json::array({q.w(), q.x(), q.y(), q.z()});
}

// Generator params: numbers as JSON numbers, paths (and anything unparsable) as strings.
json paramsToJson(const GeneratorSpec& spec) {
  const GeneratorInfo* info = nullptr;
  for (const GeneratorInfo& g : generatorCatalog())
    if (g.name == spec.name) info = &g;
  json out = json::object();
  for (const auto& [key, text] : spec.params) {
    bool is_number = info != nullptr;
    if (info != nullptr)
      for (const GeneratorParam& p : info->params)
        if (p.name == key && p.kind == "path") is_number = false;
    double value = 0.0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), value);
    if (is_number && r.ec == std::errc() && r.ptr == text.data() + text.size())
      out[key] = value;
    else
      out[key] = text;
  }
  return out;
}

json surfaceToJson(const Surface& s) {
  json out = json::object();
  if (!s.source.normal_map_file.empty()) {
    out["normal_map"] = s.source.normal_map_file;
  } else if (s.source.generator.name == "height_map") {
    // Written as read: the file and its scale (texture_size is the surface's own).
    const auto& params = s.source.generator.params;
    out["height_map"] = params.at("file");
    if (params.count("height_scale") && std::stod(params.at("height_scale")) > 0.0)
      out["height_scale"] = std::stod(params.at("height_scale"));
  } else if (!s.source.generator.name.empty()) {
    out["normal_map"] = {{"generator", s.source.generator.name},
                         {"params", paramsToJson(s.source.generator)},
                         {"size", s.source.generator.size},
                         {"seed", s.source.generator.seed}};
  }
  out["directx"] = s.source.green == GreenConvention::DirectX;
  out["gain"] = s.gain;
  out["texture_size"] = s.texture_size;
  out["texture_rotation_deg"] = degreesFromRadians(s.texture_rotation);
  if (!s.source.mask_file.empty()) out["mask"] = s.source.mask_file;
  out["base_color"] = toJson(s.base_color);
  return out;
}

// The OBJ source of bodies[body].shapes[shape], if it came from one.
const SceneMesh* meshSource(const SceneDesc& scene, size_t body, size_t shape) {
  for (const SceneMesh& m : scene.meshes)
    if (m.body == body && m.shape == shape) return &m;
  return nullptr;
}

// Hulls and meshes: the asset file they came from, else a hull's points.
void meshToJson(const SceneDesc& scene, size_t body, size_t index, json& out) {
  const Shape& shape = scene.bodies[body].shapes[index];
  const bool hull = shape.type == ShapeType::ConvexHull;
  if (const SceneMesh* m = meshSource(scene, body, index)) {
    out["file"] = m->file;
    out["scale"] = m->scale;
    out["simplify"] = m->simplify;
    if (!m->node.empty()) out["node"] = m->node;
  } else if (shape.mesh && !shape.mesh->source_file.empty()) {
    out["file"] = shape.mesh->source_file;
  } else if (hull && shape.mesh) {
    json points = json::array();
    for (const Vec3& p : shape.mesh->vertices) points.push_back(toJson(p));
    out["points"] = points;
  } else {
    throw Error("cannot save body \"" + scene.bodies[body].name + "\" shape " +
                std::to_string(index) + ": a mesh needs an OBJ file");
  }
}

// Mechanical values (a material's or an inline surface's): the preset's name while they equal it,
// else the numbers.
json mechanicalToJson(const Mechanical& m) {
  for (const Mechanical& p : mechanicalPresets()) {
    if (p.name == m.name && p.modulus == m.modulus && p.poisson == m.poisson &&
        p.hardness == m.hardness && p.shear == m.shear)
      return m.name;
  }
  return {{"E", m.modulus}, {"nu", m.poisson}, {"H", m.hardness}, {"tau", m.shear}};
}

json shapeToJson(const SceneDesc& scene, size_t body, size_t index) {
  const Shape& s = scene.bodies[body].shapes[index];
  json out = {{"type", enumName(s.type, kShapeTypeNames)},
              {"position", toJson(s.local.position)},
              {"orientation", toJson(s.local.rotation)},
              {"density", s.density}};
  // Only the fields of this shape type.
  switch (s.type) {
    case ShapeType::Box:
      out["half_extents"] = toJson(s.half_extents);
      break;
    case ShapeType::Sphere:
      out["radius"] = s.radius;
      break;
    case ShapeType::Capsule:
    case ShapeType::Cylinder:
      out["radius"] = s.radius;
      out["half_height"] = s.half_height;
      break;
    case ShapeType::Plane:
      out["normal"] = toJson(s.plane_normal);
      out["offset"] = s.plane_offset;
      break;
    case ShapeType::ConvexHull:
    case ShapeType::TriangleMesh:
      meshToJson(scene, body, index, out);
      break;
  }
  out["surface"] = surfaceToJson(s.surface);
  // A surface that still equals the material it was read from is written as its name.
  const auto material = scene.materials.find(s.surface.source.material);
  if (material != scene.materials.end() &&
      surfaceToJson(material->second.surface) == out["surface"]) {
    out["surface"] = material->first;
    return out;
  }
  // A surface that showed its asset's base colour keeps doing so.
  const SceneMesh* m = meshSource(scene, body, index);
  if (m && m->asset_base_color) out["surface"].erase("base_color");
  // An inline surface's own mechanical values.
  const auto mechanical = scene.surface_mechanical.find({body, index});
  if (mechanical != scene.surface_mechanical.end())
    out["surface"]["mechanical"] = mechanicalToJson(mechanical->second);
  return out;
}

json settingsToJson(const SceneDesc& scene) {
  const WorldSettings& s = scene.settings;
  const FrictionSettings& f = s.friction;
  return {{"dt", s.dt},
          {"iterations", s.iterations},
          {"substeps", s.substeps},
          {"threads", s.threads},
          {"gravity", toJson(s.gravity)},
          {"limit_surface", enumName(s.limit_surface, kLimitSurfaceNames)},
          {"frame_mode", enumName(s.frame.mode, kFrameModeNames)},
          {"world_axis", toJson(s.frame.world_axis)},
          {"fallback_axis", toJson(s.frame.fallback_axis)},
          {"sliding_speed", s.frame.sliding_speed},
          {"auto_frame_iterations", s.auto_frame_iterations},
          {"warm_starting", s.warm_starting},
          {"baumgarte", s.baumgarte},
          {"linear_slop", s.linear_slop},
          {"contact_margin", s.contact_margin},
          {"max_correction_speed", s.max_correction_speed},
          {"max_speed", s.max_speed},
          {"max_pairs", s.max_pairs},
          {"directions", f.directions},
          {"mu0", f.mu0},
          {"mu_max", static_cast<double>(f.mu_max)},
          {"patch_width", f.patch_width},
          {"patch_resolution", f.patch_resolution},
          {"reuse_pixels", f.reuse_pixels},
          {"texel_reading", enumName(f.texel_reading, EnumNames<TexelReading>(kTexelReadingNames))},
          {"friction_provider", scene.friction_provider},
          {"friction_model",
           enumName(scene.friction_model, EnumNames<FrictionModel>(kFrictionModelNames))}};
}

// "materials": each entry as a surface, its base colour only when it gave one.
json materialsToJson(const SceneDesc& scene) {
  json out = json::object();
  for (const auto& [name, material] : scene.materials) {
    out[name] = surfaceToJson(material.surface);
    if (!material.names_base_color) out[name].erase("base_color");
    if (material.mechanical) out[name]["mechanical"] = mechanicalToJson(*material.mechanical);
  }
  return out;
}

json jointToJson(const SceneJoint& j) {
  const JointDesc& d = j.desc;
  json out = {{"name", d.name},
              {"type", enumName(d.type, kJointTypeNames)},
              {"body_a", j.body_a},
              {"body_b", j.body_b},
              {"anchor_a", toJson(d.anchor_a)},
              {"anchor_b", toJson(d.anchor_b)},
              {"axis_a", toJson(d.axis_a)},
              {"axis_b", toJson(d.axis_b)},
              {"amplitude", d.amplitude},
              {"frequency", d.frequency},
              {"phase", d.phase},
              {"collide_connected", d.collide_connected}};
  // A negative rest length means "the anchors' distance at creation": left out.
  if (d.rest_length >= 0.0) out["rest_length"] = d.rest_length;
  return out;
}

json springToJson(const SceneSpring& s) {
  const SpringDesc& d = s.desc;
  return {{"name", d.name},
          {"body", s.body},
          {"local_point", toJson(d.local_point)},
          {"target", toJson(d.target)},
          {"target_velocity", toJson(d.target_velocity)},
          {"stiffness", d.stiffness},
          {"damping", d.damping}};
}

json loadToJson(const SceneLoad& l) {
  const LoadDesc& d = l.desc;
  return {{"name", d.name},
          {"body", l.body},
          {"kind", enumName(d.kind, kLoadKindNames)},
          {"value", toJson(d.value)},
          {"local_point", toJson(d.local_point)},
          {"start", d.start},
          {"end", d.end}};
}

// A relative path written from `from` rewritten to be relative to `to` (absolute ones stay).
void rebase(std::string& file, const std::filesystem::path& from, const std::filesystem::path& to) {
  if (file.empty() || std::filesystem::path(file).is_absolute()) return;
  file = (from / file).lexically_normal().lexically_proximate(to).string();
}

// A surface's files: its normal map, its mask and generator parameters that name files.
void rebaseSurface(SurfaceSource& s, const std::filesystem::path& from,
                   const std::filesystem::path& to) {
  rebase(s.normal_map_file, from, to);
  rebase(s.mask_file, from, to);
  for (const GeneratorInfo& g : generatorCatalog())
    for (const GeneratorParam& p : g.params)
      if (g.name == s.generator.name && p.kind == "path" && s.generator.params.count(p.name))
        rebase(s.generator.params[p.name], from, to);
}

// Every file name of the scene, made relative to `folder` instead of scene.base_dir.
void rebaseScene(SceneDesc& scene, const std::string& folder) {
  namespace fs = std::filesystem;
  const fs::path from =
      fs::absolute(scene.base_dir.empty() ? "." : scene.base_dir).lexically_normal();
  const fs::path to = fs::absolute(folder.empty() ? "." : folder).lexically_normal();
  scene.base_dir = folder;
  if (from == to) return;
  for (auto& entry : scene.materials) rebaseSurface(entry.second.surface.source, from, to);
  for (BodyDesc& body : scene.bodies)
    for (Shape& shape : body.shapes) rebaseSurface(shape.surface.source, from, to);
  for (SceneMesh& m : scene.meshes) rebase(m.file, from, to);
}

}  // namespace

json bodyToJson(const SceneDesc& scene, size_t index) {
  const BodyDesc& b = scene.bodies[index];
  json out = {{"name", b.name},
              {"type", enumName(b.type, kBodyTypeNames)},
              {"position", toJson(b.pose.position)},
              {"orientation", toJson(b.pose.rotation)},
              {"linear_velocity", toJson(b.linear_velocity)},
              {"angular_velocity", toJson(b.angular_velocity)}};
  if (b.mass_override > 0.0) out["mass"] = b.mass_override;
  if (b.frame_axis != Vec3::Zero()) out["frame_axis"] = toJson(b.frame_axis);
  json shapes = json::array();
  for (size_t i = 0; i < b.shapes.size(); ++i) shapes.push_back(shapeToJson(scene, index, i));
  out["shapes"] = shapes;
  return out;
}

}  // namespace scene

nlohmann::json sceneToJson(const SceneDesc& scene) {
  using namespace scene;
  json bodies = json::array();
  for (size_t i = 0; i < scene.bodies.size(); ++i) bodies.push_back(bodyToJson(scene, i));
  json joints = json::array();
  for (const SceneJoint& j : scene.joints) joints.push_back(jointToJson(j));
  json springs = json::array();
  for (const SceneSpring& s : scene.springs) springs.push_back(springToJson(s));
  json loads = json::array();
  for (const SceneLoad& l : scene.loads) loads.push_back(loadToJson(l));
  json out = {{"settings", settingsToJson(scene)},
              {"bodies", bodies},
              {"joints", joints},
              {"springs", springs},
              {"loads", loads}};
  // The materials table only when the scene has one.
  if (!scene.materials.empty()) out["materials"] = materialsToJson(scene);
  // The pairs only when the scene has some.
  if (!scene.pairs.empty()) {
    json pairs = json::array();
    for (const ScenePair& p : scene.pairs)
      pairs.push_back({{"materials", {p.materials[0], p.materials[1]}},
                       {"friction_model", enumName(p.friction_model, EnumNames<FrictionModel>(
                                                                         kFrictionModelNames))}});
    out["pairs"] = pairs;
  }
  // The camera only when the scene chose one.
  if (scene.camera)
    out["camera"] = {{"eye", toJson(scene.camera->eye)},
                     {"target", toJson(scene.camera->target)},
                     {"fov_deg", degreesFromRadians(scene.camera->fov_y)}};
  return out;
}

void saveScene(const SceneDesc& scene, const std::string& path) {
  SceneDesc copy = scene;
  scene::rebaseScene(copy, scene::parentFolder(path));
  writeFileAtomically(path, sceneToJson(copy).dump(2) + "\n");
}

uint64_t sceneStateId(const SceneDesc& scene) {
  // Neither the thread count nor the provider changes which scene this is: the provider is
  // checked on its own (World::loadState names it), threads change no result (SPEC 9).
  SceneDesc copy = scene;
  copy.settings.threads = 0;
  copy.friction_provider.clear();
  const std::string text = sceneToJson(copy).dump();
  uint64_t hash = 1469598103934665603ull;
  for (const unsigned char c : text) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  return hash ^ scene.bodies.size();
}

}  // namespace asperity
